#include "sweep_run.hpp"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <map>

#include "shell/exit_codes.hpp"
#include "shell/interrupt.hpp"
#include "shell/output.hpp"
#include "shell/progress.hpp"
#include "springblock/errors.hpp"
#include "springblock/io.hpp"
#include "springblock/sweep/checkpoint.hpp"
#include "springblock/sweep/streamed_results.hpp"
#include "springblock/sweep/units.hpp"
#include "scheduler_choice.hpp"
#include "sweep_files.hpp"

namespace sb::app {
namespace {

using Clock = std::chrono::steady_clock;

std::string unit_name(const std::vector<sweep::Unit>& units, int id) {
  return std::to_string(id) + " (scene " + std::to_string(units[id].scene) + " rep " + std::to_string(units[id].rep) + ")";
}

// "rank 1: 3 (scene 1 rep 0), 7 (...); rank 2: ..." for units in flight or lost.
template <class List>
std::string by_rank(const List& list, const std::vector<sweep::Unit>& units) {
  std::map<int, std::string> per_rank;
  for (const auto& u : list) {
    auto& s = per_rank[u.rank];
    s += (s.empty() ? "" : ", ") + unit_name(units, u.unit_id());
  }
  std::string out;
  for (auto& [rank, s] : per_rank) out += (out.empty() ? "" : "; ") + ("rank " + std::to_string(rank) + ": " + s);
  return out;
}

struct Lost : sweep::LostUnit {
  int unit_id() const { return unit; }
};
struct Flight : parallel::InFlight {
  int unit_id() const { return id; }
};

// What the coordinator keeps while units come in: the checkpoint, the results as scenes complete,
// the per-unit records file if asked, counts for the progress line and the cost of writing the
// checkpoint. Nothing here grows with a unit's record: per unit only a few bytes (its scene,
// whether it is done, where its record starts in the checkpoint).
struct Ledger {
  sweep::Checkpoint& checkpoint;
  sweep::StreamedResults& results;
  const std::vector<sweep::Unit>& units;
  std::vector<double> scene_cost;  // sweep::unit_cost of each scene's units
  std::unique_ptr<sweep::LineFile> unit_records;
  double cost_total = 0, cost_before = 0, cost_now = 0;
  int computed = 0;
  double checkpoint_s = 0;
  Clock::time_point start = Clock::now();
  double cost(int id) const { return scene_cost[units[id].scene]; }
};

void show_progress(const Ledger& l, int units_total, int ranks, int threads) {
  const double elapsed = std::chrono::duration<double>(Clock::now() - l.start).count();
  const double fraction = (l.cost_before + l.cost_now) / l.cost_total;
  char text[200];
  std::snprintf(text, sizeof text, "sweep: %5.1f%% (%d of %d units, %d ranks x %d threads), %s elapsed, ETA %s",
                100 * fraction, l.checkpoint.done_count(), units_total, ranks, threads,
                shell::format_seconds(elapsed).c_str(),
                l.cost_now > 0 ? shell::format_seconds(elapsed * (l.cost_total - l.cost_before - l.cost_now) / l.cost_now).c_str()
                               : "?");
  shell::show_progress(text);
}

parallel::Hooks hooks(Ledger& l, bool progress, int units_total, const parallel::Scheduler& s) {
  parallel::Hooks h;
  h.assigned = [&l](const std::vector<int>& ids, int rank) {
    const auto t0 = Clock::now();
    l.checkpoint.assigned(ids, rank);
    l.checkpoint_s += std::chrono::duration<double>(Clock::now() - t0).count();
  };
  h.settled = [&l] {
    const auto t0 = Clock::now();
    l.checkpoint.flush();
    l.checkpoint_s += std::chrono::duration<double>(Clock::now() - t0).count();
    if (l.unit_records) l.unit_records->flush();
  };
  h.finished = [&l](int id, int, nlohmann::json result) {
    const auto& line = result.at("record").get_ref<const std::string&>();
    const auto t0 = Clock::now();
    l.checkpoint.finished(id, line);
    l.checkpoint_s += std::chrono::duration<double>(Clock::now() - t0).count();
    if (l.unit_records) l.unit_records->hold(line);
    l.results.add(l.units[id].scene, l.units[id].rep, result.at("numbers"));
    l.cost_now += l.cost(id);
    ++l.computed;
  };
  if (progress) h.tick = [&l, units_total, &s] { show_progress(l, units_total, s.ranks(), s.threads()); };
  return h;
}

// Units not in the checkpoint, the dearest first (sweep::unit_cost), so that no long unit starts
// last; equal costs keep their order.
std::vector<int> pending_units(const Ledger& l) {
  std::vector<int> ids;
  for (int id = 0; id < static_cast<int>(l.units.size()); ++id)
    if (!l.checkpoint.done(id)) ids.push_back(id);
  std::stable_sort(ids.begin(), ids.end(), [&](int a, int b) { return l.cost(a) > l.cost(b); });
  return ids;
}

void report_resume(const sweep::Checkpoint& cp, const std::vector<sweep::Unit>& units, int pending) {
  std::fprintf(stderr, "springblock: resuming from %s: %d of %d units already done, %d to compute\n",
               cp.path().c_str(), cp.done_count(), static_cast<int>(units.size()), pending);
  if (!cp.lost().empty()) {
    std::vector<Lost> lost;
    for (auto& u : cp.lost()) lost.push_back({u});
    std::fprintf(stderr, "springblock: the stopped run lost %d unit(s) in flight (recomputed now): %s\n",
                 static_cast<int>(lost.size()), by_rank(lost, units).c_str());
  }
}

int interrupted(const parallel::Outcome& o, Ledger& l, const std::vector<sweep::Unit>& units,
                parallel::Scheduler& s) {
  shell::end_progress_line();
  l.checkpoint.sync();
  std::vector<Flight> flight;
  for (auto& f : o.unfinished) flight.push_back({f});
  std::fprintf(stderr,
               "springblock: interrupted; %d of %d units are finished and checkpointed in %s. Units in flight "
               "(lost, recomputed on resume): %s. Run the same command with --resume to compute the rest. The "
               "%d scene(s) complete so far are in %s (marked partial).\n",
               l.checkpoint.done_count(), static_cast<int>(units.size()), l.checkpoint.path().c_str(),
               flight.empty() ? "none" : by_rank(flight, units).c_str(), l.results.scenes_complete(),
               l.results.partial().c_str());
  std::fflush(stderr);
  s.abort(shell::kInterrupted);  // the other ranks stop too (returns only without MPI)
  return shell::kInterrupted;
}

nlohmann::json header(const SweepOptions& o, const std::vector<sweep::SweepScene>& scenes, const Ledger& l,
                      const parallel::Outcome& out, const parallel::Scheduler& s, const std::string& command_line) {
  return {{"kind", "sweep"},
          {"file", o.file},
          {"scenes", scenes.size()},
          {"units", l.units.size()},
          {"computed_units", l.computed},
          {"resumed_units", l.checkpoint.done_count() - l.computed},
          {"ranks", s.ranks()},
          {"threads_per_rank", s.threads()},
          {"wall_s", std::chrono::duration<double>(Clock::now() - l.start).count()},
          {"lost_ranks", out.lost_ranks},
          {"messages", out.messages},
          {"message_s", out.message_s},
          {"checkpoint_s", l.checkpoint_s},
          {"provenance", provenance(command_line)}};
}

int finish(const SweepOptions& o, const std::vector<sweep::SweepScene>& scenes, Ledger& l,
           const parallel::Outcome& out, const parallel::Scheduler& s, const std::string& command_line) {
  shell::end_progress_line();
  for (auto& note : out.notes) std::fprintf(stderr, "springblock: %s\n", note.c_str());
  l.checkpoint.flush();
  l.results.complete(header(o, scenes, l, out, s, command_line), l.checkpoint);
  if (l.unit_records) l.unit_records->rename_to(o.units);
  l.checkpoint.remove();  // the results hold every unit now
  std::cout << l.results.summary();
  std::printf("%d scenes, %d units (%d computed now, %d from the checkpoint) on %d rank(s) x %d thread(s) in %.2f s; "
              "results in %s\n",
              static_cast<int>(scenes.size()), static_cast<int>(l.units.size()), l.computed,
              l.checkpoint.done_count() - l.computed, s.ranks(), s.threads(),
              std::chrono::duration<double>(Clock::now() - l.start).count(), out_path(o).c_str());
  return shell::kOk;
}

}  // namespace

int run_sweep(const SweepOptions& o, const std::string& command_line) {
  auto sched = make_scheduler(o.threads, o.batch_ms / 1000, o.dead_after_s);
  const bool lead = sched->coordinator();
  std::vector<sweep::SweepScene> scenes;
  std::vector<sweep::Unit> units;
  try {
    scenes = sweep::expand(sweep::read_spec(o.file));  // on every rank: a unit id means the same there
    units = sweep::make_units(scenes);
  } catch (const InputError&) {
    if (lead) throw;
    // Rank 0 found the same, says so and exits with kBadInput, which mpirun then returns. A
    // worker exiting non-zero first would make mpirun abort the job, at times before rank 0 has
    // printed a word (seen under load in cli_sweep_mpi): it leaves quietly instead.
    return 0;
  }
  sweep::StreamedResults results(scenes, out_path(o));
  std::unique_ptr<sweep::Checkpoint> cp;
  std::exception_ptr refused;
  if (lead) try {
      cp = open_checkpoint(o, scenes, units, results);
    } catch (...) {
      refused = std::current_exception();
    }
  if (!sched->agree(!refused)) {
    if (refused) std::rethrow_exception(refused);
    return lead ? shell::kBadInput : 0;  // a worker leaves quietly, as above
  }
  const auto* interrupt = shell::catch_interrupts();
  // A unit's result travels as its record's text (written to the checkpoint as it is) and the
  // few numbers its scene's statistics need: the coordinator parses those, not the record.
  auto run_unit = [&, rank = sched->rank()](int id, const std::atomic<bool>* stop) -> nlohmann::json {
    auto record = sweep::run_unit(scenes, units, id, stop);
    if (record.is_null()) return record;
    record["rank"] = rank;
    return {{"record", record.dump()}, {"numbers", sweep::record_numbers(record)}};
  };
  if (!lead) {
    sched->run({}, run_unit, {}, interrupt);
    return shell::kOk;
  }
  results.start(partial_header(o, scenes, units, command_line));
  Ledger l{*cp, results, units, {}, nullptr};
  if (!o.units.empty()) l.unit_records = start_unit_records(o.units, *cp);
  for (const auto& s : scenes) l.scene_cost.push_back(sweep::unit_cost(s.scene));
  for (int id = 0; id < static_cast<int>(units.size()); ++id) {
    l.cost_total += l.cost(id);
    if (cp->done(id)) l.cost_before += l.cost(id);
  }
  const auto ids = pending_units(l);
  if (o.resume) report_resume(*cp, units, static_cast<int>(ids.size()));
  const bool progress = o.progress || ::isatty(STDERR_FILENO);
  const auto outcome = sched->run(ids, run_unit, hooks(l, progress, static_cast<int>(units.size()), *sched), interrupt);
  if (outcome.interrupted) return interrupted(outcome, l, units, *sched);
  return finish(o, scenes, l, outcome, *sched, command_line);
}

}  // namespace sb::app
