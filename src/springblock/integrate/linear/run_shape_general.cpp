// The shapes of a chain whose blocks differ (RunShapes::general, run_shape.hpp) and their modes (general_modes.hpp).
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include <Eigen/Eigenvalues>

#include "springblock/integrate/linear/general_modes.hpp"
#include "springblock/integrate/linear/run_shape.hpp"

namespace sb::event_detail {

const RunShape& RunShapes::general(BlockRange r, std::uint8_t parts) {
  RunShape*& sh = ranged_[{r.lo, r.hi}];
  if (sh == nullptr) {
    RunShape*& shape = by_content_[general_key(r)];
    if (shape == nullptr) shape = &shapes_.emplace_back(make(r, r.lo > 0, r.hi < c_.N));
    sh = shape;
  }
  if ((sh->steps.parts & parts) != parts) add_parts(*sh, parts);
  return *sh;
}

// Every value make reads, so that runs with equal keys have equal shapes to the last bit
// (the chain's v, gamma and m are common to all): each block's slider spring and mass, the springs
// inside the run, and the holding spring at each end (-1 at a free chain end, never a spring).
std::vector<double> RunShapes::general_key(BlockRange r) const {
  const Chain& c = c_;
  std::vector<double> key;
  key.reserve(3 * static_cast<std::size_t>(r.size()) + 1);
  for (int i = r.lo; i < r.hi; ++i) key.push_back(c.k_s(i)), key.push_back(c.mass(i));
  for (int i = r.lo; i + 1 < r.hi; ++i) key.push_back(c.spring(i));
  key.push_back(r.lo > 0 ? c.spring(r.lo - 1) : -1.0);
  key.push_back(r.hi < c.N ? c.spring(r.hi - 1) : -1.0);
  return key;
}

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
