// Friction sums over a quiet phase's samples in closed form: what an observer of mu(t), its peak
// and its time averages needs from a stretch of samples, without visiting each one.
//
// Over samples tau_j = tau_0 + j dt a contact block's force is f = fa + fb tau + the springs to the
// groove ends beside it times their ringing. Where no f changes sign, sum_j |f| = sign(f) sum_j f, with
// sum_j (fa + fb tau_j) = m fa + fb sum_j tau_j and the ringing's sums from the integrator. A
// force keeps its sign while its affine part stays further from zero than the ringing can reach
// (bounded from the stretch's first sample on), and an affine part is monotone, so checking the
// last sample checks them all. The contact blocks with no groove neighbour have affine forces of
// one common slope (CommonSlopeSum): each crosses zero once, at a known time, and the samples
// between two such crossings are summed at once.
//
// An edge force whose sign the bounds cannot fix (its affine part within the ringing's reach:
// just after a slip, beside a groove still ringing) is summed sample by sample instead, from its
// groups' terms at every sample; the other forces stay in closed form, so one such edge does not
// send the whole stretch to one-by-one service.
#include "springblock/observe/ringing_sums.hpp"

#include <algorithm>
#include <cmath>

#include "springblock/infinity.hpp"

namespace sb {

RingingSums::RingingSums(RingingForces& forces)
    : f_(forces),
      now_(2 * static_cast<std::size_t>(forces.groups())),
      terms_(2 * static_cast<std::size_t>(forces.groups())),
      bound_(2 * static_cast<std::size_t>(forces.groups())),
      slot_(static_cast<std::size_t>(forces.groups())) {}

void RingingSums::prepare() {
  const long phase = f_.phase();
  if (interior_of_ == phase) return;
  const std::vector<double>& a = f_.interior();
  interior_.reset(a.data(), static_cast<int>(a.size()), f_.interior_slope());
  interior_of_ = phase;
  std::fill(now_.begin(), now_.end(), 0.0);
  split_.tau_end = -1;
  t0_ = f_.t0();
  edges_ = &f_.edges();
}

void RingingSums::at(double t, double& sum_abs, double& sum_signed) {
  prepare();
  if (split_.tau_end != f_.tau_end()) split_edges(f_.tau_end());
  const double tau = t - t0_;
  interior_.at(tau, sum_abs, sum_signed);
  sum_abs += split_.abs_a + split_.abs_b * tau;
  sum_signed += split_.signed_a + split_.signed_b * tau;
  f_.terms_now(tau, now_.data());
  const std::vector<EdgeForce>& edges = *edges_;
  for (int k : split_.listed) {
    const EdgeForce& e = edges[k];
    double f = e.fa + e.fb * tau;
    for (int r = 0; r < e.n; ++r) f += e.k[r] * now_[e.term[r]];
    sum_abs += std::fabs(f);
    sum_signed += f;
  }
}

// An affine force keeps the sign it starts with over [0, tau_end] when its slope does not lead
// it back to zero or its value at tau_end still has that sign (+inf: the slope alone decides).
void RingingSums::split_edges(double tau_end) {
  split_.live.assign(static_cast<std::size_t>(f_.groups()), 0);
  for (int g : f_.live_groups()) split_.live[g] = 1;
  split_.listed.clear();
  split_.abs_a = split_.abs_b = split_.signed_a = split_.signed_b = 0;
  const std::vector<EdgeForce>& edges = *edges_;
  for (std::size_t k = 0; k < edges.size(); ++k) {
    const EdgeForce& e = edges[k];
    bool ringing = false;
    for (int r = 0; r < e.n; ++r) ringing = ringing || split_.live[e.term[r] / 2];
    const double sg = e.fa >= 0 ? 1.0 : -1.0;
    const bool keeps = sg * e.fb >= 0 || (tau_end < kInf && sg * (e.fa + e.fb * tau_end) >= 0);
    if (ringing || !keeps) {
      split_.listed.push_back(static_cast<int>(k));
      continue;
    }
    split_.abs_a += sg * e.fa, split_.abs_b += sg * e.fb;
    split_.signed_a += e.fa, split_.signed_b += e.fb;
  }
  split_.tau_end = tau_end;
}

// Whether every contact block's force keeps its sign over tau0 .. tau_last, with bounds on the
// ringing from tau0 on in bound_. need_sums (window): the forces beside no groove are not tested
// (window splits the stretch at their crossings), an edge whose sign the bounds cannot fix is
// flagged in unsure_ instead of failing the test, and false when the ringing has no closed-form
// sample sum.
bool RingingSums::keeps_signs(double tau0, double tau_last, bool need_sums) {
  if (!need_sums && interior_.crossed(tau_last) != interior_.crossed(tau0)) return false;
  if (!f_.bounds(tau0, need_sums, bound_.data())) return false;
  // Edge forces: the affine part keeps clear of the ringing's reach, on the side it starts on, at
  // both ends of the stretch (so everywhere between).
  const std::vector<EdgeForce>& edges = *edges_;
  if (need_sums) unsure_.assign(edges.size(), 0);
  for (std::size_t k = 0; k < edges.size(); ++k) {
    const EdgeForce& e = edges[k];
    const double reach = edge_reach(e);
    const double f0 = e.fa + e.fb * tau0, sg = f0 >= 0 ? 1.0 : -1.0;
    if (sg * f0 > reach && sg * (e.fa + e.fb * tau_last) > reach) continue;
    if (!need_sums) return false;
    unsure_[k] = 1;
  }
  return true;
}

double RingingSums::edge_reach(const EdgeForce& e) const {
  double reach = 0;
  for (int r = 0; r < e.n; ++r) reach += e.k[r] * bound_[e.term[r]];
  return reach;
}

bool RingingSums::window(long k0, double dt, long n, double& sum_abs, double& sum_signed) {
  sum_abs = sum_signed = 0;
  if (n <= 0) return false;
  prepare();
  const double t0 = t0_;
  auto tau_of = [&](long k) { return static_cast<double>(k) * dt - t0; };
  const double tau0 = tau_of(k0);
  if (!keeps_signs(tau0, tau_of(k0 + n - 1), true)) return false;
  f_.sums(k0, dt, n, terms_.data());
  // The affine parts: sum of the sample times, sum_j (k dt - t0) with the sum of k exact in
  // integers.
  auto sum_of_taus = [&](long k, long m) {
    const double mm = static_cast<double>(m);
    return dt * (0.5 * static_cast<double>(2 * k + m - 1) * mm) - mm * t0;
  };
  const double mm = static_cast<double>(n);
  const double st = sum_of_taus(k0, n);
  // The forces beside no groove: each crosses zero once, at a known time, so the samples between
  // two crossings are summed at once, a stretch without one in a single piece.
  double interior_abs = 0, interior_signed = 0;
  for (long j = 0; j < n;) {
    const int p = interior_.crossed(tau_of(k0 + j));
    long lo = j, hi = n - 1;  // the last sample with p crossings: crossed() grows with tau
    while (lo < hi) {
      const long mid = hi - (hi - lo) / 2;
      if (interior_.crossed(tau_of(k0 + mid)) == p) lo = mid;
      else hi = mid - 1;
    }
    const long m = lo + 1 - j;
    double part_abs, part_signed;
    interior_.sums(p, m, sum_of_taus(k0 + j, m), part_abs, part_signed);
    interior_abs += part_abs, interior_signed += part_signed;
    j += m;
  }
  sum_abs = interior_abs, sum_signed = interior_signed;
  const std::vector<EdgeForce>& edges = *edges_;
  for (std::size_t k = 0; k < edges.size(); ++k) {
    if (unsure_[k]) continue;
    const EdgeForce& e = edges[k];
    double f = e.fa * mm + e.fb * st;
    for (int r = 0; r < e.n; ++r) f += e.k[r] * terms_[e.term[r]];
    sum_abs += e.fa + e.fb * tau0 >= 0 ? f : -f;  // every sample's sign (checked above)
    sum_signed += f;
  }
  unsure_sums(k0, dt, n, sum_abs, sum_signed);
  return true;
}

void RingingSums::unsure_sums(long k0, double dt, long n, double& sum_abs, double& sum_signed) {
  const double t0 = t0_;
  auto tau_of = [&](long k) { return static_cast<double>(k) * dt - t0; };
  // The groups beside the flagged edges, each given a slot of 2 n values: its two terms at each
  // sample.
  const std::vector<EdgeForce>& edges = *edges_;
  std::fill(slot_.begin(), slot_.end(), -1);
  int slots = 0;
  for (std::size_t k = 0; k < edges.size(); ++k)
    if (unsure_[k])
      for (int r = 0; r < edges[k].n; ++r)
        if (slot_[edges[k].term[r] / 2] < 0) slot_[edges[k].term[r] / 2] = slots++;
  if (slots == 0) return;
  const std::size_t nn = static_cast<std::size_t>(n);
  values_.assign(2 * nn * static_cast<std::size_t>(slots), 0.0);
  f_.series(k0, dt, n, slot_.data(), values_.data());
  for (std::size_t k = 0; k < edges.size(); ++k) {
    if (!unsure_[k]) continue;
    const EdgeForce& e = edges[k];
    for (long j = 0; j < n; ++j) {
      double f = e.fa + e.fb * tau_of(k0 + j);
      for (int r = 0; r < e.n; ++r)
        f += e.k[r] * values_[2 * nn * static_cast<std::size_t>(slot_[e.term[r] / 2]) +
                             (e.term[r] % 2 == 0 ? 0 : nn) + static_cast<std::size_t>(j)];
      sum_abs += std::fabs(f);
      sum_signed += f;
    }
  }
}

// Each sum is affine in tau up to the edges' ringing, whose sizes edge_reach bounds: with every
// sign fixed, sum |f| = sum sign(f) f. The sums at() forms round differently from the exact
// values, and the straight line between the ends rounds too; a margin of 1e-9 of the sums' size,
// millions of times their round-off, keeps the bound a bound.
bool RingingSums::envelope(long k0, double dt, long n, Envelope& env) {
  if (n <= 0) return false;
  prepare();
  const double t0 = t0_;
  auto tau_of = [&](long k) { return static_cast<double>(k) * dt - t0; };
  const double tau0 = tau_of(k0), tau1 = tau_of(k0 + n - 1);
  if (!keeps_signs(tau0, tau1, false)) return false;
  interior_.at(tau0, env.abs_first, env.signed_first);
  interior_.at(tau1, env.abs_last, env.signed_last);
  double reach = 0;
  for (const EdgeForce& e : *edges_) {
    const double f0 = e.fa + e.fb * tau0, f1 = e.fa + e.fb * tau1, sg = f0 >= 0 ? 1.0 : -1.0;
    env.abs_first += sg * f0, env.abs_last += sg * f1;
    env.signed_first += f0, env.signed_last += f1;
    reach += edge_reach(e);
  }
  env.reach = reach + 1e-9 * (std::fabs(env.abs_first) + std::fabs(env.abs_last) + reach);
  return true;
}

}  // namespace sb
