#include "springblock/integrate/linear/general_modes.hpp"

#include <cmath>
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

}  // namespace sb::event_detail
