#include "springblock/integrate/events/span_screen.hpp"

#include <algorithm>
#include <cmath>

#include "springblock/integrate/numerics/estrin.hpp"
#include "springblock/integrate/numerics/first_root.hpp"
#include "springblock/infinity.hpp"
#include "springblock/integrate/numerics/round_off.hpp"

namespace sb::event_detail {
namespace {

// Whether g > 0 on (0, h] follows from its values g0, g1 and slopes d0, d1 (per unit of tau) at
// the ends of a step h and a bound M4 on |g''''|. g leaves its cubic Hermite interpolant H by at
// most K s^2 (1 - s)^2, K = M4 h^4 / 24, s = tau / h. Either test suffices: the minimum of H on
// [0, 1] above K / 16 (the largest allowance), or the quartic H - K s^2 (1 - s)^2 positive by its
// Bernstein coefficients, which keeps the allowance's vanishing at the ends: a block that has
// just started to slide starts at g = eps_v, and only the second test sees it rise.
bool hermite_positive(double g0, double d0, double g1, double d1, double h, double M4) {
  const double b = h * d0, c = 3.0 * (g1 - g0) - h * (2.0 * d0 + d1), d = 2.0 * (g0 - g1) + h * (d0 + d1);
  const double K = M4 * h * h * h * h / 24.0;
  const double a2 = c - K, a3 = d + 2.0 * K, a4 = -K;
  if (g0 >= 0 && g0 + 0.25 * b > 0 && g0 + 0.5 * b + a2 / 6.0 > 0 && g0 + 0.75 * b + 0.5 * a2 + 0.25 * a3 > 0 &&
      g0 + b + a2 + a3 + a4 > 0)
    return true;
  auto H = [&](double x) { return g0 + x * (b + x * (c + x * d)); };
  double m = std::min(g0, g1);
  auto at = [&](double x) {
    if (x > 0.0 && x < 1.0) m = std::min(m, H(x));
  };
  if (d == 0.0) {
    if (c != 0.0) at(-b / (2.0 * c));
  } else {
    const double disc = c * c - 3.0 * d * b;
    if (disc >= 0.0) {
      const double r = std::sqrt(disc);
      at((-c - r) / (3.0 * d));
      at((-c + r) / (3.0 * d));
    }
  }
  return m - K / 16.0 > 0;
}

}  // namespace

SpanScreen::SpanScreen(const Chain& c)
    : v_(c.v_slider), eps_v_(kStopMargin * c.v_slider), N_(c.N) {}

SpanScreen::Border SpanScreen::border(const SpanModes& spans, const ActiveSet& active, int j) const {
  if (j < 0 || j >= N_) return {kNone, -1};
  if (spans.holds(j)) return {kSpan, -1};
  if (active.kind(j) == ActiveSet::kSettled) return {kSettled, spans.store().run(j).id};
  if (active.kind(j) == ActiveSet::kModal) return {kModal, spans.store().run(j).id};
  return {kFixed, -1};
}

bool SpanScreen::current(const State& s, const SpanModes& spans, const ActiveSet& active, const Watch& w) const {
  for (const Fn& f : w.fns_) {
    if (s.dir[f.block] != f.dir) return false;
    if (f.dir == 0 && (f.border[0] != border(spans, active, f.block - 1) ||
                       f.border[1] != border(spans, active, f.block + 1)))
      return false;
  }
  return true;
}

void SpanScreen::rebuild(const Chain& c, const State& s, const SpanModes& spans, const ActiveSet& active, int k0,
                         int k1, Watch& w) const {
  std::vector<Fn>& fns_ = w.fns_;
  fns_.clear();
  const int N = c.N;
  // A stuck block between two stepped runs borders both: it is listed once (the runs come in
  // block order, so it is the last one listed).
  auto add_stuck = [&](int j) {
    if (j < 0 || j >= N || (!fns_.empty() && fns_.back().block == j)) return;
    Fn f{j, 0, {border(spans, active, j - 1), border(spans, active, j + 1)}, {}, {}, 0, 0, 0};
    for (int side = 0; side < 2; ++side) {
      const int nb = side == 0 ? j - 1 : j + 1;
      if (f.border[side].side == kNone) continue;
      const double k = c.spring_between(j, nb);
      if (f.border[side].side == kSpan) f.M2 += k * spans.row_bound(nb, 2), f.M4 += k * spans.row_bound(nb, 4);
      if (f.border[side].side == kModal) f.spread += k * active.modal_amplitude(nb);
    }
    fns_.push_back(f);
  };
  for (int k = k0; k < k1; ++k) {
    const BlockRange& r = spans.span(k);
    add_stuck(r.lo - 1);
    for (int i = r.lo; i < r.hi; ++i)
      if (s.dir[i] != 0) fns_.push_back({i, s.dir[i], {}, {}, {}, spans.row_bound(i, 3), spans.row_bound(i, 5), 0});
    add_stuck(r.hi);
  }
  for (Fn& f : fns_) f.start.g = cheap(c, s, spans, active, f, s.t, false);
}

double SpanScreen::cheap(const Chain& c, const State& s, const SpanModes& spans, const ActiveSet& active,
                         const Fn& f, double t, bool end, bool slope) const {
  const int j = f.block;
  // At a fresh projection's time the rows read are the state's own u and v (SpanModes::fresh).
  auto fresh_at_start = [&](int i) { return !end && spans.fresh(i); };
  if (f.dir != 0)
    return f.dir * (slope ? spans.a(j, end) : (fresh_at_start(j) ? s.v[j] : spans.v(j, end)) + eps_v_ * f.dir);
  // The driving force as the Dormand-Prince search sums it (event_search.cpp), and its slope.
  const double uj = s.u[j];
  const double k_s = c.k_s(j);
  double F = k_s * (v_ * t - uj), dF = k_s * v_;
  for (int side = 0; side < 2; ++side) {
    const int nb = side == 0 ? j - 1 : j + 1;
    if (f.border[side].side == kNone) continue;
    const double k = c.spring_between(j, nb);
    switch (f.border[side].side) {
      case kNone: break;  // skipped above: there is no block there, nor a spring
      case kSpan:
        F += k * ((fresh_at_start(nb) ? s.u[nb] : spans.u(nb, end)) - uj);
        if (slope) dF += k * (fresh_at_start(nb) ? s.v[nb] : spans.v(nb, end));
        break;
      case kSettled:
      case kModal:
        F += k * (active.path_u(nb, t) - uj);
        dF += k * active.path_slope(nb);
        break;
      case kFixed: F += k * (s.u[nb] - uj); break;
    }
  }
  if (slope) return F >= 0 ? -dF : dF;
  return c.f_static[j] - std::fabs(F) - f.spread;
}

double SpanScreen::locate(const Chain& c, const State& s, const SpanModes& spans, ActiveSet& active, Watch& w,
                          double t0, double h, double window) {
  double best = kInf;
  const double chord = 0.125 * h * h;
  for (Fn& f : w.fns_) {
    f.end.g = cheap(c, s, spans, active, f, t0 + h, true);
    f.end.known = false;
    f.root = kInf;
    if (f.end.g > 0 && std::min(f.start.g, f.end.g) - f.M2 * chord > 0) continue;
    if (f.end.g > 0) {
      if (!f.start.known) f.start.d = cheap(c, s, spans, active, f, t0, false, true), f.start.known = true;
      f.end.d = cheap(c, s, spans, active, f, t0 + h, true, true), f.end.known = true;
      if (hermite_positive(f.start.g, f.start.d, f.end.g, f.end.d, h, f.M4)) continue;
    }
    // A root later than best + window h can neither be the event nor join it (the final best is
    // no later than this one): exact_root does not refine it.
    f.root = exact_root(c, s, spans, active, f, t0, h, best + window * h);
    best = std::min(best, f.root);
  }
  w.hits_.clear();
  if (best <= h)
    for (const Fn& f : w.fns_)
      if (f.root <= best + window * h) w.hits_.push_back(f.block);
  return best;
}

void SpanScreen::accept(Watch& w) {
  for (Fn& f : w.fns_) f.start = f.end;
}

// g over the step as a polynomial in tau = t - t0: the rows' Taylor polynomials combined as the
// cheap form combines their values.
double SpanScreen::exact_root(const Chain& c, const State& s, const SpanModes& spans, ActiveSet& active, const Fn& f,
                              double t0, double h, double after) {
  double row[D + 2], g[D + 1];
  const int j = f.block;
  if (f.dir != 0) {
    spans.row_taylor(j, row);
    for (int k = 0; k <= D; ++k) g[k] = f.dir * ((k + 1) * row[k + 1]);
    g[0] += eps_v_;
    return poly_root(g, t0, h, after);
  }
  double F[D + 1] = {};
  const double uj = s.u[j];
  F[0] = c.k_s(j) * (v_ * t0 - uj);
  F[1] = c.k_s(j) * v_;
  for (int side = 0; side < 2; ++side) {
    const int nb = side == 0 ? j - 1 : j + 1;
    if (f.border[side].side == kNone) continue;
    const double kj = c.spring_between(j, nb);
    switch (f.border[side].side) {
      case kNone: continue;  // skipped above
      case kFixed: F[0] += kj * (s.u[nb] - uj); continue;
      case kSettled:
        F[0] += kj * (active.path_u(nb, t0) - uj);
        F[1] += kj * active.path_slope(nb);
        continue;
      case kSpan: spans.row_taylor(nb, row); break;
      case kModal: active.modal_taylor(nb, t0, D, row); break;
    }
    F[0] += kj * (row[0] - uj);
    for (int k = 1; k <= D; ++k) F[k] += kj * row[k];
  }
  const double fs = c.f_static[j];
  double root = kInf;
  for (double sense : {1.0, -1.0}) {
    for (int k = 0; k <= D; ++k) g[k] = -sense * F[k];
    g[0] += fs;
    root = std::min(root, poly_root(g, t0, h, std::min(after, root)));
  }
  return root;
}

double SpanScreen::poly_root(const double* g, double t0, double h, double after) const {
  // g >= g_0 - sum_j |g_j| h^j on [0, h]. Where that is positive by far more than round-off,
  // every Bernstein coefficient (g_0 plus weights in [0, 1] times the others) is positive too,
  // so first_bracket would find nothing: the same answer without the change of basis.
  // The caller has no use for a root after `after`. The same test on [0, past], past a little
  // beyond it (a few times the refinement's final width, so that no root it would put at or before
  // `after` is missed), finds most of those without the change of basis either.
  auto spread_to = [&](double tau) {
    double sum = 0, tj = 1.0;
    for (int j = 1; j <= D; ++j) tj *= tau, sum += std::fabs(g[j] * tj);
    return sum;
  };
  auto clear = [&](double spread) { return g[0] - spread > 1e-10 * (g[0] + spread); };
  const double past = after + 4.0 * time_round_off(t0 + after);
  if (past < h && clear(spread_to(past))) return kInf;
  const double spread = spread_to(h);
  if (clear(spread)) return kInf;
  double lo, hi;
  if (!bern_.first_bracket(g, h, lo, hi)) return kInf;
  auto p = [&](double x) { return estrin<D>(g, x); };  // estrin.hpp: latency, not flops
  // The bracket holds one sign change of g, so g > 0 at `past` puts the root after it, and one
  // evaluation replaces the refinement (~9).
  if (past > lo && past < hi && p(past) > 0) return kInf;
  // At the step's start the polynomial is g_0, as its evaluation there would give (every term
  // but the first vanishes; only the sign of a zero could differ, which no comparison sees).
  const double p_lo = lo == 0.0 && std::isfinite(g[0] + spread) ? g[0] : p(lo);
  return first_root(p, lo, p_lo, hi, p(hi), [&](double x) { return time_round_off(t0 + x); });
}

}  // namespace sb::event_detail
