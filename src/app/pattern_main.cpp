// springblock_pattern: the `pattern` subcommand of springblock on its own. The figures draw every
// surface from the simulator's mask builder; this program gives them that builder without the
// rest of the command-line tool, whose sweep, design and MPI layers are most of a fresh
// reproduce-all's compile time. Same options, same output, same exit codes as `springblock pattern`.
#include <CLI/CLI.hpp>

#include "pattern_command.hpp"
#include "shell/command_line.hpp"
#include "shell/exit_codes.hpp"

int main(int argc, char** argv) {
  CLI::App app{"springblock_pattern: a surface's contact mask, as `springblock pattern` prints it."};
  app.require_subcommand(1);
  const sb::app::PatternCommand pattern(app);
  if (auto done = sb::shell::parse(app, argc, argv, "springblock_pattern", "Run 'springblock_pattern pattern --help'."))
    return *done;
  return sb::shell::guarded("springblock_pattern", [&] { return pattern.run(); });
}
