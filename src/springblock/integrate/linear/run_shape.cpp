#include "springblock/integrate/linear/run_shape.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "springblock/integrate/integrator.hpp"
#include "springblock/integrate/linear/edge_march.hpp"
#include "springblock/integrate/linear/general_modes.hpp"

namespace sb::event_detail {
namespace {

// The longest step of the exact stepper, kExactStepRadians of the fastest rate: a step turns every
// mode by at most 0.75 rad, so the screen's Hermite allowance M4 H^4 / 384 is ~1/1200 of a row's
// amplitude and the Taylor remainder over a step (degree 13 of u, so 12 of its velocity) below
// 0.75^14 / 14! ~ 2e-13 of it. Chosen by measurement (paper/choices.md, Integration): 0.5 rad with
// degree 10 and 1 rad with degree 14 cost a few per cent more per switch, 0.35 rad with degree 8
// some 5 % more.
static_assert(kExactStepRadians == 0.75, "the bounds above are worked out for 0.75 rad");

// The modes of a run in closed form. Its stiffness is K_s I + K_int L, L the Laplacian of a path
// of n blocks whose end rows lose their outer spring at a free chain end. With every block alike,
// L's eigenvectors are sampled sines and cosines (the discrete sine and cosine transforms),
// j = 0 .. n-1 the row, k = 0 .. n-1 the mode, eigenvalue 2 - 2 cos theta:
//   held at both ends (u_-1 = u_n = 0):     sin(theta (j + 1)),   theta = pi (k + 1) / (n + 1)
//   free left, held right (u_-1 = u_0):     cos(theta (j + 1/2)), theta = pi (2k + 1) / (2n + 1)
//   held left, free right:                  the same, mirrored (j -> n - 1 - j)
//   free at both ends:                      cos(theta (j + 1/2)), theta = pi k / n
// Each column is normalised by its computed norm, and the eigenvalues rise with k, as a
// symmetric eigensolver would order them. O(n^2) per shape, against O(n^3) for the solver, which
// the runs of many lengths of the exact stepper ask for once per repetition each.
void closed_form_modes(double K_s, double K_int, int n, bool left, bool right, Eigen::MatrixXd& Q,
                       std::vector<double>& lambda) {
  const double pi = 3.14159265358979323846;
  Q.resize(n, n);
  lambda.resize(n);
  for (int k = 0; k < n; ++k) {
    double theta;
    if (left && right) theta = pi * (k + 1) / (n + 1);
    else if (left || right) theta = pi * (2 * k + 1) / (2 * n + 1);
    else theta = pi * k / n;
    double norm2 = 0;
    for (int j = 0; j < n; ++j) {
      const int jj = (left && !right) ? n - 1 - j : j;  // the free end at row 0
      const double x = (left && right) ? std::sin(theta * (jj + 1)) : std::cos(theta * (jj + 0.5));
      Q(j, k) = x;
      norm2 += x * x;
    }
    const double inv = 1.0 / std::sqrt(norm2);
    for (int j = 0; j < n; ++j) Q(j, k) *= inv;
    lambda[k] = K_s + K_int * (2.0 - 2.0 * std::cos(theta));
  }
}

}  // namespace

void Factors::factor() {
  const int n = static_cast<int>(diag.size());
  inv_pivot.resize(n);
  upper.assign(n, 0.0);
  for (int k = 0; k < n; ++k) {
    const double pivot = k == 0 ? diag[0] : diag[k] - off[k - 1] * upper[k - 1];
    inv_pivot[k] = 1.0 / pivot;
    if (k + 1 < n) upper[k] = off[k] / pivot;
  }
}

// Written here rather than taken from GSL, whose tridiagonal solver factors K again for every
// right-hand side: a projection solves one per run.
void Factors::solve(const double* f, double* y) const {
  const int n = static_cast<int>(diag.size());
  for (int r = 0; r < n; ++r) y[r] = (r == 0 ? f[0] : f[r] - off[r - 1] * y[r - 1]) * inv_pivot[r];
  for (int r = n - 2; r >= 0; --r) y[r] -= upper[r] * y[r + 1];
}

// Every run's modes are below sqrt((K_s + 4 K_int) / m); an overdamped mode decays no faster than gamma. The step is
// set by the faster of the two, so the Taylor bound of kExactStepRadians holds for all.
RunShapes::RunShapes(const Chain& c)
    : c_(c), step_(kExactStepRadians / std::max(c.omega_max(), c.gamma)), march_step_(EdgeMarch::grid_step(c.omega_max())) {}

const RunShape& RunShapes::get(int n, bool left, bool right, std::uint8_t parts) {
  const std::size_t slot = 4 * static_cast<std::size_t>(n) + 2 * left + right;
  if (slot >= index_.size()) index_.resize(slot + 1, nullptr);
  if (index_[slot] == nullptr) index_[slot] = &shapes_.emplace_back(make({0, n}, left, right));
  RunShape& sh = *index_[slot];
  if ((sh.steps.parts & parts) != parts) add_parts(sh, parts);
  return sh;
}

// K and the path's pieces (run_shape.hpp) from each block's own values: K's diagonal K_s,i plus
// the springs to block i's neighbours, K B = (K_s,i v), a0 = K^-1 (-m_i gamma B_i), gL and gR =
// K^-1 of the holding springs at the ends.
RunShape RunShapes::make(BlockRange r, bool left, bool right) const {
  const Chain& c = c_;
  const int n = r.size(), lo = r.lo;
  RunShape sh;
  sh.n = n, sh.path.left = left, sh.path.right = right;
  Factors& K = sh.K;
  for (int k = 0; k < n; ++k) {
    const int i = lo + k;
    K.diag.push_back(c.k_s(i) + ((k > 0 || left) ? c.spring(i - 1) : 0.0) + ((k + 1 < n || right) ? c.spring(i) : 0.0));
    if (k + 1 < n) K.off.push_back(-c.spring(i));
  }
  K.factor();
  AffinePieces& path = sh.path;
  path.B.resize(n);
  for (int k = 0; k < n; ++k) path.B[k] = c.k_s(lo + k) * c.v_slider;
  K.solve(path.B.data(), path.B.data());
  path.a0.resize(n), path.gL.assign(n, 0.0), path.gR.assign(n, 0.0);
  for (int k = 0; k < n; ++k) path.a0[k] = -c.mass(lo + k) * c.gamma * path.B[k];
  K.solve(path.a0.data(), path.a0.data());
  if (left) path.gL[0] = c.spring(lo - 1), K.solve(path.gL.data(), path.gL.data());
  if (right) path.gR[n - 1] = c.spring(r.hi - 1), K.solve(path.gR.data(), path.gR.data());
  if (c.uniform()) {
    cached_modes(std::make_tuple(c.K_s, c.K_int, n, left, right),
                 [&](auto& Q, auto& lambda) { closed_form_modes(c.K_s, c.K_int, n, left, right, Q, lambda); }, sh.Q,
                 sh.spectrum.lambda);
  } else {
    sh.weight.resize(n);
    for (int k = 0; k < n; ++k) sh.weight[k] = c.mass(lo + k) / c.m;
    std::vector<double> key(K.diag);  // every value general_modes reads
    key.insert(key.end(), K.off.begin(), K.off.end());
    key.insert(key.end(), sh.weight.begin(), sh.weight.end());
    cached_modes(std::move(key), [&](auto& Q, auto& lambda) { general_modes(K, sh.weight, Q, lambda); }, sh.Q,
                 sh.spectrum.lambda);
  }
  finish_modes(sh, c.m, c.gamma);
  return sh;
}

// The modes' rows and oscillators and the constants of the derivative bounds, from Q and lambda:
// from q'' = -gamma q' - omega^2 q and omega |q| <= sqrt(E), |q''| <= (gamma + omega) sqrt(E) and
// q^(j+2) = -gamma q^(j+1) - omega^2 q^(j) for the higher ones.
void RunShapes::finish_modes(RunShape& sh, double mass, double gamma) {
  const int n = sh.n;
  Spectrum& sp = sh.spectrum;
  sh.Qr.resize(static_cast<std::size_t>(n) * n);
  for (int r = 0; r < n; ++r)
    for (int k = 0; k < n; ++k) sh.Qr[static_cast<std::size_t>(r) * n + k] = sh.Q(r, k);
  for (int k = 0; k < n; ++k) {
    const DampedMode m(0.5 * gamma, sp.lambda[k] / mass);
    sh.modes.push_back(m);
    sp.w2.push_back(m.omega2);
    sp.inv_omega.push_back(1.0 / m.omega);
    const double c2 = gamma + m.omega, c3 = gamma * c2 + m.omega2;
    const double c4 = gamma * c3 + m.omega2 * c2, c5 = gamma * c4 + m.omega2 * c3;
    sp.c[0].push_back(c2), sp.c[1].push_back(c3), sp.c[2].push_back(c4), sp.c[3].push_back(c5);
  }
}

// Each transition costs two mode evaluations (an exp and a sincos), so a shape makes only those
// its users ask for (what each owner of a run asks for: parts_for, run_store.cpp).
void RunShapes::add_parts(RunShape& sh, std::uint8_t parts) const {
  Transitions& st = sh.steps;
  const std::uint8_t missing = parts & ~st.parts;
  for (const DampedMode& m : sh.modes) {
    if (missing & RunShape::kStep) {
      const Transition P = m.transition(step_);
      st.p00.push_back(P[0]), st.p01.push_back(P[1]), st.p10.push_back(P[2]), st.p11.push_back(P[3]);
    }
    if (missing & RunShape::kMarch) st.march.push_back(m.transition(march_step_));
  }
  st.parts |= missing;
  if ((missing & RunShape::kSample) && sample_dt_ > 0) set_sample_transitions(sh);
}

void RunShapes::set_sample_transitions(RunShape& sh) const {
  Transitions& st = sh.steps;
  st.sample.clear();
  st.sample_sum.clear();
  for (const DampedMode& m : sh.modes) {
    const Transition P = m.transition(sample_dt_);
    st.sample.push_back(P);
    const double det = (1.0 - P[0]) * (1.0 - P[3]) - P[1] * P[2];
    const double nan = std::numeric_limits<double>::quiet_NaN();
    st.sample_sum.push_back(std::fabs(det) < 1e-6 ? std::array<double, 2>{nan, nan}
                                                  : std::array<double, 2>{(1.0 - P[3]) / det, P[1] / det});
  }
}

void RunShapes::set_sample_dt(double dt) {
  sample_dt_ = dt;
  for (RunShape& sh : shapes_)
    if (sh.steps.parts & RunShape::kSample) set_sample_transitions(sh);
}

}  // namespace sb::event_detail
