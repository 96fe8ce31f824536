#include "springblock/integrate/linear/run_basis.hpp"

#include "springblock/integrate/linear/run_stiffness.hpp"

namespace sb::event_detail {

const RunBasis& RunBases::get(int n, bool left, bool right) {
  const auto key = std::make_tuple(n, left, right);
  auto it = bases_.find(key);
  if (it != bases_.end()) return it->second;
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(run_stiffness(K_s_, K_int_, n, left, right));
  RunBasis b;
  b.Q = es.eigenvectors();
  b.lambda = es.eigenvalues();
  for (int k = 0; k < n; ++k) b.modes.push_back({0.5 * gamma_, b.lambda[k] / m_});
  for (int k = 0; k < n; ++k) b.first_row.push_back(b.Q(0, k)), b.last_row.push_back(b.Q(n - 1, k));
  if (sample_dt_ > 0)
    for (const DampedMode& m : b.modes) b.sample.push_back(m.transition(sample_dt_));
  return bases_.emplace(key, std::move(b)).first->second;
}

void RunBases::set_sample_dt(double dt) {
  sample_dt_ = dt;
  for (auto& [key, b] : bases_) {
    b.sample.clear();
    for (const DampedMode& m : b.modes) b.sample.push_back(m.transition(dt));
  }
}

}  // namespace sb::event_detail
