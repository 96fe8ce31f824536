#include "pattern_command.hpp"

#include <CLI/CLI.hpp>
#include <cstdio>
#include <string>

#include "shell/exit_codes.hpp"
#include "springblock/surface.hpp"

namespace sb::app {

struct PatternArgs {
  int N = 120;
  std::string spec = "smooth";
  std::string layout = sb::PatternSpec{}.layout_text();
};

PatternCommand::PatternCommand(CLI::App& app) : args_(std::make_unique<PatternArgs>()) {
  cmd_ = app.add_subcommand("pattern", "print a surface's contact mask (1 = pawl, 0 = groove) and S/S_tot");
  cmd_->add_option("--N", args_->N, "number of blocks")->check(CLI::Range(1, 1000000));
  cmd_->add_option("--pattern", args_->spec, "smooth | periodic:NP,NG | hierarchical:G1,G2,... | hierarchical:P1/G1,P2/G2,... | "
                   "random:FRACTION | mask:0110... | mask:@FILE (a mask has N blocks)");
  cmd_->add_option("--layout", args_->layout,
                   "pawl_first | symmetric | groove_first | one_based (per level, comma separated)")
      ->default_str(args_->layout);
}

PatternCommand::~PatternCommand() = default;

bool PatternCommand::parsed() const { return cmd_->parsed(); }

int PatternCommand::run() const {
  auto spec = sb::parse_pattern(args_->spec);
  spec.layout = sb::parse_layout(args_->layout);
  const auto mask = sb::build_contact_mask(spec, args_->N, 1);
  for (auto m : mask) std::putchar(m ? '1' : '0');
  // %.17g: S/S_tot read back bit for bit.
  std::printf("\n%.17g\n", sb::contact_fraction(mask));
  return shell::kOk;
}

}  // namespace sb::app
