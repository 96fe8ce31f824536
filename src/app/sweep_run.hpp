#pragma once
// The sweep command's run: the library's sweep (sweep/driver.hpp) on MPI ranks or this process's
// threads, with its progress line, its messages on stderr and its summary table on stdout.
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
// other ranks return kOk quietly (the coordinator says why, once).
int run_sweep(const SweepOptions& options, const std::string& command_line);

}  // namespace sb::app
