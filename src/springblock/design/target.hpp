#pragma once
// What a design query asks for: an interval (a point is an interval of width 0) for mu_s, mu_d
// and their ratio mu_s/mu_d, and optionally a quantity to minimise or maximise subject to them.
// One rule decides whether an estimate "meets" an interval (meets(), stated in
// paper/choices.md, "Inverse design"), so the search, the verification and the report agree.
#include <limits>
#include <string>

#include "springblock/ensemble.hpp"

namespace sb::design {

enum class Quantity { MuS, MuD, Ratio };
std::string quantity_name(Quantity q);  // "mu_s", "mu_d", "ratio"

struct Interval {
  double lo = -std::numeric_limits<double>::infinity();
  double hi = std::numeric_limits<double>::infinity();
  bool set = false;
  std::string text() const;  // "0.65", "[0.6, 0.7]", ">= 0.52", "any"
};

// "0.65" (a point), "0.6:0.7" (closed interval), ">=0.52" or "<=0.5" (half lines). Throws
// InputError(field) naming the accepted forms and the allowed range [0, 10].
Interval parse_interval(const std::string& field, const std::string& text);

// How far x lies outside the interval (0 inside); +infinity for a non-finite x.
double distance(const Interval& in, double x);

// The rule "meets the target within its uncertainty": the estimate's two-standard-error interval
// [mean - 2 SEM, mean + 2 SEM] overlaps the target interval. For a point target this is
// |mean - target| <= 2 SEM, about a 95% two-sided test that the true value could be the target.
// An estimate with no defined value (n = 0) never meets. kMeetsZ is the 2.
constexpr double kMeetsZ = 2.0;
bool meets(const Interval& in, const Statistic& s);

enum class Goal { None, Minimise, Maximise };

struct Target {
  Interval mu_s, mu_d, ratio;
  Goal goal = Goal::None;
  Quantity objective = Quantity::MuS;  // with goal != None
  const Interval& of(Quantity q) const;
  // Whether any part of the query needs mu_d (a mu_d or ratio interval, or an objective on them):
  // then no stage may stop at the first slip.
  bool needs_mu_d() const;
  bool any() const;  // an interval or a goal is set
};

// The ranking score of an estimate (lower is better): the summed distance to the intervals,
// plus, with a goal, the objective (signed so that lower is better) after a penalty weight that
// puts every candidate outside the intervals behind every candidate inside them.
double score(const Target& t, double mu_s, double mu_d);

}  // namespace sb::design
