#pragma once
// How a run is integrated and how its coefficients are read off mu(t): the part of a scene that
// the integrators and observers need. Kept apart from scene.hpp so that they depend on what they
// use, not on the whole scene (surface, material, scene files).
#include <string>

namespace sb {

enum class Method { RK4, Event };
std::string method_name(Method m);
Method parse_method(const std::string& text);  // throws InputError("method")

// How the event method moves the runs that something slides in: by their exact modes, or by
// Dormand-Prince 5(4) steps under the tolerance (a reference for the exact stepper, and its
// fallback on runs longer than exact_max_run).
enum class Stepper { Exact, Dopri5 };

// The event method's defaults, shared by RunControl and EventDriven: the longest mobile run and
// the longest ringing groove-only run propagated by their modes, and the exact stepper's
// longest run (paper/choices.md, Integration).
inline constexpr int kDefaultModalMaxRun = 2;
inline constexpr int kDefaultModalMaxGroove = 64;
// The longest modal_max_groove accepted: a groove shape of n blocks holds 2 n^2 doubles.
inline constexpr int kLongestModalGroove = 1024;
inline constexpr int kDefaultExactMaxRun = 128;

std::string stepper_name(Stepper s);
Stepper parse_stepper(const std::string& text);  // throws InputError("stepper")

// How the macroscopic coefficients are read off mu(t). See paper/choices.md.
struct ExtractionRules {
  // Where the loading phase ends; mu_s is the largest mu(t) reached up to that moment. The
  // paper's "first load peak" leaves this open, so a family of readings is offered, each a
  // property of one trajectory (paper/choices.md, "Reading mu_s").
  //  AllSlipped: when every contact block has slid at least once, i.e. the whole surface has
  //    moved. Precursor slips of a few blocks, however large their mu drop on a surface with
  //    few contacts, do not end it.
  //  Drop: when mu(t) first falls `peak_drop` below its running maximum. Simple, but on
  //    surfaces with few contact blocks a precursor of 2-5 blocks already drops mu by 0.05.
  //  The SlidOr* rules end it at AllSlipped's moment or earlier, at the first sample where
  //    SlidOrDrop:          mu(t) < running max - peak_drop;
  //    SlidOrRelativeDrop:  mu(t) < (1 - peak_drop_fraction) running max;
  //    SlidOrEvent:         one slip event has moved at least peak_event_fraction of the
  //                         contact blocks (a large detachment, not a precursor).
  // The default, SlidOrDrop with a drop of 0.1, is the one the cross-validation over the three
  // appendix tables chose by the criterion stated before the comparison (paper/choices.md).
  enum class PeakRule { AllSlipped, Drop, SlidOrDrop, SlidOrRelativeDrop, SlidOrEvent };
  PeakRule peak_rule = PeakRule::SlidOrDrop;
  double peak_drop = 0.1;
  double peak_drop_fraction = 0.1;
  double peak_event_fraction = 0.5;
  // mu_d averages mu(t) from (first macroscopic slip + skip) to the end of the run,
  // skip in units of the loading time t0 (see RunControl).
  double mu_d_skip_t0 = 0.25;
};
std::string peak_rule_name(ExtractionRules::PeakRule r);
ExtractionRules::PeakRule parse_peak_rule(const std::string& text);  // throws InputError("peak_rule")

struct RunControl {
  // The event method by default: it locates every stick/slip switch instead of resolving it to
  // one step, and is 7 to 600 times faster than RK4 at the paper's step (README, Cost). RK4 is
  // kept, by name, as the paper's own method.
  Method method = Method::Event;
  double dt_s = 1e-7;        // RK4 step (the paper's 1e-4 ms)
  // event method: relative error tolerance. The default is the loosest decade tolerance whose
  // first-peak error (accuracy_cost: worst of 3 seeds against tol 1e-12) stays below a tenth of
  // the smallest mu_s standard error the reproduction compares (1.4e-3): 5.2e-5 at 1e-8, 1.9e-3
  // at 1e-7 (paper/choices.md, Integration).
  double tol = 1e-8;
  // event method: mobile runs of up to this many blocks are propagated exactly by their modes
  // rather than stepped once they have moved for two periods of the chain's fastest mode with
  // nothing in or beside them switching (ActiveSet::promote_runs; 0: step every run). The
  // default is the measured optimum (bench_methods, paper/choices.md).
  int modal_max_run = kDefaultModalMaxRun;
  // event method: ringing groove-only runs (no contact block, so no stop to search for; only
  // their stuck neighbours' crossings) of up to this many blocks are propagated by their modes
  // too. Separate from modal_max_run because a groove run has no stop events: it pays off up to
  // much longer runs (bench_methods, modal_groove/*): 64 on the paper's chains (paper/choices.md,
  // Integration); up to 1024 allowed, for chains so fine that stepping a long groove costs more
  // than its O(n^2) projections (the size-scaling study's).
  int modal_max_groove = kDefaultModalMaxGroove;
  // event method: the stepped runs move by their modes (Stepper::Exact) while none is longer than
  // exact_max_run blocks, and by Dormand-Prince steps otherwise (a run's projection costs O(n^2)
  // at each switch); Stepper::Dopri5 always steps them. The default, 128, is the fastest over
  // the criterion's four scenes (paper/choices.md, Integration).
  Stepper stepper = Stepper::Exact;
  int exact_max_run = kDefaultExactMaxRun;
  // Run length in units of t0 = (mu_s)_m F_n / (K_s v), the time the slider needs to load an
  // average block to its threshold. Scaling with t0 keeps the number of stick-slip cycles the
  // same when the contact fraction (hence F_n) changes. duration_s > 0 overrides.
  double duration_t0 = 4.0;
  double duration_s = 0.0;
  // Spacing of mu(t) samples. mu_s is a maximum over them, so a coarser grid reads it lower:
  // 1e-2 ms moved some appendix rows by half their combined error against 1e-3 ms, which the
  // criterion fixed beforehand does not allow (paper/choices.md, "Reading mu_s").
  double sample_dt_s = 1e-6;
  bool stop_after_mu_s = false;  // a scene that only needs mu_s stops at the first slip
};

}  // namespace sb
