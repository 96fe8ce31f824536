#include "design_command.hpp"

#include <CLI/CLI.hpp>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <nlohmann/json.hpp>
#include <unistd.h>

#include "shell/exit_codes.hpp"
#include "shell/field_options.hpp"
#include "shell/interrupt.hpp"
#include "shell/output.hpp"
#include "shell/progress.hpp"
#include "springblock/design/query.hpp"
#include "springblock/design/query_text.hpp"
#include "springblock/design/report.hpp"
#include "springblock/errors.hpp"
#include "springblock/scene_fields.hpp"
#include "springblock/surface_mask.hpp"

namespace sb::app {

struct DesignArgs {
  shell::FieldOptions fields;
  design::Query query;
  design::QueryText text;
  std::string pattern;  // refused: the search chooses the surface
  std::string out_path;
  bool json = false, progress = false, no_class_prune = false;
};

namespace {

void add_space_options(CLI::App* cmd, design::DesignSpace& s, DesignArgs& a) {
  cmd->add_option("--family", a.text.family, "pattern family: periodic (default), hierarchical, random, or given (--candidates)");
  cmd->add_option("--candidates", a.text.candidates,
                  "given: the surfaces to choose among, each as --pattern takes it (e.g. mask:@a.txt mask:0110 periodic:3,1)");
  cmd->add_option("--pattern", a.pattern, "not an option of design: it chooses the surface (see --family given)");
  cmd->add_option("--min-np", s.min_np, "periodic: smallest pawl size n_p in blocks (default 1)");
  cmd->add_option("--max-np", a.text.max_np, "periodic: largest pawl size n_p (default 60, or N if smaller)");
  cmd->add_option("--min-ng", s.min_ng, "periodic/hierarchical: smallest groove size n_g or G1 (default 1)");
  cmd->add_option("--max-ng", a.text.max_ng,
                  "periodic/hierarchical: largest groove size n_g or G1 (default 60, or N if smaller)");
  cmd->add_option("--levels", s.levels, "hierarchical: number of levels (default 2)");
  cmd->add_option("--factors", s.factors, "hierarchical: allowed ratios G_k/G_{k+1} (default 2,3,4,5,6,8,10)")->delimiter(',');
  cmd->add_option("--min-fraction", s.min_fraction, "random: smallest groove fraction (default 0.1)");
  cmd->add_option("--max-fraction", s.max_fraction, "random: largest groove fraction (default 0.9)");
  cmd->add_option("--fraction-step", s.fraction_step, "random: step of the groove fraction (default 0.05)");
  cmd->add_option("--min-contact", s.min_contact, "constraint: smallest contact fraction S/S_tot (default 0)");
  cmd->add_option("--max-contact", s.max_contact, "constraint: largest contact fraction (default 1)");
  cmd->add_option("--min-feature", s.min_feature, "constraint: shortest pawl or groove run in blocks (default 1)");
}

void add_target_options(CLI::App* cmd, DesignArgs& a) {
  const std::string forms = " X, LO:HI, >=X or <=X";
  cmd->add_option("--target-mu-s", a.text.target_mu_s, "target macroscopic mu_s:" + forms);
  cmd->add_option("--target-mu-d", a.text.target_mu_d, "target macroscopic mu_d:" + forms);
  cmd->add_option("--target-ratio", a.text.target_ratio, "target ratio mu_s/mu_d:" + forms);
  cmd->add_option("--minimise", a.text.minimise, "minimise mu_s, mu_d or ratio subject to the targets");
  cmd->add_option("--maximise", a.text.maximise, "maximise mu_s, mu_d or ratio subject to the targets");
}

void add_search_options(CLI::App* cmd, design::Query& q) {
  cmd->add_option("--top", q.top, "candidates verified and reported (default 5)");
  cmd->add_option("--verify-reps", q.verify.reps, "fresh full repetitions of each reported candidate at first (default 10)");
  cmd->add_option("--verify-max-reps", q.verify.max_reps,
                  "doubled while a candidate's distance to the target is unresolved, up to this many (default 80)");
  cmd->add_option("--resolution", q.verify.resolution,
                  "a distance to the target counts as resolved once 2 SEM is at most this (default 0.002)");
  cmd->add_option("--screen-reps", q.search.screen_reps, "repetitions of every candidate in rung 0 (default 1)");
  cmd->add_option("--eta", q.search.eta, "successive halving: keep 1/eta of the survivors per rung (default 4)");
  cmd->add_option("--growth", q.search.growth, "successive halving: repetitions multiplied per rung (default 2)");
  cmd->add_option("--max-reps", q.search.max_reps, "successive halving: repetitions cap per candidate (default 16)");
  cmd->add_option("--final-pool", q.search.final_pool, "successive halving: stop at this many survivors (default 15)");
  cmd->add_option("--class-width", q.classes.bin_width, "mu_d target: width of the contact-fraction classes (default 0.02)");
  cmd->add_option("--class-margin", q.classes.margin, "mu_d target: prune a class whose mu_d is this far from the target (default 0.02)");

}

// The query of the command line, validated; the --out file claimed. Bad input throws first.
design::Query build_query(const DesignArgs& a, CLI::App* cmd) {
  design::Query q = a.query;
  if (cmd->count("--pattern") > 0) design::refuse_pattern(a.pattern);
  q.class_prune = !a.no_class_prune;
  a.fields.apply(q.base);
  design::complete_query(q, a.text);
  if (cmd->count("--out") > 0) shell::claim_output(a.out_path, "out");
  return q;
}

std::string statistic_text(const Statistic& s) {
  if (s.n == 0) return "     not measured";
  char t[64];
  std::snprintf(t, sizeof t, "%.4f +- %.4f", s.mean, s.sem);
  return t;
}

void print_table(const design::Query& q, const design::Outcome& o) {
  const auto& c = o.candidates;
  std::printf("design: %s family, %d specs, %zu simulated (%d same mask, %d contact, %d feature excluded), %zu rungs, "
              "%.1f s\n", design::family_name(q.space.family).c_str(), c.generated, c.kept.size(), c.dropped_duplicate,
              c.dropped_contact, c.dropped_feature, o.search.rungs.size(), o.wall_s);
  std::printf("target: mu_s %s, mu_d %s, ratio %s\n", q.target.mu_s.text().c_str(), q.target.mu_d.text().c_str(),
              q.target.ratio.text().c_str());
  std::printf("fresh estimates (%d reps each at first, up to %d, seed %llu); %s\n", q.verify.reps, q.verify.max_reps,
              (unsigned long long)design::stage_seed(q.base.seed, design::kVerifyStage), design::meets_rule().c_str());
  std::printf("%s (resolution %g)\n", design::order_rule().c_str(), q.verify.resolution);
  std::printf("%-3s %-22s %7s %-17s %-17s %-6s %-10s %5s %-8s\n", "#", "pattern", "S/Stot", "mu_s", "mu_d", "meets",
              "score", "reps", "resolved");
  for (std::size_t i = 0; i < o.verified.size(); ++i) {
    const auto& v = o.verified[i];
    std::printf("%-3zu %-22s %7.4f %-17s %-17s %-6s %-10.4f %5d %s (2 SEM %.4f)\n", i + 1,
                pattern_label(o.candidates.kept[v.candidate].spec).c_str(), o.candidates.kept[v.candidate].contact_fraction,
                statistic_text(v.mu_s).c_str(), statistic_text(v.mu_d).c_str(), v.meets_target ? "yes" : "no", v.score,
                v.reps, v.resolved ? "yes" : "no", v.half_width);
  }
  std::printf("feasible: %s\n", o.feasible ? "yes" : "no");
  if (!o.feasible) std::printf("why: %s\n", design::infeasible_reason(q, o).c_str());
}

// One line per stage (classes, rungs, verification): its share done and its ETA, and the query's
// elapsed time. Rung 0 is most of a query (README, Design a surface), so its ETA is nearly the
// query's; the stages after it are each cheaper than the one before.
design::StageProgress progress_printer() {
  const auto start = std::chrono::steady_clock::now();
  return [start](const std::string& stage, double f, double elapsed) {
    if (f <= 0) return;
    const double total = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    char text[240];
    std::snprintf(text, sizeof text, "springblock design: %s: %5.1f%%, ETA of this stage %s (%s elapsed)", stage.c_str(),
                  100 * f, shell::format_seconds(shell::eta_seconds(f, elapsed)).c_str(),
                  shell::format_seconds(total).c_str());
    shell::show_progress(text);
  };
}

}  // namespace

DesignCommand::DesignCommand(CLI::App& app) : args_(std::make_unique<DesignArgs>()) {
  cmd_ = app.add_subcommand("design", "inverse design: search a pattern family for the surface that gives a target "
                                      "mu_s, mu_d or ratio (successive halving, verified on fresh repetitions)");
  for (const auto& f : scene_fields())
    if (design::shared_scene_field(f.key)) args_->fields.add(cmd_, f.key, f.help + " (e.g. " + f.example + ")");
  add_space_options(cmd_, args_->query.space, *args_);
  add_target_options(cmd_, *args_);
  add_search_options(cmd_, args_->query);
  cmd_->add_flag("--no-class-prune", args_->no_class_prune, "mu_d target: do not prune on contact-fraction classes");
  cmd_->add_flag("--json", args_->json, "print one JSON object on stdout");
  cmd_->add_option("--out", args_->out_path, "write the full JSON results to this file (atomically)");
  cmd_->add_flag("--progress", args_->progress, "show progress and ETA on stderr even when it is not a terminal");
  cmd_->footer("Exit codes: 0 results printed (feasible or not: see 'feasible'); 2 bad input, named with its allowed "
               "range (nothing run or written); 130 interrupted (nothing written); 1 any other error.");
}

DesignCommand::~DesignCommand() = default;

bool DesignCommand::parsed() const { return cmd_->parsed(); }

int DesignCommand::run(const std::string& command_line) const {
  const design::Query q = build_query(*args_, cmd_);
  const auto* interrupt = shell::catch_interrupts();
  const bool show = args_->progress || ::isatty(STDERR_FILENO);
  const auto outcome = design::run_design(q, interrupt, show ? progress_printer() : design::StageProgress{});
  shell::end_progress_line();
  if (outcome.interrupted) {
    std::fprintf(stderr, "springblock: interrupted. No output file was written and existing files are untouched.\n");
    return shell::kInterrupted;
  }
  const auto j = design::design_json(q, outcome, command_line);
  if (!args_->out_path.empty()) shell::write_output(args_->out_path, j.dump(2) + "\n");
  if (args_->json)
    std::cout << j.dump() << "\n";
  else
    print_table(q, outcome);
  return shell::kOk;
}

}  // namespace sb::app
