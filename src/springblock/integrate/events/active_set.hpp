#pragma once
// Which blocks the stepper has to integrate while something slides, and the exact treatment of
// everything else.
//
// Stuck contact blocks do not move, so during a phase (no switch) they cut the chain into
// independent pieces: each maximal run of mobile blocks (grooves and sliding blocks) between two
// stuck blocks or a chain end is its own linear system. A run is
//   * Active   if it holds a sliding block: stepped by Dormand-Prince;
//   * Ringing  if it is grooves only and still carries a transient: stepped too (its own blocks
//              only, so a groove far from the slip costs n, not N);
//   * Settled  if it is grooves only and its transient is below the tolerance (see below):
//              u = A + B t exactly, the affine particular solution (a run store record
//              without modes, run_store.hpp);
//   * Modal    if it is not settled and at most modal_max_run blocks long (modal_max_groove
//              for a grooves-only run, which has no stop to search): propagated exactly
//              by its modes with no time step (modal_runs.hpp), its stops and its stuck
//              neighbours' crossings found by EdgeMarch. A creeping block (mu_d clipped to
//              mu_s) that never stops then costs nothing between its neighbours' switches.
//              A short run holding a contact block becomes modal only once it has moved for
//              promote_age() with nothing in or beside it switching (promote_runs): most
//              slips of one or two blocks end sooner, and a few steps of the stepper cost less
//              than the modal searches (the stop and both neighbours' crossings, each marched
//              up to the next event) that every switch beside such a run would renew. What
//              outlasts that age is creeping, which the modal searches skip over.
// A stuck block with no stepped or modal neighbour feels an affine force a + b t, so its
// threshold crossing is closed form; one beside a modal run (and no stepped one) has an exact
// crossing from the modes; only stuck blocks next to a stepped run need the step's dense output.
// The cost of a step is therefore proportional to the blocks that actually move, which is what
// makes a precursor of a few blocks in a 360-block chain cheap.
//
// A settled run drops a transient smaller than 0.1 times the stepper's absolute tolerance (in u
// and in v); it keeps decaying, so the error committed is below one step's.
// With settle_grooves = false no run is ever settled or modal (the reference mode used by the
// tests). modal_max_run = modal_max_groove = 0 turns modal runs off.
#include <cstdint>
#include <limits>
#include <queue>
#include <utility>
#include <vector>

#include "springblock/integrate/block_range.hpp"
#include "springblock/integrate/events/event_queue.hpp"
#include "springblock/integrate/events/known_forces.hpp"
#include "springblock/integrate/linear/modal_runs.hpp"
#include "springblock/integrate/linear/run_store.hpp"
#include "springblock/model.hpp"
#include "springblock/state.hpp"

namespace sb::event_detail {

class ActiveSet {
 public:
  // The settled and modal runs' records live in store.
  ActiveSet(const Chain& c, RunStore& store, bool settle_grooves, double atol_u, double atol_v, int modal_max_run = 0,
            int modal_max_groove = 0, double t_end = std::numeric_limits<double>::infinity());

  // Classify every run at s.t from scratch: the first classification of a new set (the start of
  // a run).
  void rebuild(const Chain& c, const State& s);
  // After a switch at s.t (every settled and modal run the switch reads already materialised in
  // s): the classification brought up to date where it can have changed, the same as a
  // classification of every run that remembers the previous one would make
  // (active_set_update.cpp). touched: per block, 1 if it switched since the last call, and
  // touched_list the same blocks (Switching::touched(), touched_list()).
  void update(const Chain& c, const State& s, const std::uint8_t* touched, const std::vector<int>& touched_list);

  // What the last classification (rebuild or update) may have changed: the blocks whose event
  // time it renewed, in block order (every block after a rebuild). A block's own kind or run, or
  // a neighbour's, can change only where it is listed (collect_candidates). And the number of
  // classifications so far, to tell whether the list is new.
  const std::vector<int>& renewed() const { return work_.cand; }
  std::int64_t classifications() const { return work_.classifications; }

  // Runs stepped by Dormand-Prince, in block order.
  const std::vector<BlockRange>& stepped() const { return list_.stepped; }
  // Blocks whose events the step's dense output must be searched for: every sliding block and
  // every stuck block next to a stepped run (K_int > 0).
  const std::vector<int>& watched() const { return list_.watched; }

  enum Kind : std::uint8_t { kStuck = 0, kStepped = 1, kSettled = 2, kModal = 3 };
  Kind kind(int i) const { return static_cast<Kind>(kind_[i]); }
  // The affine path A + B t of a settled or modal block: a settled block's exact u and v, a
  // modal block's u less its modes.
  double path_u(int i, double t) const { return store_.path_u(i, t); }
  double path_slope(int i) const { return store_.B(i); }
  // Displacement of a block in a modal run at time t.
  double modal_u(int i, double t) const { return modal_.u(i, t); }
  // Its Taylor polynomial about t (ModalRuns::row_taylor).
  void modal_taylor(int i, double t, int deg, double* c) { modal_.row_taylor(i, t, deg, c); }
  // A bound on its deviation from its path (ModalRuns::amplitude).
  double modal_amplitude(int i) const { return modal_.amplitude(i); }
  // Block i has a run of kind k beside it (K_int > 0).
  bool beside(int i, Kind k) const;

