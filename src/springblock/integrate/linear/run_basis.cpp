#include "springblock/integrate/linear/run_basis.hpp"

#include <cmath>
#include <limits>

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
  if (sample_dt_ > 0) set_sample_transitions(b, sample_dt_);
  return bases_.emplace(key, std::move(b)).first->second;
}

void RunBases::set_sample_transitions(RunBasis& b, double dt) {
  b.sample.clear();
  b.sample_sum.clear();
  for (const DampedMode& m : b.modes) {
    const Transition P = m.transition(dt);
    b.sample.push_back(P);
    const double det = (1.0 - P[0]) * (1.0 - P[3]) - P[1] * P[2];
    const double nan = std::numeric_limits<double>::quiet_NaN();
    b.sample_sum.push_back(std::fabs(det) < 1e-6 ? std::array<double, 2>{nan, nan}
                                                 : std::array<double, 2>{(1.0 - P[3]) / det, P[1] / det});
  }
}

void RunBases::set_sample_dt(double dt) {
  sample_dt_ = dt;
  for (auto& [key, b] : bases_) set_sample_transitions(b, dt);
}

}  // namespace sb::event_detail
