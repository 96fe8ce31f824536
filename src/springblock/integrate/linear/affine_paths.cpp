#include "springblock/integrate/linear/affine_paths.hpp"

#include <gsl/gsl_linalg.h>

#include <cmath>

#include "springblock/integrate/linear/run_stiffness.hpp"

namespace sb::event_detail {
namespace {

// Solve the symmetric tridiagonal system (diag, off) x = rhs with GSL (n = 1 by hand: GSL
// rejects an empty off-diagonal).
void solve_tridiag(std::vector<double>& diag, std::vector<double>& off, std::vector<double>& rhs, double* x,
                   int n) {
  if (n == 1) {
    x[0] = rhs[0] / diag[0];
    return;
  }
  gsl_vector_view d = gsl_vector_view_array(diag.data(), n);
  gsl_vector_view e = gsl_vector_view_array(off.data(), n - 1);
  gsl_vector_view b = gsl_vector_view_array(rhs.data(), n);
  gsl_vector_view out = gsl_vector_view_array(x, n);
  gsl_linalg_solve_symm_tridiag(&d.vector, &e.vector, &b.vector, &out.vector);
}

}  // namespace

AffinePaths::AffinePaths(const Chain& c) : N_(c.N), shapes_(c), A_(c.N, 0.0), B_(c.N, 0.0) {}

const AffineShapes::Shape& AffineShapes::get(int n, bool left, bool right) {
  const auto key = std::make_tuple(n, left, right);
  auto it = shapes_.find(key);
  if (it != shapes_.end()) return it->second;
  diag_.resize(n), off_.resize(n), rhs_.resize(n);
  Shape sh{std::vector<double>(n), std::vector<double>(n), std::vector<double>(n), std::vector<double>(n)};
  auto solve = [&](auto&& rhs, std::vector<double>& x) {
    for (int k = 0; k < n; ++k) {
      diag_[k] = run_stiffness_diagonal(K_s_, K_int_, n, k, left, right);
      off_[k] = -K_int_;
      rhs_[k] = rhs(k);
    }
    solve_tridiag(diag_, off_, rhs_, x.data(), n);
  };
  solve([&](int) { return K_s_ * v_; }, sh.B);
  solve([&](int k) { return -m_gamma_ * sh.B[k]; }, sh.a0);
  solve([&](int k) { return k == 0 && left ? K_int_ : 0.0; }, sh.gL);
  solve([&](int k) { return k == n - 1 && right ? K_int_ : 0.0; }, sh.gR);
  return shapes_.emplace(key, std::move(sh)).first->second;
}

void AffinePaths::compute(const State& s, BlockRange r) {
  const int n = r.hi - r.lo;
  const bool left = r.lo > 0, right = r.hi < N_;  // held by a stuck block there (else a free end)
  const AffineShapes::Shape& sh = shapes_.get(n, left, right);
  const double uL = left ? s.u[r.lo - 1] : 0.0, uR = right ? s.u[r.hi] : 0.0;
  for (int k = 0; k < n; ++k) {
    B_[r.lo + k] = sh.B[k];
    A_[r.lo + k] = sh.a0[k] + uL * sh.gL[k] + uR * sh.gR[k];
  }
}

bool AffinePaths::within(const State& s, BlockRange r, double eps_u, double eps_v) const {
  for (int i = r.lo; i < r.hi; ++i) {
    if (std::fabs(s.u[i] - u(i, s.t)) > eps_u) return false;
    if (std::fabs(s.v[i] - B_[i]) > eps_v) return false;
  }
  return true;
}

void AffinePaths::write(BlockRange r, double t, double* u, double* v) const {
  for (int i = r.lo; i < r.hi; ++i) {
    u[i] = A_[i] + B_[i] * t;
    v[i] = B_[i];
  }
}

}  // namespace sb::event_detail
