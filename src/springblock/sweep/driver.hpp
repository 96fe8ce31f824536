#pragma once
// A whole sweep on a scheduler: expand the spec on every rank, open the checkpoint (resumed or
// fresh) and deal the missing units on the coordinator, stream the results and complete them.
// What the command line prints and what Python hands back are both read off the Report and the
// Events, so the two give the same files and the same numbers from the same code.
#include <atomic>
#include <functional>
#include <string>
#include <vector>

#include "springblock/parallel/scheduler.hpp"
#include "springblock/sweep/outputs.hpp"
#include "springblock/sweep/spec.hpp"

namespace sb::sweep {

// How far the sweep has got (the coordinator's view).
struct Progress {
  int done = 0, total = 0;  // units finished (resumed ones included) and in all
  int computed = 0;         // of them, computed by this run
  int ranks = 1, threads = 1;
  double fraction = 0;      // of the sweep's cost (unit_cost) done
  double elapsed_s = 0;
  double eta_s = -1;        // at this run's rate; negative until a unit of this run has finished
};

// A resumed checkpoint, read back before any unit runs.
struct Resumed {
  std::string path;
  int done = 0, total = 0, pending = 0;
  int lost = 0;           // units the stopped run had handed out and never got back
  std::string lost_units; // those units by rank: "rank 1: 3 (scene 1 rep 0), 7 (...); rank 2: ..."
};

// Called on the coordinator, from the thread that called run_sweep.
struct Events {
  std::function<void(const Resumed&)> resumed;
  std::function<void(const Progress&)> progress;  // about 5 times a second while units run
};

struct Report {
  bool coordinator = true;  // false on the other ranks: they computed units and wrote nothing
  bool refused = false;     // on another rank: the coordinator refused the input, nothing ran
  bool interrupted = false;
  int scenes = 0, units = 0, computed = 0, resumed = 0;
  int ranks = 1, threads = 1;
  double wall_s = 0;
  std::string out, partial, checkpoint;  // the results, the partial results, the checkpoint
  int scenes_complete = 0;
  std::string in_flight;    // interrupted: units handed out and lost, by rank ("" for none)
  std::vector<std::string> notes;
  std::string summary;      // the summary table (heading and one row per complete scene)
};

// Runs `spec` on `scheduler` (every rank calls it with the same spec; the coordinator's options
// count). On completion OUT holds the results and the checkpoint is removed; on an interrupt the
// checkpoint holds every finished unit (synced) for a later resume, OUT.partial the complete
// scenes. Throws InputError on the coordinator for bad input before any unit runs; the other
// ranks return `refused` quietly.
Report run_sweep(const Spec& spec, const OutputOptions& options, parallel::Scheduler& scheduler,
                 const std::atomic<bool>* interrupt, const Events& events, const std::string& command_line);

}  // namespace sb::sweep
