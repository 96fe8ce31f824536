// The quiet phase's samples summed in closed form (QuietSums::window): what an observer of
// time averages alone needs from a stretch of samples, without visiting each one.
//
// Over samples tau_j = tau_0 + j dt a contact block's force is f = fa + fb tau + K_int (end rows
// of its groove segments' modes). Where no f changes sign, sum_j |f| = sign(f) sum_j f, and
//   sum_j (fa + fb tau_j)  is m fa + fb sum_j tau_j,
//   sum_j q_k(tau_j)       is the geometric series of mode k's sample transition P:
//                          (I - P)^-1 (x_0 - x_m), x_j = (q_k, q_k')(tau_j) (first row only).
// A force keeps its sign while its affine part stays further from zero than the modes can
// reach: each mode's energy never grows, so the bound taken at tau_0 holds throughout, and an
// affine part is monotone, so checking the last sample checks them all. The contact blocks with
// no groove neighbour have affine forces of one common slope (CommonSlopeSum): each crosses zero
// once, at a known time, and the samples between two such crossings are summed at once.
//
// An edge force whose sign the bound cannot fix (its affine part within the modes' reach: just
// after a slip, beside a groove still ringing) is summed sample by sample instead, from its
// segments' end rows brought from sample to sample by the same recurrence as advance_sample;
// the other forces stay in closed form, so one such edge does not send the whole block of samples
// to one-by-one service (every live mode advanced, every edge summed, per sample).
#include <algorithm>
#include <cmath>

#include "springblock/integrate/linear/envelope.hpp"
#include "springblock/integrate/linear/quiet_sums.hpp"

