#include "springblock/integrate/linear/run_store.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "springblock/kernel_clones.hpp"

namespace sb::event_detail {
namespace {

// a = sum_i x[i] M_i and b = sum_i y[i] M_i over the n contiguous length-n vectors M_i of M, accumulated vector by
// vector: the inner loop vectorises, and each entry still sums its terms in order of i. Over Q's rows (Qr) that is the
// projection Q^T x; over its columns (Q) it is Q q, each row summed in row_dot's order (the same doubles).
SB_KERNEL_CLONES void combine(int n, const double* __restrict M, const double* __restrict x, const double* __restrict y,
                              double* __restrict a, double* __restrict b) {
  for (int j = 0; j < n; ++j) a[j] = 0.0, b[j] = 0.0;
  for (int i = 0; i < n; ++i) {
    const double* m = M + static_cast<std::size_t>(i) * n;
    const double xi = x[i], yi = y[i];
    for (int j = 0; j < n; ++j) {
      a[j] += m[j] * xi;
      b[j] += m[j] * yi;
    }
  }
}

// Runs this short are written row by row (row_dot): the same doubles as combine, without
// its set-up, which costs more than the products on a run of a few blocks.
constexpr int kRowWise = 8;

// What each owner moves its runs by: the exact stepper by its grid step, a modal run by
// EdgeMarch's and by the sample spacing, a quiet phase's segment by the sample spacing.
std::uint8_t parts_for(RunStore::Owner owner) {
  switch (owner) {
    case RunStore::kSpan: return RunShape::kStep;
    case RunStore::kModal: return RunShape::kMarch | RunShape::kSample;
    case RunStore::kQuiet: return RunShape::kSample;
    default: return 0;
  }
}

}  // namespace

RunStore::RunStore(const Chain& c)
    : gamma_(c.gamma),
      shapes_(c),
      records_(c.N),
      A_(c.N),
      B_(c.N),
      modes_(c.N),
      dev_(c.N),
      sums_(c.N) {
  for (auto& b : bound_) b.assign(c.N, std::numeric_limits<double>::infinity());
}

RunStore::Run& RunStore::Records::claim(BlockRange r, const RunShape* shape, double t0, bool modes, Owner owner) {
  for (int i = r.lo; i < r.hi; ++i)
    if (first_[i] >= 0) drop(first_[i]);
  std::fill(first_.begin() + r.lo, first_.begin() + r.hi, r.lo);
  return runs_[r.lo] = Run{r.lo, r.hi, shape, t0, modes, owner, ++serial_};
}

// A = a0 + u_left gL + u_right gR - K^-1 f_kin and B from the shape's pieces (run_shape.hpp).
void RunStore::set_path(const Chain& c, Run& run, const double* u, const std::int8_t* dir) {
  const RunShape& sh = *run.shape;
  const int lo = run.lo, n = run.n();
  const double uL = sh.path.left ? u[lo - 1] : 0.0, uR = sh.path.right ? u[run.hi] : 0.0;
  for (int k = 0; k < n; ++k) {
    A_[lo + k] = sh.path.A(k, uL, uR);
    B_[lo + k] = sh.path.B[k];
  }
  if (dir == nullptr || std::all_of(dir + lo, dir + run.hi, [](std::int8_t d) { return d == 0; })) return;
  double* f = dev_.q.data();
  for (int k = 0; k < n; ++k) f[k] = dir[lo + k] * c.f_kinetic[lo + k];
  sh.K.solve(f, f);
  for (int k = 0; k < n; ++k) A_[lo + k] -= f[k];
}

const RunStore::Run& RunStore::project(const Chain& c, BlockRange r, double t, const double* u, const double* v,
                                       const std::int8_t* dir, Owner owner, bool with_modes) {
  Run& run = records_.claim(r, &shapes_.of(r, parts_for(owner)), t, with_modes, owner);
  set_path(c, run, u, dir);
  const int lo = r.lo, n = r.size();
  if (!with_modes) {
    std::fill(modes_.q.begin() + lo, modes_.q.begin() + r.hi, 0.0);
    std::fill(modes_.p.begin() + lo, modes_.p.begin() + r.hi, 0.0);
  } else {
    double* x = dev_.q.data();
    double* y = dev_.p.data();
    for (int k = 0; k < n; ++k) {
      x[k] = u[lo + k] - A_[lo + k] - B_[lo + k] * t;
      y[k] = v[lo + k] - B_[lo + k];
    }
    // Q^T W: the rows' masses weigh the deviation on a chain whose blocks differ.
    const std::vector<double>& w = run.shape->weight;
    for (int k = 0; k < static_cast<int>(w.size()); ++k) x[k] *= w[k], y[k] *= w[k];
    combine(n, run.shape->Qr.data(), x, y, modes_.q.data() + lo, modes_.p.data() + lo);
  }
  set_bounds(run, dir);
  return run;
}

void RunStore::set_bounds(const Run& run, const std::int8_t* dir) {
  if (run.owner != kModal && run.owner != kSpan) return;
  const int n = run.n();
  double* sE = dev_.p.data();
  for (int k = 0; k < n; ++k) {
    const double qk = modes_.q[run.lo + k], pk = modes_.p[run.lo + k];
    sE[k] = std::sqrt(pk * pk + run.shape->spectrum.w2[k] * qk * qk);
  }
  if (run.owner == kModal) {
    for (int row : {0, n - 1}) bound_[0][run.lo + row] = row_deviation_bound(*run.shape, row, sE);
    return;
  }
  for (int row = 0; row < n; ++row) {
    const int i = run.lo + row;
    if (row != 0 && row != n - 1 && (dir == nullptr || dir[i] == 0)) continue;
    double d[4];
    row_derivative_bounds(*run.shape, row, sE, d);
    for (int j = 0; j < 4; ++j) bound_[j + 1][i] = d[j];
  }
}

void RunStore::rebase(int lo, double t) {
  Run& run = records_.at(lo);
  if (run.modes) coords(run, t, modes_.q.data(), modes_.p.data());
  run.t0 = t;
}

void RunStore::coords(const Run& r, double t, double* q, double* p) const {
  r.shape->evolve(modes_.q.data() + r.lo, modes_.p.data() + r.lo, t - r.t0, q + r.lo, p + r.lo);
}

double RunStore::u(int i, double t) const {
  const Run& r = records_.run(i);
  if (!r.modes) return path_u(i, t);
  double q[64], p[64];  // the modes in blocks of 64: no allocation
  const double* row = r.shape->row(i - r.lo);
  const double tau = t - r.t0;
  double d = 0;
  for (int k0 = 0; k0 < r.n(); k0 += 64) {
    const int m = std::min(r.n() - k0, 64);
    r.shape->evolve(modes_.q.data() + r.lo + k0, modes_.p.data() + r.lo + k0, tau, q, p, k0, m);
    for (int k = 0; k < m; ++k) d += row[k0 + k] * q[k];
  }
  return path_u(i, t) + d;
}

double RunStore::row_a(int i, const double* q, const double* p) const {
  const Run& r = records_.run(i);
  const int n = r.n();
  const double* row = r.shape->row(i - r.lo);
  const double* w2 = r.shape->spectrum.w2.data();
  double d = 0;
  for (int k = 0; k < n; ++k) d += row[k] * (-gamma_ * p[r.lo + k] - w2[k] * q[r.lo + k]);
  return d;
}

void RunStore::write(const Run& r, double t, const double* q, const double* p, double* u, double* v, bool ends_only,
                     const double* du, const double* dv) {
  const int n = r.n(), lo = r.lo;
  const RunShape& sh = *r.shape;
  // Row k's modal parts (x, y): from its row on short runs (both sums in one pass), else from combine.
  auto put = [&](int k, double x, double y) {
    const int i = lo + k;
    u[i] = path_u(i, t) + x;
    v[i] = B_[i] + y;
    if (du != nullptr) u[i] += du[i], v[i] += dv[i];
  };
  auto by_row = [&](int k) {
    const double* row = sh.row(k);
    double x = 0, y = 0;
    for (int j = 0; j < n; ++j) x += row[j] * q[lo + j], y += row[j] * p[lo + j];
    put(k, x, y);
  };
  if (ends_only && n > 2) {
    by_row(0), by_row(n - 1);
  } else if (n <= kRowWise) {
    for (int k = 0; k < n; ++k) by_row(k);
  } else {
    combine(n, sh.Q.data(), q + lo, p + lo, sums_.q.data(), sums_.p.data());
    for (int k = 0; k < n; ++k) put(k, sums_.q[k], sums_.p[k]);
  }
}

void RunStore::write_path(const Run& r, double t, double* u, double* v, bool ends_only) const {
  if (ends_only) {
    for (int i : {r.lo, r.hi - 1}) u[i] = path_u(i, t), v[i] = B_[i];
    return;
  }
  for (int i = r.lo; i < r.hi; ++i) u[i] = path_u(i, t), v[i] = B_[i];
}

void RunStore::write_at(const Run& r, double t, double* u, double* v) {
  coords(r, t, dev_.q.data(), dev_.p.data());
  write(r, t, dev_.q.data(), dev_.p.data(), u, v);
}

void RunStore::taylor(int i, double t, const double* q, const double* p, int deg, double* c) const {
  const Run& r = records_.run(i);
  const double* row = r.shape->row(i - r.lo);
  c[0] = path_u(i, t);
  c[1] = B_[i];
  for (int j = 2; j <= deg; ++j) c[j] = 0.0;
  for (int k = 0; k < r.n(); ++k) add_taylor(row[k], q[r.lo + k], p[r.lo + k], gamma_, r.shape->spectrum.w2[k], deg, c);
  taylor_scale(deg, c);
}

}  // namespace sb::event_detail
