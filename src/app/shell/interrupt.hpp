#pragma once
// Ctrl-C and kill end a run cleanly: the signal only sets a flag that the simulation polls
// between steps, so the program stops with kInterrupted and writes nothing rather than dying
// halfway through writing a file.
#include <atomic>

namespace sb::shell {

// Installs the SIGINT and SIGTERM handlers and returns the flag they set (for sb::run_ensemble).
const std::atomic<bool>* catch_interrupts();

}  // namespace sb::shell
