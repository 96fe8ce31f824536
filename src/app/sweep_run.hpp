#pragma once
// The sweep command's run: read and expand the sweep file on every rank, open the checkpoint and
// deal the missing units on the coordinator, then write the results and print the table.
#include <string>

namespace sb::app {

struct SweepOptions {
  std::string file, out, units;  // units: the per-unit records file, if asked
  int threads = 0;
  double batch_ms = 50;  // under MPI: a worker's target time per batch of units; 0 = one unit per request
  double dead_after_s = 10;  // under MPI: a worker rank silent this long is taken for dead
  bool resume = false, progress = false;
};

// Returns the exit code (shell::ExitCode). Throws InputError on the coordinator for bad input;
// other ranks return kBadInput quietly (the coordinator says why, once).
int run_sweep(const SweepOptions& options, const std::string& command_line);

}  // namespace sb::app
