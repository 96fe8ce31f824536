#pragma once
// The `design` subcommand (inverse design, src/springblock/design): its options, its terminal
// table and its JSON. main.cpp registers it with one call and runs it when it was parsed.
#include <memory>
#include <string>

namespace CLI {
class App;
}

namespace sb::app {

struct DesignArgs;

class DesignCommand {
 public:
  explicit DesignCommand(CLI::App& app);  // adds the subcommand and its options to `app`
  ~DesignCommand();
  bool parsed() const;
  int run(const std::string& command_line) const;  // an exit code of shell/exit_codes.hpp

 private:
  std::unique_ptr<DesignArgs> args_;
  CLI::App* cmd_ = nullptr;
};

}  // namespace sb::app
