#pragma once
// The `pattern` subcommand: a surface's contact mask (1 = pawl, 0 = groove) and S/S_tot, from the
// simulator's own mask builder. Two programs carry it: `springblock` and `springblock_pattern`,
// the small program the figures call for their drawings, so that `make reproduce-all` need not
// build the whole command-line tool (its sweep and design layers) to draw a surface.
#include <memory>

namespace CLI {
class App;
}

namespace sb::app {

struct PatternArgs;

class PatternCommand {
 public:
  explicit PatternCommand(CLI::App& app);  // adds the subcommand and its options to `app`
  ~PatternCommand();
  bool parsed() const;
  int run() const;  // prints the mask and S/S_tot on stdout; an exit code of shell/exit_codes.hpp

 private:
  std::unique_ptr<PatternArgs> args_;
  CLI::App* cmd_ = nullptr;
};

}  // namespace sb::app
