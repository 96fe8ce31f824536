#include "shell/command_line.hpp"

#include <CLI/CLI.hpp>
#include <cstdio>

#include "shell/exit_codes.hpp"

namespace sb::shell {

std::optional<int> parse(CLI::App& app, int argc, char** argv, const std::string& program, const std::string& hint,
                         bool quiet) {
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return quiet ? kOk : app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return quiet ? kOk : app.exit(e);
  } catch (const CLI::ParseError& e) {
    if (!quiet) std::fprintf(stderr, "%s: %s\n%s\n", program.c_str(), e.what(), hint.c_str());
    return kBadInput;
  }
  return std::nullopt;
}

std::string command_line(int argc, char** argv) {
  std::string s;
  for (int i = 0; i < argc; ++i) s += (i ? " " : "") + std::string(argv[i]);
  return s;
}

}  // namespace sb::shell
