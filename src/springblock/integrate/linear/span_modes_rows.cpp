// The rows of the exact stepper's runs (span_modes.hpp): a block's u, v and acceleration from
// the modes, the bounds on its derivatives, its Taylor polynomial over a step, and the rows
// written into the chain's state.
#include <algorithm>
#include <cmath>

#include "springblock/integrate/linear/envelope.hpp"
#include "springblock/integrate/linear/span_modes.hpp"
#include "springblock/kernel_clones.hpp"

namespace sb::event_detail {
namespace {

// su = Q q and sv = Q p for the n x n column-major Q, accumulated mode by mode.
SB_KERNEL_CLONES void columns_times(int n, const double* __restrict Q, const double* __restrict q,
                                    const double* __restrict p, double* __restrict su, double* __restrict sv) {
  for (int r = 0; r < n; ++r) su[r] = 0.0, sv[r] = 0.0;
  for (int k = 0; k < n; ++k) {
    const double* col = Q + static_cast<std::size_t>(k) * n;
    const double qk = q[k], pk = p[k];
    for (int r = 0; r < n; ++r) {
      su[r] += col[r] * qk;
      sv[r] += col[r] * pk;
    }
  }
}

}  // namespace

double SpanModes::a(int i, bool end) const {
  const Span& sp = spans_[span_of_[i]];
  const int n = sp.hi - sp.lo;
  const double* row = sp.shape->Qr.data() + static_cast<std::size_t>(i - sp.lo) * n;
  const double* w2 = sp.shape->w2.data();
  const double* q = (end ? qn_.data() : q_.data()) + sp.lo;
  const double* p = (end ? pn_.data() : p_.data()) + sp.lo;
  double d = 0;
  for (int k = 0; k < n; ++k) d += row[k] * (-gamma_ * p[k] - w2[k] * q[k]);
  return d;
}

double SpanModes::row_bound(int i, int order) const { return bound_[order - 2][i]; }

// The derivative bounds of row `row` of span sp (orders 2 to 5) from the energies at projection.
void SpanModes::set_bounds(const Span& sp, int row) {
  const int n = sp.hi - sp.lo, i = sp.lo + row;
  const double* q = sp.shape->Qr.data() + static_cast<std::size_t>(row) * n;
  double b[4] = {0, 0, 0, 0};
  for (int k = 0; k < n; ++k) {
    const double w = std::fabs(q[k]) * sE_[sp.lo + k];
    for (int j = 0; j < 4; ++j) b[j] += w * sp.shape->c[j][k];
  }
  for (int j = 0; j < 4; ++j) bound_[j][i] = b[j];
}

void SpanModes::row_taylor(int i, double* c) const {
  constexpr int D = kDegree + 1;
  const Span& sp = spans_[span_of_[i]];
  const int n = sp.hi - sp.lo;
  const double* row = sp.shape->Qr.data() + static_cast<std::size_t>(i - sp.lo) * n;
  c[0] = A_[i] + B_[i] * t_ + du_[i];
  c[1] = B_[i] + dv_[i];
  for (int j = 2; j <= D; ++j) c[j] = 0.0;
  for (int k = 0; k < n; ++k) add_taylor(row[k], q_[sp.lo + k], p_[sp.lo + k], gamma_, sp.shape->w2[k], D, c);
  taylor_scale(D, c);
}

void SpanModes::write(double* u, double* v, bool ends_only) const {
  for (const Span& sp : spans_) {
    const int n = sp.hi - sp.lo;
    if (!ends_only || n <= 2) {
      write_rows(sp, u, v);
      continue;
    }
    for (int i : {sp.lo, sp.hi - 1}) {
      u[i] = A_[i] + B_[i] * t_ + row_dot(i, q_.data()) + du_[i];
      v[i] = B_[i] + row_dot(i, p_.data()) + dv_[i];
    }
  }
}

// Every row of a run: Q q and Q p a column at a time (Q is stored by column), so the loop over
// rows vectorises while each row still sums its modes in row_dot's order: the same doubles.
void SpanModes::write_rows(const Span& sp, double* u, double* v) const {
  const int n = sp.hi - sp.lo;
  double* su = scratch_u_.data();
  double* sv = scratch_v_.data();
  columns_times(n, sp.shape->basis->Q.data(), q_.data() + sp.lo, p_.data() + sp.lo, su, sv);
  for (int r = 0; r < n; ++r) {
    const int i = sp.lo + r;
    u[i] = A_[i] + B_[i] * t_ + su[r] + du_[i];
    v[i] = B_[i] + sv[r] + dv_[i];
  }
}

void SpanModes::write_near(const std::vector<int>& blocks, double* u, double* v) const {
  for (const Span& sp : spans_) {
    bool near = sp.grooves;
    for (std::size_t k = 0; k < blocks.size() && !near; ++k) near = blocks[k] >= sp.lo - 1 && blocks[k] <= sp.hi;
    if (near) write_rows(sp, u, v);
  }
}

void SpanModes::write_untouched(const std::uint8_t* switched, double* u, double* v) const {
  for (const Span& sp : spans_) {
    bool touched = false;
    for (int i = std::max(sp.lo - 1, 0); i < std::min(sp.hi + 1, N_) && !touched; ++i) touched = switched[i] != 0;
    if (!touched) write_rows(sp, u, v);
  }
}

double SpanModes::settled_after(int k, double eps_u, double eps_v) const {
  const Span& sp = spans_[k];
  return sp.t0 + transient_envelope(*sp.shape->basis, q0_.data() + sp.lo, p0_.data() + sp.lo).time_below(eps_u, eps_v);
}

}  // namespace sb::event_detail
