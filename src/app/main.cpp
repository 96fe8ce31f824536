// springblock: command-line front end. It only parses arguments and calls the library; the
// shell (src/app/shell) it shares with the reproduction targets owns exit codes, interrupts,
// progress and output files.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <iostream>
#include <nlohmann/json.hpp>
#include <unistd.h>

#include "shell/command_line.hpp"
#include "shell/exit_codes.hpp"
#include "shell/field_options.hpp"
#include "shell/interrupt.hpp"
#include "shell/output.hpp"
#include "shell/progress.hpp"
#include "design_command.hpp"
#include "pattern_command.hpp"
#include "run_ranks.hpp"
#include "sweep_command.hpp"
#include "work_table.hpp"
#include "springblock/ensemble.hpp"
#include "springblock/errors.hpp"
#include "springblock/input_file.hpp"
#include "springblock/io.hpp"
#include "springblock/scene.hpp"
#include "springblock/scene_theory.hpp"
#include "springblock/surface_mask.hpp"

namespace {

namespace shell = sb::shell;

struct RunArgs {
  shell::FieldOptions fields;
  std::string scene_file, out_path, series_path;
  bool json = false, progress = false, profile = false;
};

struct TheoryArgs {
  shell::FieldOptions fields;
  bool json = false;
};

sb::Scene load_scene_file(const std::string& path) {
  const std::string text = sb::read_input_file(path, "scene", "scene file");
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(text);
  } catch (const nlohmann::json::exception& e) {
    throw sb::InputError("scene", "'" + path + "' is not valid JSON: " + e.what());
  }
  sb::Scene s;
  sb::apply_scene_json(s, j);
  return s;
}

void print_progress(double fraction, double elapsed) {
  if (fraction <= 0) return;
  char text[128];
  std::snprintf(text, sizeof text, "springblock: %5.1f%% done, %.0f s elapsed, ETA %.0f s", 100 * fraction, elapsed,
                shell::eta_seconds(fraction, elapsed));
  shell::show_progress(text);
}

// A statistic over no repetitions prints why instead of a NaN.
void print_statistic(const char* name, const sb::Statistic& st, const std::string& not_measured) {
  if (st.n == 0)
    std::printf("%s: not measured (%s)\n", name, not_measured.c_str());
  else
    std::printf("%s = %.4f +- %.4f (sd %.4f, n=%d)\n", name, st.mean, st.sem, st.std, st.n);
}

// The scene of `run`, checked, with its output paths claimed: bad input fails before the run.
sb::Scene run_scene(const RunArgs& a, CLI::App* cmd) {
  sb::Scene scene = a.scene_file.empty() ? sb::Scene{} : load_scene_file(a.scene_file);
  a.fields.apply(scene);
  if (cmd->count("--series") > 0) scene.observe.series = true;
  if (a.profile) scene.observe.timed_work = true;
  sb::validate(scene);
  if (cmd->count("--out") > 0) shell::claim_output(a.out_path, "out");
  if (cmd->count("--series") > 0) {
    if (a.series_path == a.out_path)
      throw sb::InputError("series", "'" + a.series_path + "' is also the --out file; give another file");
    shell::claim_output(a.series_path, "series");
  }
  return scene;
}

const char* loading_end(const sb::Scene& scene) {
  using R = sb::ExtractionRules::PeakRule;
  switch (scene.rules.peak_rule) {
    case R::Drop: return "mu(t) never fell peak_drop below its running maximum";
    case R::SlidOrDrop: return "not every contact block slid, and mu(t) never fell peak_drop below its running maximum";
    case R::SlidOrRelativeDrop:
      return "not every contact block slid, and mu(t) never fell peak_drop_fraction below its running maximum";
    case R::SlidOrEvent:
      return "not every contact block slid, and no slip event moved peak_event_fraction of the contact blocks";
    case R::AllSlipped: break;
  }
  return "not every contact block slid";
}

