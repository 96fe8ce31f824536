#include "springblock/integrate/linear/general_modes.hpp"

#include <cmath>
#include <map>
#include <stdexcept>

#include <Eigen/Eigenvalues>

namespace sb::event_detail {

void general_modes(const Factors& K, const std::vector<double>& w, Eigen::MatrixXd& Q, std::vector<double>& lambda) {
  const int n = static_cast<int>(K.diag.size());
  if (static_cast<int>(w.size()) != n) throw std::logic_error("general_modes: one weight per row");
  Eigen::VectorXd inv_sqrt_w(n), diag(n), sub(std::max(n - 1, 0));
  for (int r = 0; r < n; ++r) inv_sqrt_w[r] = 1.0 / std::sqrt(w[r]);
  for (int r = 0; r < n; ++r) diag[r] = K.diag[r] * inv_sqrt_w[r] * inv_sqrt_w[r];
  for (int r = 0; r + 1 < n; ++r) sub[r] = K.off[r] * inv_sqrt_w[r] * inv_sqrt_w[r + 1];
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es;
  es.computeFromTridiagonal(diag, sub, Eigen::ComputeEigenvectors);
  if (es.info() != Eigen::Success) throw std::runtime_error("general_modes: the eigensolver did not converge");
  Q = inv_sqrt_w.asDiagonal() * es.eigenvectors();
  lambda.assign(es.eigenvalues().data(), es.eigenvalues().data() + n);
}

// Every repetition of a scene has the same springs and masses, so it asks for the same runs'
// modes; so do runs of equal blocks at different places. Kept per thread and keyed by the exact
// doubles of K and w: a hit gives what the solver would, so results do not depend on the thread
// count or on what was cached. The cache is emptied when it holds more than kMaxDoubles.
void cached_general_modes(const Factors& K, const std::vector<double>& w, Eigen::MatrixXd& Q,
                          std::vector<double>& lambda) {
  constexpr std::size_t kMaxDoubles = std::size_t{1} << 23;  // 64 MB
  struct Modes {
    Eigen::MatrixXd Q;
    std::vector<double> lambda;
  };
  thread_local std::map<std::vector<double>, Modes> cache;
  thread_local std::size_t held = 0;
  std::vector<double> key(K.diag);
  key.insert(key.end(), K.off.begin(), K.off.end());
  key.insert(key.end(), w.begin(), w.end());
  auto it = cache.find(key);
  if (it == cache.end()) {
    const std::size_t n = K.diag.size();
    if (held + n * n > kMaxDoubles) cache.clear(), held = 0;
    Modes m;
    general_modes(K, w, m.Q, m.lambda);
    held += n * n + key.size();
    it = cache.emplace(std::move(key), std::move(m)).first;
  }
  Q = it->second.Q;
  lambda = it->second.lambda;
}

}  // namespace sb::event_detail
