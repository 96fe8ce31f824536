#pragma once
// Locates stick/slip events inside a step of the exact stepper (linear/span_modes.hpp).
//
// Event functions, positive while nothing happens:
//   sliding block in a stepped run:   g = dir v + eps_v  (it stops when dir v falls below -eps_v,
//                                     the round-off margin of the modal runs, modal_runs.hpp)
//   stuck block beside a stepped run: g = f_static - |F|  (F its driving force)
// Each is screened over a step [0, h] in three stages, cheapest first:
//   * two tests that provably pass no root, from g at both ends of the step and bounds on its
//     derivatives from the rows' (SpanModes::row_bound): the chord, g >= min(g_0, g_h) - M2 h^2 / 8
//     with M2 >= |g''|; where that fails, the cubic Hermite interpolant of g and g' at the ends,
//     which g leaves by at most M4 h^4 / 384 (M4 >= |g''''|), so its minimum on the step less
//     that is a lower bound (far tighter: a step turns the fastest mode by 0.75 rad). A
//     stuck block beside a modal run takes that run's row as its affine path widened by its
//     modal bound (ModalRuns::amplitude), which holds at every time;
//   * where that test fails, g as the Taylor polynomial of its rows about the step's start
//     (exact to round-off over a step, SpanModes::row_taylor), whose first root in [0, h] is
//     isolated in the Bernstein basis (bernstein.hpp) and refined to round-off in t
//     (first_root.hpp). A stuck block's |F| is searched as F reaching +f_static and -f_static.
// The earliest root, and every block whose root lies within `window` (a fraction of the step)
// of it, make the step's event, as for the Dormand-Prince search (event_search.hpp).
// The functions are kept per clock (SpanScreen::Watch): the runs that step together, from their
// own time t0, which may lie before the chain's.
#include <cstdint>
#include <vector>

#include "springblock/integrate/events/active_set.hpp"
#include "springblock/integrate/numerics/bernstein.hpp"
#include "springblock/integrate/linear/span_modes.hpp"
#include "springblock/model.hpp"
#include "springblock/state.hpp"

namespace sb::event_detail {

class SpanScreen {
  static constexpr int D = SpanModes::kDegree;
  enum Side : std::uint8_t { kNone, kSpan, kSettled, kModal, kFixed };
  // What a neighbour of a stuck block is to the screen, and the store's record holding a settled
  // or modal one (-1: none).
  struct Border {
    Side side = kNone;
    std::int64_t run = -1;
    bool operator==(const Border&) const = default;
  };
  struct Value {
    double g = 0, d = 0;  // g, and its slope where known
    bool known = false;   // d is known
  };
  struct Fn {
    int block;
    std::int8_t dir;  // a sliding block's direction; 0 for a stuck block's threshold
    Border border[2];  // a stuck block's neighbours (left, right)
    Value start, end;  // g (or its cheap lower bound) at the step's start and end, and its slope
    double M2, M4;    // bounds on |g''| and |g''''| (of the part that is not a modal bound)
    double spread;    // the spring to a modal neighbour times its bound (0 without one)
    double root = 0;  // its first root in the step last located (+inf if none)
  };

 public:
  explicit SpanScreen(const Chain& c);

  // The event functions of the runs on one clock, and the blocks of its last event.
  class Watch {
   public:
    const std::vector<int>& hits() const { return hits_; }

   private:
    friend class SpanScreen;
    std::vector<Fn> fns_;
    std::vector<int> hits_;
  };

  // The event functions of runs k0 .. k1 - 1 of `spans` and their values at s.t, which is their
  // current time (after they were projected or brought there).
  void rebuild(const Chain& c, const State& s, const SpanModes& spans, const ActiveSet& active, int k0, int k1,
               Watch& w) const;
  // After spans.advance(h) of w's runs from their time t0: the earliest event in (0, h] as an
  // offset from t0, or a value > h if none; w.hits() then lists its blocks.
  double locate(const Chain& c, const State& s, const SpanModes& spans, ActiveSet& active, Watch& w, double t0,
                double h, double window = 1e-12);
  // The step was taken: each function's value at its end is its value at the next start.
  static void accept(Watch& w);
  // Whether w's functions are still those rebuild would make now: each block's direction, and
  // a stuck block's neighbours' kinds and records (a check for the tests, ClockAudit).
  bool current(const State& s, const SpanModes& spans, const ActiveSet& active, const Watch& w) const;

 private:
  // g's cheap form at the step's start (end = false) or end, time t, and its slope (slope = true).
  double cheap(const Chain& c, const State& s, const SpanModes& spans, const ActiveSet& active, const Fn& f,
               double t, bool end, bool slope = false) const;
  // The first root of f in [0, h] from its polynomial about t0 (+inf if none, or if it is surely
  // later than `after`: such a root is not refined).
  double exact_root(const Chain& c, const State& s, const SpanModes& spans, ActiveSet& active, const Fn& f,
                    double t0, double h, double after);
  double poly_root(const double* g, double t0, double h, double after) const;
  Border border(const SpanModes& spans, const ActiveSet& active, int j) const;

  double v_, eps_v_;
  int N_;
  BernsteinRoots<D> bern_;
};

}  // namespace sb::event_detail
