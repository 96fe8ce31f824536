#pragma once
// `springblock sweep FILE`: many scenes, each repetition a work unit, over threads or, under
// mpirun, over ranks and their threads; checkpointed and resumable. main() only registers it.
#include <memory>
#include <string>

namespace CLI {
class App;
}

namespace sb::app {

class SweepCommand {
 public:
  explicit SweepCommand(CLI::App& app);  // adds the subcommand and its options
  ~SweepCommand();
  bool parsed() const;
  int run(const std::string& command_line) const;

 private:
  struct Args;
  std::unique_ptr<Args> args_;
  CLI::App* cmd_ = nullptr;
};

}  // namespace sb::app
