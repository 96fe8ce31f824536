#include "sweep_command.hpp"

#include <CLI/CLI.hpp>

#include "shell/exit_codes.hpp"
#include "springblock/errors.hpp"
#include "sweep_run.hpp"

namespace sb::app {

struct SweepCommand::Args : SweepOptions {};

SweepCommand::SweepCommand(CLI::App& app) : args_(std::make_unique<Args>()) {
  cmd_ = app.add_subcommand("sweep", "run every scene of a sweep file (TOML or JSON): one work unit per repetition, "
                                     "over threads, or over ranks and threads under mpirun");
  cmd_->add_option("FILE", args_->file, "sweep file: [base] scene fields, [[scenes]] to list, [axes] to vary "
                                        "(lists, or ranges {from, to, steps, scale})")
      ->required();
  cmd_->add_option("--out", args_->out, "results (JSON lines; default: FILE with .results.jsonl); the checkpoint "
                                        "is this path + .checkpoint");
  cmd_->add_option("--units", args_->units, "also write every unit's record (JSON lines, one per repetition) to this "
                                            "file: UNITS.partial grows as units finish, renamed UNITS when the sweep "
                                            "completes");
  cmd_->add_option("--threads", args_->threads, "threads per process (rank); 0 = all cores (OMP_NUM_THREADS if set)")
      ->check(CLI::Range(0, 4096));
  cmd_->add_option("--batch-ms", args_->batch_ms, "under mpirun: each worker asks for enough units to keep its "
                                                "threads busy about this long (from their measured time), so "
                                                "rank 0 answers one message per batch; 0 = one unit per request")
      ->check(CLI::Range(0.0, 60000.0));
  cmd_->add_option("--dead-after", args_->dead_after_s,
                   "under mpirun: a worker rank silent this many seconds (workers send a heartbeat while they "
                   "compute) is taken for dead and its units are dealt to the others; the job survives a dead "
                   "rank only under mpirun --enable-recovery --mca orte_abort_on_non_zero_status 0")
      ->check(CLI::Range(1.0, 86400.0));
  cmd_->add_flag("--resume", args_->resume, "finish an interrupted sweep from its checkpoint, computing only the "
                                            "units it lacks");
  cmd_->add_flag("--progress", args_->progress, "show progress and ETA on stderr even when it is not a terminal");
  cmd_->footer(
      "Under mpirun -np P, rank 0 deals units in batches (--batch-ms) from the front of its queue, the "
      "dearest first, to every rank (dynamic balance) and writes the files; the numbers are bit-identical "
      "to a run in one process. A worker rank silent for --dead-after seconds is taken for dead and its "
      "units are dealt to the others (the job outlives it under mpirun --enable-recovery --mca "
      "orte_abort_on_non_zero_status 0). While it runs, OUT.partial holds a line per complete scene (statistics, "
      "no runs) under a header with \"partial\": true; OUT appears, whole, when the sweep completes. "
      "Exit codes: 0 done; 2 bad input (the field and the line of the sweep file; nothing run); 130 "
      "interrupted (finished units are checkpointed: run again with --resume); 1 any other error.");
}

SweepCommand::~SweepCommand() = default;

bool SweepCommand::parsed() const { return cmd_->parsed(); }

int SweepCommand::run(const std::string& command_line) const {
  return shell::guarded("springblock", [&] { return run_sweep(*args_, command_line); });
}

}  // namespace sb::app
