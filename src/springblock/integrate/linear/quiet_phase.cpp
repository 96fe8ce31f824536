#include "springblock/integrate/linear/quiet_phase.hpp"
#include "springblock/integrate/linear/envelope.hpp"
#include "springblock/integrate/numerics/affine_crossing.hpp"
#include "springblock/infinity.hpp"

#include <algorithm>
#include <cmath>

namespace sb::event_detail {

QuietPhase::QuietPhase(const Chain& c, RunStore& store)
    : slider_slope_(c.K_s * c.v_slider), store_(store), cursor_{0, Coords(c.N), false}, kept_(cursor_) {
  const int N = c.N;
  std::vector<int> seg_of(N, -1);  // groove block -> its segment, for the contact blocks beside it
  for (int i = 0; i < N;) {
    if (c.contact[i]) {
      ++i;
      continue;
    }
    int j = i + 1;
    while (j < N && !c.contact[j]) ++j;
    std::fill(seg_of.begin() + i, seg_of.begin() + j, static_cast<int>(segs_.size()));
    segs_.push_back(GrooveRun{i, j - i, &store.shapes().of({i, j}, RunShape::kSample)});
    i = j;
  }

  for (int j = 0; j < N; ++j) {
    if (!c.contact[j]) continue;
    Edge e;
    e.block = j;
    EdgeForce f;
    for (int nb : {j - 1, j + 1}) {
      if (!(c.K_int > 0) || nb < 0 || nb >= N || c.contact[nb]) continue;
      const int g = seg_of[nb];
      const GrooveRun& s = segs_[g];
      const int n = f.n++;
      f.k[n] = c.spring_between(j, nb);
      f.term[n] = 2 * g + (nb == s.first ? 0 : 1);
      const double* row = s.shape->row(nb - s.first);
      for (int k = 0; k < s.n; ++k) e.march.add_mode(f.k[n] * row[k], s.shape->modes[k], s.first + k);
    }
    // A block beside no groove has the slider's slope, shared by all such blocks on a chain
    // whose slider springs are equal (CommonSlopeSum sums them at once); where they differ it is
    // an edge without ringing.
    if (f.n == 0 && c.uniform()) {
      interior_.blocks.push_back(j);
      continue;
    }
    if (f.n) e.march.finish();
    edges_.forces.push_back(f);
    edges_.list.push_back(std::move(e));
  }
  interior_.a.resize(interior_.blocks.size());
  edges_.order.reserve(edges_.list.size());
}

// Underdamped modes shrink at least like e^{-alpha tau} (amplitude and velocity amplitude); once
// below 1e-17 of the segment's u and v scales they no longer change a double (dead_tau), and
// below the sample scales they are dropped from samples (sample_dead_tau).
void QuietPhase::set_dead_times(GrooveRun& s) const {
  const RunStore::Run& rec = store_.run(s.first);
  // Without modes only whether the scales are positive counts (below): the first rows that make
  // them so settle it, not a pass over all rows.
  double uscale = 0, vscale = 0;
  const auto scales_positive = [&] { return 1e-17 * uscale > 0 && 1e-17 * vscale > 0; };
  for (int i = s.first; i < s.first + s.n && (rec.modes || !scales_positive()); ++i) {
    uscale = std::max(uscale, std::fabs(store_.path_u(i, span_.t0)));
    vscale = std::max(vscale, std::fabs(store_.B(i)));
  }
  if (rec.modes) {
    const TransientEnvelope env = store_.envelope(rec);
    s.dead_tau = env.time_below(1e-17 * uscale, 1e-17 * vscale);
    s.sample_dead_tau = std::min(s.dead_tau, env.time_below(scales_.u, scales_.v));
    return;
  }
  // No modes (q0 = p0 = 0): the envelope is zero, so each time is 0 where its scales are
  // positive and the modes decay, infinity otherwise, as time_below gives.
  bool decays = rec.shape->n > 0;
  for (const DampedMode& m : rec.shape->modes) decays = decays && m.alpha > 0 && m.s > 0;
  s.dead_tau = decays && scales_positive() ? 0.0 : kInf;
  s.sample_dead_tau = std::min(s.dead_tau, decays && scales_.u > 0 && scales_.v > 0 ? 0.0 : kInf);
}

void QuietPhase::begin(const Chain& c, double t0, const double* u, const double* v) {
  span_.t0 = t0;
  span_.next = kInf;
  cursor_.valid = false;
  ++interior_.phase;
  live_.clear();
  for (std::size_t k = 0; k < segs_.size(); ++k) {
    GrooveRun& s = segs_[k];
    const BlockRange r{s.first, s.first + s.n};
    const RunStore::Run* held = store_.exact(r);
    if (held != nullptr && (held->owner == RunStore::kSettled || held->owner == RunStore::kModal))
      store_.rebase(s.first, t0);
    else
      store_.project(c, r, t0, u, v, nullptr, RunStore::kQuiet);
    set_dead_times(s);
    if (store_.run(s.first).modes) live_.push_back(static_cast<int>(k));
  }
  for (std::size_t k = 0; k < interior_.blocks.size(); ++k)
    interior_.a[k] = c.driving_force(interior_.blocks[k], u, v, t0);
  for (std::size_t x = 0; x < edges_.list.size(); ++x) {
    Edge& e = edges_.list[x];
    EdgeForce& f = edges_.forces[x];
    double a = c.driving_force(e.block, u, v, t0), b = c.k_s(e.block) * c.v_slider;
    for (int n = 0; n < f.n; ++n) {
      const GrooveRun& s = segs_[f.term[n] / 2];  // term 2 g + end: segment g's first or last row
      const int i = f.term[n] % 2 == 0 ? s.first : s.first + s.n - 1;
      b += f.k[n] * store_.B(i);
      // A record without modes has q0 = 0: its terms would subtract zeros.
      if (!store_.run(s.first).modes) continue;
      const double* row = s.shape->row(i - s.first);
      for (int k = 0; k < s.n; ++k) a -= f.k[n] * row[k] * store_.q0()[s.first + k];
    }
    e.march.set_affine(a, b);
    f.fa = a, f.fb = b;
  }
}

void QuietPhase::release() {
  for (const GrooveRun& s : segs_)
    if (store_.owner(s.first) == RunStore::kQuiet) store_.drop(s.first);
}

double QuietPhase::all_dead_after() const {
  double tau = 0;
  for (const GrooveRun& s : segs_) tau = std::max(tau, s.sample_dead_tau);
  return span_.t0 + tau;
}

void QuietPhase::affine_forces(const Chain& c, const double* u, double* a, double* b) const {
  // A groove neighbour j of a contact block sits at A_j + B_j t; a stuck neighbour at u_j.
  for (int i = 0; i < c.N; ++i) {
    a[i] = b[i] = 0.0;
    if (!c.contact[i]) continue;
    a[i] = -c.k_s(i) * u[i];
    b[i] = c.k_s(i) * c.v_slider;
    if (c.K_int > 0)
      for (int j : {i - 1, i + 1}) {
        if (j < 0 || j >= c.N) continue;
        const double k = c.spring_between(i, j);
        a[i] += k * ((c.contact[j] ? u[j] : store_.A(j)) - u[i]);
        if (!c.contact[j]) b[i] += k * store_.B(j);
      }
  }
}

QuietPhase::Next QuietPhase::next_threshold(const Chain& c, double t_limit) {
  double best = t_limit - span_.t0;
  int block = -1;
  for (std::size_t k = 0; k < interior_.blocks.size(); ++k) {
    const int j = interior_.blocks[k];
    const double tau = affine_crossing(interior_.a[k], c.K_s * c.v_slider, c.f_static[j]);
    if (tau < best) best = tau, block = j;
  }
  // Search the edges likeliest to cross first first: each search stops at the best time so far.
  // An edge whose segments have no modes (settled grooves) has an affine force: closed form, and
  // it is not searched, so only the edges with modes are ordered (a search marches the same steps
  // whatever its limit, so the order changes how early searches stop, not the crossing found).
  edges_.order.clear();
  for (std::size_t k = 0; k < edges_.list.size(); ++k) {
    Edge& e = edges_.list[k];
    const EdgeForce& f = edges_.forces[k];
    bool modes = false;
    for (int n = 0; n < f.n; ++n) modes = modes || segs_[f.term[n] / 2].dead_tau > 0;
    if (!modes) {
      e.lower = kInf;  // never searched below
      const double tau = affine_crossing(f.fa, f.fb, c.f_static[e.block]);
      if (tau < best || (tau == best && block >= 0 && e.block < block)) best = tau, block = e.block;
    } else {
      e.lower = e.march.lower_bound(store_.q0(), store_.p0(), c.f_static[e.block]);
      edges_.order.push_back(static_cast<int>(k));
    }
  }
  // With no limit (best infinite) an affine edge's lower bound is not above it: search every edge.
  if (!(best < kInf)) {
    edges_.order.resize(edges_.list.size());
    for (std::size_t k = 0; k < edges_.list.size(); ++k) edges_.order[k] = static_cast<int>(k);
  }
  std::sort(edges_.order.begin(), edges_.order.end(),
            [&](int x, int y) { return edges_.list[x].lower < edges_.list[y].lower; });
  for (int k : edges_.order) {
    Edge& e = edges_.list[k];
    if (e.lower > best) break;
    const double tau = e.march.first_crossing(store_.q0(), store_.p0(), c.f_static[e.block], best, span_.t0);
    if (tau < best || (tau == best && block >= 0 && e.block < block)) best = tau, block = e.block;
  }
  span_.next = span_.t0 + best;
  return {span_.next, block};
}

}  // namespace sb::event_detail
