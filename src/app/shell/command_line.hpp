#pragma once
// The command line: parsed with CLI11 the same way by every program (help, and a malformed
// command line as bad input), and kept as text for the provenance of every output.
#include <optional>
#include <string>

namespace CLI {
class App;
}

namespace sb::shell {

// Parses argv into `app`. Returns the exit code when parsing already ends the program: help
// printed (kOk), or a malformed command line (kBadInput, "<program>: <what>" and then `hint` on
// stderr; with `quiet`, nothing printed: another process says it). nullopt: go on.
std::optional<int> parse(CLI::App& app, int argc, char** argv, const std::string& program, const std::string& hint,
                         bool quiet = false);

// argv joined by spaces: the command recorded in every output's provenance.
std::string command_line(int argc, char** argv);

}  // namespace sb::shell
