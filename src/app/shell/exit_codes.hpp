#pragma once
// How every springblock program ends: its exit codes, and the one stderr line that says why it
// failed. Scripts (CTest, the reproduction build, the checker) branch on these codes, so the
// main program and the reproduction targets must agree on them.
#include <functional>
#include <string>

namespace sb::shell {

enum ExitCode : int {
  kOk = 0,
  kFailed = 1,           // anything not covered below (a bug, a full disk)
  kBadInput = 2,         // sb::InputError or a malformed command line: nothing ran, nothing written
  kNothingMeasured = 3,  // the run finished but measured nothing; nothing written
  kInterrupted = 130,    // SIGINT/SIGTERM (128 + SIGINT, as a shell reports it); nothing written
};

// How a failure that is not an sb::InputError is reported: "<program>: <label>: <what>" and the
// exit code. A target's setup reads tables and other targets' documents, so a failure there is
// the user's input (kBadInput) even when it is not an InputError.
struct OtherFailure {
  std::string label = "error";
  int code = kFailed;
};

// Runs `body` and returns its exit code. An exception ends any progress line and becomes one
// stderr line: sb::InputError -> "<program>: invalid <field>: <message>" with kBadInput, any
// other -> `other`.
int guarded(const std::string& program, const std::function<int()>& body, const OtherFailure& other = {});

}  // namespace sb::shell