namespace sb::event_detail {

QuietSums::QuietSums(const QuietPhase& phase)
    : phase_(phase),
      end_dots_(2 * phase.segments().size()),
      w0_(static_cast<int>(phase.cursor().q.size())),
      w1_(static_cast<int>(phase.cursor().q.size())),
      end_bound_(2 * phase.segments().size()),
      slot_(phase.segments().size()) {}

// Every interior force has the slider's slope K_s v (QuietPhase::next_threshold's affine
// crossings).
void QuietSums::prepare() {
  if (interior_of_ == phase_.phases()) return;
  const std::vector<double>& a = phase_.interior_forces();
  interior_.reset(a.data(), static_cast<int>(a.size()), phase_.slider_slope());
  interior_of_ = phase_.phases();
}

void QuietSums::at(double t, double& sum_abs, double& sum_signed) {
  const double tau = t - phase_.t0();
  prepare();
  interior_.at(tau, sum_abs, sum_signed);
  // The end rows' modal displacement of each live segment (dead ones: none, as in write_sample).
  for (std::size_t k = 0; k < phase_.segments().size(); ++k) {
    const QuietPhase::GrooveRun& s = phase_.segments()[k];
    double first = 0, last = 0;
    if (tau <= s.sample_dead_tau) s.shape->end_rows(phase_.cursor().q.data() + s.first, first, last);
    end_dots_[2 * k] = first, end_dots_[2 * k + 1] = last;
  }
  for (const QuietPhase::Edge& e : phase_.edges()) {
    double f = e.fa + e.fb * tau;
    for (int n = 0; n < e.nseg; ++n) f += phase_.K_int() * end_dots_[2 * e.seg[n] + (e.row[n] == 0 ? 0 : 1)];
    sum_abs += std::fabs(f);
    sum_signed += f;
  }
}


// Whether every contact block's force keeps its sign over tau0 .. tau_last (the tests above),
// with the live segments' modes at tau0 in w0_.q, w0_.p and bounds on their end rows' modal part from
// then on in end_bound_. need_sums (window): the forces beside no groove are not tested
// (window splits the stretch at their crossings), an edge whose sign the bounds cannot fix
// is flagged in unsure_ instead of failing the test, and false when a mode has no closed-form
// sample sum. The
// bounds come from the modes at tau0 itself, never from an earlier sample's, so whether a stretch
// is taken depends on the phase and the stretch only, not on which samples were served before
// it (an observer keeping the series gets the sums of one that does not).
bool QuietSums::keeps_signs(double tau0, double tau_last, bool need_sums) {
  prepare();
  // Interior forces: for bounds, none crosses zero inside the stretch; the sums split the
  // stretch at their crossings instead (window).
  if (!need_sums && interior_.crossed(tau_last) != interior_.crossed(tau0)) return false;
  // The live segments' modes at tau0, and bounds on their end rows' modal part from then on.
  for (std::size_t sgi = 0; sgi < phase_.segments().size(); ++sgi) {
    const QuietPhase::GrooveRun& s = phase_.segments()[sgi];
    end_bound_[2 * sgi] = end_bound_[2 * sgi + 1] = 0.0;
    if (!(tau0 <= s.sample_dead_tau)) continue;
    const RunShape& d = *s.shape;
    for (int k = 0; need_sums && k < s.n; ++k)
      if (std::isnan(d.steps.sample_sum[k][0])) return false;  // no closed-form sum for this mode
    double* q = w0_.q.data() + s.first;
    double* p = w0_.p.data() + s.first;
    d.evolve(phase_.store().q0() + s.first, phase_.store().p0() + s.first, tau0, q, p);
    end_bound_[2 * sgi] = row_deviation_bound(d, 0, q, p);
    end_bound_[2 * sgi + 1] = row_deviation_bound(d, s.n - 1, q, p);
  }
  // Edge forces: the affine part keeps clear of the modes' reach, on the side it starts on, at
  // both ends of the stretch (so everywhere between).
  if (need_sums) unsure_.assign(phase_.edges().size(), 0);
  for (std::size_t k = 0; k < phase_.edges().size(); ++k) {
    const QuietPhase::Edge& e = phase_.edges()[k];
    const double reach = edge_reach(e);
    const double f0 = e.fa + e.fb * tau0, sg = f0 >= 0 ? 1.0 : -1.0;
    if (sg * f0 > reach && sg * (e.fa + e.fb * tau_last) > reach) continue;
    if (!need_sums) return false;
    unsure_[k] = 1;
  }
  return true;
}

double QuietSums::edge_reach(const QuietPhase::Edge& e) const {
  double reach = 0;
  for (int r = 0; r < e.nseg; ++r) reach += phase_.K_int() * end_bound_[2 * e.seg[r] + (e.row[r] == 0 ? 0 : 1)];
  return reach;
}

bool QuietSums::window(long k0, double dt, long n, double& sum_abs, double& sum_signed) {
  sum_abs = sum_signed = 0;
  if (n <= 0) return false;
  auto tau_of = [&](long k) { return static_cast<double>(k) * dt - phase_.t0(); };
  const double tau0 = tau_of(k0);
  if (!keeps_signs(tau0, tau_of(k0 + n - 1), true)) return false;
  // Each live segment's end rows summed over its live samples (those with tau <= sample_dead_tau,
  // as friction_sums counts them).
  for (std::size_t sgi = 0; sgi < phase_.segments().size(); ++sgi) {
    const QuietPhase::GrooveRun& s = phase_.segments()[sgi];
    end_dots_[2 * sgi] = end_dots_[2 * sgi + 1] = 0.0;
    if (!(tau0 <= s.sample_dead_tau)) continue;
    long live = n;
    while (live > 0 && !(tau_of(k0 + live - 1) <= s.sample_dead_tau)) --live;  // rare: dies in the stretch
    const RunShape& d = *s.shape;
    const double tau1 = tau_of(k0 + live);
    double* q1 = w1_.q.data() + s.first;
    double* p1 = w1_.p.data() + s.first;
    d.evolve(phase_.store().q0() + s.first, phase_.store().p0() + s.first, tau1, q1, p1);
    const double* q = w0_.q.data() + s.first;
    const double* p = w0_.p.data() + s.first;
    const double* first_row = d.row(0);
    const double* last_row = d.row(s.n - 1);
    double first = 0, last = 0;
    for (int k = 0; k < s.n; ++k) {
      const double Sq = d.steps.sample_sum[k][0] * (q[k] - q1[k]) + d.steps.sample_sum[k][1] * (p[k] - p1[k]);
      first += first_row[k] * Sq, last += last_row[k] * Sq;
    }
    end_dots_[2 * sgi] = first, end_dots_[2 * sgi + 1] = last;
  }
  // The affine parts: sum of the sample times, sum_j (k dt - t0) with the sum of k exact in
  // integers.
  auto sum_of_taus = [&](long k, long m) {
    const double mm = static_cast<double>(m);
    return dt * (0.5 * static_cast<double>(2 * k + m - 1) * mm) - mm * phase_.t0();
  };
  const double mm = static_cast<double>(n);
  const double st = sum_of_taus(k0, n);
  // The forces beside no groove: each crosses zero once, at a known time (CommonSlopeSum), so
  // the samples between two crossings are summed at once, a stretch without one in a single
  // piece (as before crossings split it).
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
  for (std::size_t k = 0; k < phase_.edges().size(); ++k) {
    if (unsure_[k]) continue;
    const QuietPhase::Edge& e = phase_.edges()[k];
    double f = e.fa * mm + e.fb * st;
    for (int r = 0; r < e.nseg; ++r) f += phase_.K_int() * end_dots_[2 * e.seg[r] + (e.row[r] == 0 ? 0 : 1)];
    sum_abs += e.fa + e.fb * tau0 >= 0 ? f : -f;  // every sample's sign (checked above)
    sum_signed += f;
  }
  unsure_sums(k0, dt, n, sum_abs, sum_signed);
  return true;
}

void QuietSums::unsure_sums(long k0, double dt, long n, double& sum_abs, double& sum_signed) {
  auto tau_of = [&](long k) { return static_cast<double>(k) * dt - phase_.t0(); };
  // The segments beside the flagged edges, each given a slot of 2 n values: its first and last
  // rows' modal parts at each sample.
  std::fill(slot_.begin(), slot_.end(), -1);
  int slots = 0;
  for (std::size_t k = 0; k < phase_.edges().size(); ++k)
    if (unsure_[k])
      for (int r = 0; r < phase_.edges()[k].nseg; ++r)
        if (slot_[phase_.edges()[k].seg[r]] < 0) slot_[phase_.edges()[k].seg[r]] = slots++;
  if (slots == 0) return;
  // Zero once the segment's modes are cut, as friction_sums cuts them; from the modes at the
  // first sample (keeps_signs' w0_.q, w0_.p) before.
  const std::size_t nn = static_cast<std::size_t>(n);
  row_values_.assign(2 * nn * static_cast<std::size_t>(slots), 0.0);
  const double tau0 = tau_of(k0);
  for (std::size_t sgi = 0; sgi < phase_.segments().size(); ++sgi) {
    const QuietPhase::GrooveRun& s = phase_.segments()[sgi];
    if (slot_[sgi] < 0 || !(tau0 <= s.sample_dead_tau)) continue;
    const RunShape& d = *s.shape;
    double* q = w1_.q.data() + s.first;  // window_sums is done with them: a working copy
    double* p = w1_.p.data() + s.first;
    std::copy(w0_.q.begin() + s.first, w0_.q.begin() + s.first + s.n, q);
    std::copy(w0_.p.begin() + s.first, w0_.p.begin() + s.first + s.n, p);
    double* first = row_values_.data() + 2 * nn * static_cast<std::size_t>(slot_[sgi]);
    double* last = first + n;
    for (long j = 0; j < n && tau_of(k0 + j) <= s.sample_dead_tau; ++j) {
      d.end_rows(q, first[j], last[j]);
      d.step_sample(q, p);
    }
  }
  for (std::size_t k = 0; k < phase_.edges().size(); ++k) {
    if (!unsure_[k]) continue;
    const QuietPhase::Edge& e = phase_.edges()[k];
    for (long j = 0; j < n; ++j) {
      double f = e.fa + e.fb * tau_of(k0 + j);
      for (int r = 0; r < e.nseg; ++r)
        f += phase_.K_int() * row_values_[2 * nn * static_cast<std::size_t>(slot_[e.seg[r]]) + (e.row[r] == 0 ? 0 : nn) +
                                  static_cast<std::size_t>(j)];
      sum_abs += std::fabs(f);
      sum_signed += f;
    }
  }
}

// Each sum is affine in tau up to the edges' modal parts, whose sizes edge_reach bounds: with
// every sign fixed, sum |f| = sum sign(f) f. The sums friction_sums forms round differently from
// the exact values, and the straight line between the ends rounds too; a margin of 1e-9 of the
// sums' size, millions of times their round-off, keeps the bound a bound.
bool QuietSums::envelope(long k0, double dt, long n, SampleStretch::Envelope& env) {
  if (n <= 0) return false;
  auto tau_of = [&](long k) { return static_cast<double>(k) * dt - phase_.t0(); };
  const double tau0 = tau_of(k0), tau1 = tau_of(k0 + n - 1);
  if (!keeps_signs(tau0, tau1, false)) return false;
  interior_.at(tau0, env.abs_first, env.signed_first);
  interior_.at(tau1, env.abs_last, env.signed_last);
  double reach = 0;
  for (const QuietPhase::Edge& e : phase_.edges()) {
    const double f0 = e.fa + e.fb * tau0, f1 = e.fa + e.fb * tau1, sg = f0 >= 0 ? 1.0 : -1.0;
    env.abs_first += sg * f0, env.abs_last += sg * f1;
    env.signed_first += f0, env.signed_last += f1;
    reach += edge_reach(e);
  }
  env.reach = reach + 1e-9 * (std::fabs(env.abs_first) + std::fabs(env.abs_last) + reach);
  return true;
}

}  // namespace sb::event_detail
