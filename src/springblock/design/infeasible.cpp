// infeasible_reason (report.hpp): why a target was not met, from what the search measured.
#include <algorithm>
#include <cmath>
#include <limits>

#include "springblock/design/report.hpp"
#include "springblock/errors.hpp"

namespace sb::design {
namespace {

struct Reach {
  double lo = std::numeric_limits<double>::infinity(), hi = -std::numeric_limits<double>::infinity();
  int lo_at = -1, hi_at = -1, measured = 0;
};

// The range of a quantity's screening means over the simulated candidates.
Reach reach(const Outcome& o, Quantity q) {
  Reach r;
  for (std::size_t k = 0; k < o.search.estimates.size(); ++k) {
    const auto s = o.search.estimates[k].stat(q);
    if (s.n == 0) continue;
    ++r.measured;
    if (s.mean < r.lo) r.lo = s.mean, r.lo_at = static_cast<int>(k);
    if (s.mean > r.hi) r.hi = s.mean, r.hi_at = static_cast<int>(k);
  }
  return r;
}

std::string out_of_reach(const Outcome& o, Quantity q, const Interval& in) {
  const Reach r = reach(o, q);
  const std::string name = quantity_name(q);
  const std::string over = " over the " + std::to_string(r.measured) + " candidates that measured it";
  if (r.measured == 0) return name + " was measured on no candidate";
  if (in.hi < r.lo)
    return name + " " + in.text() + " is below the smallest " + name + " reached, " + printed(r.lo) + " (" +
           o.candidates.kept[r.lo_at].spec.text() + ")" + over;
  if (in.lo > r.hi)
    return name + " " + in.text() + " is above the largest " + name + " reached, " + printed(r.hi) + " (" +
           o.candidates.kept[r.hi_at].spec.text() + ")" + over;
  return "";
}

std::string excluded(const Query& q, const Outcome& o) {
  const auto& c = o.candidates;
  std::string s;
  if (o.classes_used) {
    int pruned = 0;
    double lo = 1e300, hi = -1e300;
    for (const auto& k : o.classes.classes) {
      if (!k.kept) pruned += k.members;
      if (k.mu_d.n > 0) lo = std::min(lo, k.mu_d.mean), hi = std::max(hi, k.mu_d.mean);
    }
    if (pruned > 0)
      s += "; " + std::to_string(pruned) + " candidates were pruned by contact-fraction class (their class's mu_d, " +
           "between " + printed(lo) + " and " + printed(hi) + " over the classes, lies more than " +
           printed(q.classes.margin) + " from mu_d " + q.target.mu_d.text() + "; mu_d is set by the contact fraction, "
           "paper Sec. III)";
  }
  if (c.dropped_contact > 0)
    s += "; the contact-fraction constraint [" + printed(q.space.min_contact) + ", " + printed(q.space.max_contact) +
         "] excluded " + std::to_string(c.dropped_contact) + " of " + std::to_string(c.generated) +
         " candidates (the family's bounds span contact fractions " + printed(c.contact_lo) + " to " +
         printed(c.contact_hi) + "; fewer contacts raise mu_s and mu_d on large grooves, paper Sec. III and table tpat0)";
  if (c.dropped_feature > 0)
    s += "; the smallest-feature constraint (" + std::to_string(q.space.min_feature) + " blocks) excluded " +
         std::to_string(c.dropped_feature) + " (small features keep mu_s near the smooth surface's)";
  return s;
}

}  // namespace

std::string infeasible_reason(const Query& q, const Outcome& o) {
  if (o.feasible) return "";
  if (o.candidates.kept.empty() || o.search.estimates.empty())
    return "no candidate is left in the design space" + excluded(q, o);
  std::string why;
  for (Quantity k : {Quantity::MuS, Quantity::MuD, Quantity::Ratio}) {
    if (!q.target.of(k).set) continue;
    const std::string part = out_of_reach(o, k, q.target.of(k));
    if (!part.empty()) why += (why.empty() ? "" : "; ") + part;
  }
  if (why.empty())
    why = "each target interval lies within the range the candidates reached, but no verified candidate met them all "
          "within 2 standard errors of its fresh estimate (the combination lies between the candidates of this "
          "space, or the interval is narrower than the estimates' uncertainty)";
  return why + excluded(q, o);
}

}  // namespace sb::design
