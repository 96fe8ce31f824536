#include "springblock/design/target.hpp"

#include <cmath>

#include "springblock/errors.hpp"
#include "springblock/units.hpp"

namespace sb::design {
namespace {

// Friction coefficients and their ratio of any sensible surface lie far inside this range; a
// value outside is a typo (a percentage, a sign).
constexpr double kMaxValue = 10.0;

double value(const std::string& field, const std::string& text, const std::string& whole) {
  double x = 0;
  try {
    x = parse_quantity(text, Dimension::Dimensionless, field);
  } catch (const InputError&) {
    throw InputError(field, "'" + whole + "' is not a number; expected X, LO:HI, >=X or <=X");
  }
  if (!(x >= 0 && x <= kMaxValue))
    throw InputError(field, "'" + whole + "' is outside the allowed range [0, " + printed(kMaxValue) + "]");
  return x;
}

}  // namespace

std::string quantity_name(Quantity q) {
  switch (q) {
    case Quantity::MuS: return "mu_s";
    case Quantity::MuD: return "mu_d";
    case Quantity::Ratio: return "ratio";
  }
  return "?";
}

std::string Interval::text() const {
  if (!set) return "any";
  if (lo == hi) return printed(lo);
  // Built by appending: GCC 12 warns falsely (-Wrestrict) on "literal" + std::string.
  if (std::isinf(lo)) return std::string("<= ").append(printed(hi));
  if (std::isinf(hi)) return std::string(">= ").append(printed(lo));
  return std::string("[").append(printed(lo)).append(", ").append(printed(hi)).append("]");
}

Interval parse_interval(const std::string& field, const std::string& text) {
  Interval in;
  in.set = true;
  if (text.rfind(">=", 0) == 0) {
    in.lo = value(field, text.substr(2), text);
  } else if (text.rfind("<=", 0) == 0) {
    in.hi = value(field, text.substr(2), text);
  } else if (const auto colon = text.find(':'); colon != std::string::npos) {
    in.lo = value(field, text.substr(0, colon), text);
    in.hi = value(field, text.substr(colon + 1), text);
    if (in.lo > in.hi) throw InputError(field, "'" + text + "': LO must not exceed HI");
  } else {
    in.lo = in.hi = value(field, text, text);
  }
  return in;
}

double distance(const Interval& in, double x) {
  if (!std::isfinite(x)) return std::numeric_limits<double>::infinity();
  if (x < in.lo) return in.lo - x;
  if (x > in.hi) return x - in.hi;
  return 0;
}

bool meets(const Interval& in, const Statistic& s) {
  if (!in.set) return true;
  if (s.n == 0 || !std::isfinite(s.mean)) return false;
  const double half = kMeetsZ * (std::isfinite(s.sem) ? s.sem : 0.0);
  return s.mean + half >= in.lo && s.mean - half <= in.hi;
}

const Interval& Target::of(Quantity q) const {
  switch (q) {
    case Quantity::MuS: return mu_s;
    case Quantity::MuD: return mu_d;
    case Quantity::Ratio: return ratio;
  }
  return mu_s;
}

bool Target::needs_mu_d() const {
  return mu_d.set || ratio.set || (goal != Goal::None && objective != Quantity::MuS);
}

bool Target::any() const { return mu_s.set || mu_d.set || ratio.set || goal != Goal::None; }

double score(const Target& t, double mu_s, double mu_d) {
  const double ratio = mu_s / mu_d;
  double d = 0;
  if (t.mu_s.set) d += distance(t.mu_s, mu_s);
  if (t.mu_d.set) d += distance(t.mu_d, mu_d);
  if (t.ratio.set) d += distance(t.ratio, ratio);
  if (!std::isfinite(d)) return std::numeric_limits<double>::infinity();
  if (t.goal == Goal::None) return d;
  const double x = t.objective == Quantity::MuS ? mu_s : t.objective == Quantity::MuD ? mu_d : ratio;
  if (!std::isfinite(x)) return std::numeric_limits<double>::infinity();
  // Objectives lie in [0, kMaxValue]: an outside candidate's 2 kMaxValue + d ranks behind them all.
  const double outside = d > 0 ? 2 * kMaxValue + d : 0;
  return outside + (t.goal == Goal::Minimise ? x : -x);
}

}  // namespace sb::design