// Nothing measured is an error, not a result of NaNs: says why and returns true (exit 3, known
// only after the run; bad input is 2), or warns about the repetitions that measured nothing.
bool nothing_measured(const sb::Scene& scene, const sb::EnsembleResult& result) {
  const double T = scene.duration(), t0 = scene.t0_s();
  const bool mu_d_wanted = !scene.run.stop_after_mu_s;
  if (result.mu_s.n == 0) {
    std::fprintf(stderr,
                 "springblock: nothing measured: no repetition (of %d) ended its loading phase (%s) "
                 "before the end of the run (duration = %g s = %g t0), so mu_s and mu_d are undefined. "
                 "Lengthen --duration%s. No output file was written.\n",
                 scene.reps, loading_end(scene), T, T / t0,
                 scene.rules.peak_rule == sb::ExtractionRules::PeakRule::Drop ? " or lower --peak-drop" : "");
    return true;
  }
  if (mu_d_wanted && result.mu_d.n == 0) {
    std::fprintf(stderr,
                 "springblock: nothing measured: no repetition had a sample in its mu_d window (from the "
                 "first slip + mu_d_skip = %g t0 to the end of the run, duration = %g t0), so mu_d is "
                 "undefined. Lower --mu-d-skip or lengthen --duration. No output file was written.\n",
                 scene.rules.mu_d_skip_t0, T / t0);
    return true;
  }
  if (result.mu_s.n < scene.reps)
    std::fprintf(stderr,
                 "springblock: warning: %d of %d repetitions never ended their loading phase (%s) before "
                 "the end of the run; their mu_s and mu_d are undefined (null). Lengthen --duration.\n",
                 scene.reps - result.mu_s.n, scene.reps, loading_end(scene));
  if (mu_d_wanted && result.mu_d.n < result.mu_s.n)
    std::fprintf(stderr,
                 "springblock: warning: %d of %d repetitions that slipped had no sample in their mu_d window; "
                 "their mu_d is undefined (null). Lower --mu-d-skip or lengthen --duration.\n",
                 result.mu_s.n - result.mu_d.n, result.mu_s.n);
  return false;
}

void print_run_text(const sb::Scene& scene, const sb::EnsembleResult& result) {
  std::printf("scene: N=%d L_x=%g m pattern=%s contact fraction=%.6g method=%s reps=%d seed=%llu\n",
              scene.geometry.N, scene.geometry.L_x_m, sb::pattern_label(scene.pattern).c_str(), result.contact_fraction,
              sb::method_name(scene.run.method).c_str(), scene.reps, (unsigned long long)scene.seed);
  print_statistic("mu_s", result.mu_s, sb::not_measured(scene, result, "mu_s"));
  print_statistic("mu_d", result.mu_d, sb::not_measured(scene, result, "mu_d"));
  std::printf("wall time %.2f s on %d threads\n", result.wall_s, result.threads);
}

int cmd_run(const RunArgs& a, CLI::App* cmd, const std::string& command_line) {
  const sb::Scene scene = run_scene(a, cmd);
  const auto* interrupt = shell::catch_interrupts();
  const bool show = a.progress || ::isatty(STDERR_FILENO);
  auto ranked = sb::app::run_ensemble_on_ranks(scene, interrupt, show ? print_progress : std::function<void(double, double)>{});
  if (!ranked) return shell::kOk;  // a rank other than 0 under mpirun: rank 0 reports
  auto& result = *ranked;
  shell::end_progress_line();
  if (result.interrupted) {
    std::fprintf(stderr,
                 "springblock: interrupted; %d of %d repetitions had finished. No output file was "
                 "written and existing files are untouched.\n",
                 result.finished_reps, scene.reps);
    return shell::kInterrupted;
  }
  if (nothing_measured(scene, result)) return shell::kNothingMeasured;
  auto j = sb::ensemble_json(scene, result, command_line);
  if (!a.out_path.empty()) shell::write_output(a.out_path, j.dump(2) + "\n");
  if (!a.series_path.empty()) shell::write_output(a.series_path, sb::series_tsv(scene, result, command_line));
  if (a.json)
    std::cout << j.dump() << "\n";
  else
    print_run_text(scene, result);
  std::fflush(stdout);  // the table (stderr) after the results
  if (a.profile) sb::app::print_work_table(result);
  return shell::kOk;
}