  // Write the settled and modal runs' exact u, v at time t into u, v (at_sample: t is a sample
  // time; ends_only: grooves-only modal runs write their end rows only, see
  // ModalRuns::materialise).
  void materialise(double t, double* u, double* v, bool at_sample = false, bool ends_only = false);
  // The same for only what a switch of the given blocks reads: each block and its two
  // neighbours, and the whole modal run any of them is in (it may be projected afresh).
  // Between switches the u, v of settled and modal blocks in the state are not kept current:
  // nothing reads them there (the stepper reads stepped runs and their stuck borders, the event
  // searches use path_u / modal_u); the loop materialises everything at samples, before a
  // quiet phase and at the end of the run.
  void materialise_near(double t, double* u, double* v, const std::vector<int>& blocks);
  // Each contact block's friction force as its events were found from it (KnownForces), for a
  // sample that sums the forces (Observer::sample_active); delivered() once the sample took them.
  const KnownForces& forces() const { return forces_; }
  void forces_delivered() { forces_.delivered(); }
  // For such a sample: the positions the live blocks' forces read, their settled and modal
  // neighbours' (the modal runs' end rows as materialise writes them at a sample; the stepped
  // runs are the stepper's to write).
  void materialise_live(double t, double* u, double* v);
  // The settle scales: a grooves-only run's transient below these (in u and v) is dropped.
  double settle_eps_u() const { return rules_.eps_u; }
  double settle_eps_v() const { return rules_.eps_v; }

  // After an accepted step at s.t: ringing runs whose transient has died become settled and
  // leave the stepped set. Returns true when the stepped set changed.
  bool retire_settled(const Chain& c, const State& s);
  // Stepped runs of at most modal_max_run blocks holding a contact block, formed at least
  // promote_age() before s.t, become modal (projected from s.u, s.v, which must hold their state
  // at s.t), and the events of their blocks and stuck neighbours are searched. Returns true when
  // the stepped set changed. The earliest time one is due (+inf if none): next_promotion().
  bool promote_runs(const Chain& c, const State& s);
  double next_promotion() const { return list_.next_promotion; }
  // Two periods of the chain's fastest mode, 4 pi / sqrt((K_s + 4 K_int) / m): twice the
  // longest slip a run of one or two blocks makes undisturbed (half a period of its slowest
  // mode, at most one period of the fastest). Fixed before it was measured (paper/choices.md).
  double promote_age() const { return rules_.promote_age; }

  // The earliest closed-form or modal event; with recheck set it is not an event: a modal
  // search was cut off there, call recheck() at its time.
  using Next = EventQueue::Next;
  Next next_crossing() const { return events_.next(); }
  double next_real() const { return events_.next_real(); }  // the earliest of them not a recheck
  // At next_crossing().t with recheck set: continue that block's search from s.t.
  void recheck(const Chain& c, const State& s);

