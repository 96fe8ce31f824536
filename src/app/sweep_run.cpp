#include "sweep_run.hpp"

#include <unistd.h>

#include <cstdio>
#include <iostream>

#include "shell/exit_codes.hpp"
#include "shell/interrupt.hpp"
#include "shell/progress.hpp"
#include "springblock/errors.hpp"
#include "springblock/sweep/driver.hpp"
#include "scheduler_choice.hpp"

namespace sb::app {
namespace {

void show_progress(const sweep::Progress& p) {
  char text[200];
  std::snprintf(text, sizeof text, "sweep: %5.1f%% (%d of %d units, %d ranks x %d threads), %s elapsed, ETA %s",
                100 * p.fraction, p.done, p.total, p.ranks, p.threads, shell::format_seconds(p.elapsed_s).c_str(),
                p.eta_s >= 0 ? shell::format_seconds(p.eta_s).c_str() : "?");
  shell::show_progress(text);
}

void report_resume(const sweep::Resumed& r) {
  std::fprintf(stderr, "springblock: resuming from %s: %d of %d units already done, %d to compute\n", r.path.c_str(),
               r.done, r.total, r.pending);
  if (r.lost > 0)
    std::fprintf(stderr, "springblock: the stopped run lost %d unit(s) in flight (recomputed now): %s\n", r.lost,
                 r.lost_units.c_str());
}

int interrupted(const sweep::Report& r, parallel::Scheduler& s) {
  std::fprintf(stderr,
               "springblock: interrupted; %d of %d units are finished and checkpointed in %s. Units in flight "
               "(lost, recomputed on resume): %s. Run the same command with --resume to compute the rest. The "
               "%d scene(s) complete so far are in %s (marked partial).\n",
               r.computed + r.resumed, r.units, r.checkpoint.c_str(), r.in_flight.empty() ? "none" : r.in_flight.c_str(),
               r.scenes_complete, r.partial.c_str());
  std::fflush(stderr);
  s.abort(shell::kInterrupted);  // the other ranks stop too (returns only without MPI)
  return shell::kInterrupted;
}

int finish(const sweep::Report& r) {
  for (auto& note : r.notes) std::fprintf(stderr, "springblock: %s\n", note.c_str());
  std::cout << r.summary;
  std::printf("%d scenes, %d units (%d computed now, %d from the checkpoint) on %d rank(s) x %d thread(s) in %.2f s; "
              "results in %s\n",
              r.scenes, r.units, r.computed, r.resumed, r.ranks, r.threads, r.wall_s, r.out.c_str());
  return shell::kOk;
}

}  // namespace

int run_sweep(const SweepOptions& o, const std::string& command_line) {
  auto sched = make_scheduler(o.threads, o.batch_ms / 1000, o.dead_after_s);
  sweep::Spec spec;
  try {
    spec = sweep::read_spec(o.file);  // on every rank, as the scenes are expanded
  } catch (const InputError&) {
    if (sched->coordinator()) throw;
    return 0;  // rank 0 says why and exits with kBadInput; a worker leaves quietly (sweep::run_sweep)
  }
  const auto* interrupt = shell::catch_interrupts();
  sweep::Events events;
  events.resumed = report_resume;
  if (o.progress || ::isatty(STDERR_FILENO)) events.progress = show_progress;
  const sweep::OutputOptions outputs{o.file, o.out, o.units, o.resume};
  const auto report = sweep::run_sweep(spec, outputs, *sched, interrupt, events, command_line);
  if (!report.coordinator) return shell::kOk;  // another rank: rank 0 reports, refused input included
  shell::end_progress_line();
  return report.interrupted ? interrupted(report, *sched) : finish(report);
}

}  // namespace sb::app