void print_theory_text(const sb::theory::SingleBlock& b, const sb::FrictionDistribution& f, double mu_d_pt,
                       const sb::theory::SingleBlockCycle& c, double avg) {
  std::printf("single block: m = %.4g kg, k = K_s = %.4g N/m, v = %.4g m/s, F_n = %.4g N\n", b.m_kg, b.k_N_per_m,
              b.v_m_per_s, b.F_n_N);
  std::printf("mu_s = %.4g, mu_d = %.4g\n", f.mu_s_mean, mu_d_pt);
  std::printf("omega = %.6g rad/s, r0 = %.6g m\n", c.omega, c.r0_m);
  std::printf("T_d = %.6g s (dynamic phase)\nT_s = %.6g s (static phase)\n", c.T_d_s, c.T_s_s);
  std::printf("delta_r = %.6g m (rest offset)\n", c.delta_r_m);
  std::printf("(mu_d)_M = %.6g for these coefficients\n", c.mu_d_macro);
  std::printf("(mu_d)_M = %.6g averaged over mu_s ~ N(%g, %g), mu_d ~ N(%g, %g)\n", avg, f.mu_s_mean, f.mu_s_sd,
              f.mu_d_mean, f.mu_d_sd);
}

int cmd_theory(const TheoryArgs& a) {
  sb::Scene scene;
  a.fields.apply(scene);
  // The closed forms integrate nothing, so no integrator's limits apply: per-block slider springs
  // and masses, which only RK4 takes today, are checked as RK4 checks them.
  if (scene.materials.given() && sb::resolve_materials(scene).mechanical()) scene.run.method = sb::Method::RK4;
  sb::validate(scene);
  const auto p = sb::theory::predict(scene);
  if (a.json) {
    std::cout << nlohmann::json(p).dump(2) << "\n";
    return shell::kOk;
  }
  print_theory_text(p.block, scene.friction, p.mu_d, p.cycle, p.mu_d_macro_gaussian);
  if (p.chain)
    std::printf("(mu_d)_M = %.6g for the chain block by block (%s): mean over its %d contact blocks, each with its own "
                "Gaussians, slider spring and mass (internal springs absent in this limit)\n",
                p.chain->mu_d_macro_gaussian, sb::resolve_materials(scene).source.c_str(), p.chain->n_contact);
  return shell::kOk;
}

CLI::App* add_run_command(CLI::App& app, RunArgs& a) {
  auto* run = app.add_subcommand("run", "run one scene as an ensemble of repetitions");
  a.fields.add_all(run);
  run->add_option("--scene", a.scene_file, "JSON scene file; its keys are the option names with '_' (options override it)");
  run->add_flag("--json", a.json, "print one JSON object on stdout");
  run->add_option("--out", a.out_path, "write the full JSON results to this file (atomically)");
  run->add_option("--series", a.series_path, "write mu(t) and the sliding count of repetition 0 as TSV");
  run->add_flag("--profile", a.profile,
                "time each kind of work (stepping, event location, switching, quiet phases, sampling) and print "
                "the table on stderr; the counts are always in the JSON's runs[].work");
  run->add_flag("--progress", a.progress, "show progress and ETA on stderr even when it is not a terminal");
  run->footer(
      "Exit codes: 0 results printed and written; 2 bad input, named with its allowed range (nothing is "
      "run or written); 3 nothing measured (no repetition slipped, or no sample in the mu_d window; "
      "nothing written); 130 interrupted (nothing written); 1 any other error.");
  return run;
}

CLI::App* add_theory_command(CLI::App& app, TheoryArgs& a) {
  auto* cmd = app.add_subcommand("theory", "closed-form single-block predictions (K_int = 0 limit)");
  a.fields.add_all(cmd);
  cmd->add_flag("--json", a.json, "print JSON");
  return cmd;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"springblock: 1-D spring-block friction model of Costagliola, Bosia & Pugno (PRE 2016).\n"
               "Quantities take unit suffixes (7.2cm, 1e-4ms, 10/ms, 5MPa); bare numbers are SI."};
  app.require_subcommand(1);
  RunArgs run_args;
  TheoryArgs theory_args;
  auto* run = add_run_command(app, run_args);
  const sb::app::PatternCommand pattern(app);  // pattern_command.hpp, shared with springblock_pattern
  add_theory_command(app, theory_args);
  const sb::app::DesignCommand design(app);  // inverse design (design_command.hpp)
  const sb::app::SweepCommand sweep(app);
  if (auto done = shell::parse(app, argc, argv, "springblock", "Run 'springblock --help' or 'springblock run --help'."))
    return *done;
  if (sweep.parsed()) return sweep.run(shell::command_line(argc, argv));
  return shell::guarded("springblock", [&] {
    if (run->parsed()) return cmd_run(run_args, run, shell::command_line(argc, argv));
    if (pattern.parsed()) return pattern.run();
    if (design.parsed()) return design.run(shell::command_line(argc, argv));
    return cmd_theory(theory_args);
  });
}