 private:
  struct Run {
    BlockRange span;
    Kind kind;       // kStepped (active or ringing), kSettled or kModal
    bool grooves;    // grooves only (never holds a contact block)
    double formed;   // when it was found: nothing in or beside it has switched since
  };
  // Whether groove run r is within the settle scales of its affine path at s.t (the path formed
  // from the shape's pieces and the stuck ends' positions, as a settled record would hold it).
  bool settled_now(const State& s, BlockRange r) const;
  // The maximal runs of mobile blocks in [lo, hi) (whose borders are stuck or the chain's ends),
  // appended to out in block order.
  void find_runs(const Chain& c, const State& s, int lo, int hi, std::vector<Run>& out) const;
  // The kind of run r at s.t, given the previous classification in kind_ and modal_.
  Kind classify(const Run& r, const State& s, const std::uint8_t* touched);
  // Set run r's kind in kind_ (its blocks) and list_.live; a run that becomes modal is registered,
  // projected afresh at s.t (prev_.fresh), and a settled one gets its record on its path. The
  // caller drops a modal run that stops being one (drop_old).
  void assign(const Chain& c, const State& s, Run& r, Kind kind);
  // update()'s steps (active_set_update.cpp); rebuild() renews the whole chain as one region.
  void find_regions(const Chain& c, const State& s, const std::vector<int>& touched_list);
  void renew_region(const Chain& c, const State& s, const std::uint8_t* touched, BlockRange region);
  void retime_grooves(const Chain& c, const State& s, const std::uint8_t* touched);
  void collect_candidates(const State& s, const std::uint8_t* touched);
  // The new event times of the blocks in work_.cand (every contact block's when all is set), then
  // the previous classification is forgotten (prev_.dir, prev_.kind where it changed).
  void update_events(const Chain& c, const State& s, const std::uint8_t* touched, bool all);
  // Block i (or nothing, outside the chain) switched since the last classification.
  bool switched(const State& s, const std::uint8_t* touched, int i) const;
  // Nothing in r or beside it switched.
  bool untouched(const State& s, const std::uint8_t* touched, BlockRange r) const;
  // Fill list_.stepped and list_.watched from runs_.
  void list_stepped(const State& s);
  // After run r changed kind with time (settled, or promoted to modal): its stuck contact
  // borders without an event time get one, closed form or queued for a modal search (work_.pending).
  void renew_borders(const Chain& c, const State& s, BlockRange r);
  // Run r leaves the classification: its modal run or settled record is let go.
  void drop_old(const Run& r);
  // Entry e of list_.settling still names a modal grooves-only run.
  bool settling(const std::pair<double, int>& e) const;
  // The run starting at block lo (one of runs_), sought from a cursor (an index into runs_ at or
  // before it, moved to it) for increasing lo: O(1) when the runs sought lie close together, as
  // the stepped runs of a smooth chain do, O(log gap) otherwise.
  Run& seek(std::size_t& cursor, int lo);
  // The event time of stuck block i when it needs no modal search (watched: none here;
  // otherwise closed form). Returns false if it borders a modal run and no stepped one (search it
  // instead).
  bool refresh_stuck(const Chain& c, const State& s, int i);
  bool any_modal() const { return rules_.modal_max > 0 || rules_.modal_max_groove > 0; }
  // Modal event search of block i up to limit (stop if sliding, threshold crossing if stuck).
  void search_modal(const Chain& c, const State& s, int i, double limit);
  // How far a modal search of block i need go: the earliest real event that can make it stale.
  double local_limit(int i) const;
  // The searches in work_.pending, after the event queue's refresh (active_set_events.cpp).
  void finish_events(const Chain& c, const State& s);

  // What the classification follows, fixed for the run.
  struct Rules {
    double K_int;
    bool settle_grooves;
    int modal_max;         // longest modal run holding a contact block
    int modal_max_groove;  // longest modal grooves-only run
    double promote_age;    // promote_age()
    double eps_u, eps_v;   // the settle scales
    double t_end;
  };
  // s.dir and kind_ at the previous classification. Between classifications they equal s.dir and
  // kind_ (retire_settled keeps kind along), so only the blocks a classification changes differ
  // while it runs. And the runs projected afresh at this classification: per block, and the runs
  // (to clear the marks at the next one).
  struct Previous {
    std::vector<std::int8_t> dir;
    std::vector<std::uint8_t> kind;
    std::vector<std::uint8_t> fresh;
    std::vector<BlockRange> fresh_runs;
  };
  // What list_stepped finds: the stepped runs, the blocks whose events a step searches, the
  // runs_ indices of stepped grooves-only runs, the earliest time a short run is due promotion.
  struct Listing {
    std::vector<BlockRange> stepped;
    std::vector<int> watched;
    std::vector<int> ringing;
    // First blocks of the stepped runs, in block order: list_stepped, retime_grooves and
    // promote_runs pass over these, not over every run.
    std::vector<int> live;
    std::vector<int> live_grooves;  // those of them that are grooves only (ringing)
    // The modal grooves-only runs by the time their transient is gone (settled_after, first
    // block), earliest on top: outside the renewed regions such a run changes kind only then, so
    // retime_grooves visits those due. An entry whose run has gone or was projected again is stale
    // (its block no longer starts a modal run with that time) and is skipped.
    std::priority_queue<std::pair<double, int>, std::vector<std::pair<double, int>>, std::greater<>> settling;
    double next_promotion = std::numeric_limits<double>::infinity();
  };
  // update()'s work lists.
  struct Work {
    std::vector<int> pending;         // blocks whose modal search is due
    std::vector<int> done;            // materialise_near: modal and settled runs written (first blocks)
    std::vector<int> cand;            // blocks whose event time may have changed
    std::vector<int> switched;        // the switched blocks in block order
    std::vector<BlockRange> regions;  // the stretches renewed, and the runs retimed, in block order
    std::vector<Run> found;           // the runs found in one region
    std::vector<int> visit;           // a copy of list_.live to walk while assign() edits it
    std::vector<std::pair<double, int>> due;  // retime_grooves: settling entries taken off
    std::int64_t classifications = 0;         // rebuilds and updates so far (renewed())
  };
  int N() const { return static_cast<int>(kind_.size()); }

  Rules rules_;
  ModalRuns modal_;
  Previous prev_;
  std::vector<std::uint8_t> kind_;
  std::vector<Run> runs_;
  Listing list_;
  RunStore& store_;    // the settled and modal runs' records
  EventQueue events_;  // per contact block: next closed-form or modal event (inf if none / watched)
  KnownForces forces_;  // per contact block: its force as the events were found from it
  Work work_;
};

}  // namespace sb::event_detail
