// springblock: command-line front end. It only parses arguments and calls the library.
#include <CLI/CLI.hpp>
#include <atomic>
#include <csignal>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <unistd.h>

#include "springblock/ensemble.hpp"
#include "springblock/io.hpp"
#include "springblock/scene.hpp"
#include "springblock/scene_fields.hpp"
#include "springblock/theory.hpp"
#include "springblock/errors.hpp"

namespace {

std::atomic<bool> g_interrupt{false};
extern "C" void on_signal(int) { g_interrupt.store(true); }

std::string option_name(const std::string& key) {
  std::string o = key;
  for (auto& ch : o)
    if (ch == '_') ch = '-';
  return "--" + o;
}

std::string join_args(int argc, char** argv) {
  std::string s;
  for (int i = 0; i < argc; ++i) s += (i ? " " : "") + std::string(argv[i]);
  return s;
}

// Collects each scene field given on the command line as raw text; the library parses it.
struct FieldOptions {
  std::map<std::string, std::string> values;
  void add_to(CLI::App* app) {
    for (const auto& f : sb::scene_fields())
      app->add_option(option_name(f.key), values[f.key], f.help + " (e.g. " + f.example + ")");
  }
  void apply(sb::Scene& scene, CLI::App* app) const {
    for (const auto& f : sb::scene_fields())
      if (app->count(option_name(f.key)) > 0) sb::set_scene_field(scene, f.key, values.at(f.key));
  }
};

sb::Scene load_scene_file(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw sb::InputError("scene", "cannot open scene file '" + path + "'");
  nlohmann::json j;
  try {
    in >> j;
  } catch (const nlohmann::json::exception& e) {
    throw sb::InputError("scene", "'" + path + "' is not valid JSON: " + e.what());
  }
  sb::Scene s;
  sb::apply_scene_json(s, j);
  return s;
}

void print_progress(double fraction, double elapsed) {
  if (fraction <= 0) return;
  const double eta = elapsed * (1 - fraction) / fraction;
  std::fprintf(stderr, "\rspringblock: %5.1f%% done, %.0f s elapsed, ETA %.0f s   ", 100 * fraction, elapsed, eta);
  std::fflush(stderr);
}

// A statistic over no repetitions prints why instead of a NaN.
void print_statistic(const char* name, const sb::Statistic& st, const std::string& not_measured) {
  if (st.n == 0)
    std::printf("%s: not measured (%s)\n", name, not_measured.c_str());
  else
    std::printf("%s = %.4f +- %.4f (sd %.4f, n=%d)\n", name, st.mean, st.sem, st.std, st.n);
}

int cmd_run(const FieldOptions& fields, CLI::App* app, const std::string& scene_file, bool json,
            const std::string& out_path, const std::string& series_path, bool progress,
            const std::string& command_line) {
  sb::Scene scene = scene_file.empty() ? sb::Scene{} : load_scene_file(scene_file);
  fields.apply(scene, app);
  if (app->count("--series") > 0) scene.observe.series = true;
  sb::validate(scene);
  // Output paths are checked before the run, not after minutes of simulation.
  if (app->count("--out") > 0) sb::check_writable(out_path, "out");
  if (app->count("--series") > 0) {
    if (series_path == out_path)
      throw sb::InputError("series", "'" + series_path + "' is also the --out file; give another file");
    sb::check_writable(series_path, "series");
  }

  std::signal(SIGINT, on_signal);
  std::signal(SIGTERM, on_signal);
  const bool show = progress || ::isatty(STDERR_FILENO);
  auto result = sb::run_ensemble(scene, &g_interrupt, show ? print_progress : std::function<void(double, double)>{});
  if (show) std::fprintf(stderr, "\n");
  if (result.interrupted) {
    std::fprintf(stderr,
                 "springblock: interrupted; %d of %d repetitions had finished. No output file was "
                 "written and existing files are untouched.\n",
                 result.finished_reps, scene.reps);
    return 130;
  }
  const char* loading_end = scene.rules.peak_rule == sb::ExtractionRules::PeakRule::AllSlipped
                                ? "not every contact block slid"
                                : "mu(t) never fell peak_drop below its running maximum";
  const double T = scene.duration(), t0 = scene.t0_s();
  // Nothing measured: an error, not a result of NaNs. Exit 3 (known only after the run; bad input
  // is 2) and write nothing.
  if (result.mu_s.n == 0) {
    std::fprintf(stderr,
                 "springblock: nothing measured: no repetition (of %d) ended its loading phase (%s) "
                 "before the end of the run (duration = %g s = %g t0), so mu_s and mu_d are undefined. "
                 "Lengthen --duration%s. No output file was written.\n",
                 scene.reps, loading_end, T, T / t0,
                 scene.rules.peak_rule == sb::ExtractionRules::PeakRule::Drop ? " or lower --peak-drop" : "");
    return 3;
  }
  if (!scene.run.stop_after_mu_s && result.mu_d.n == 0) {
    std::fprintf(stderr,
                 "springblock: nothing measured: no repetition had a sample in its mu_d window (from the "
                 "first slip + mu_d_skip = %g t0 to the end of the run, duration = %g t0), so mu_d is "
                 "undefined. Lower --mu-d-skip or lengthen --duration. No output file was written.\n",
                 scene.rules.mu_d_skip_t0, T / t0);
    return 3;
  }
  if (result.mu_s.n < scene.reps)
    std::fprintf(stderr,
                 "springblock: warning: %d of %d repetitions never ended their loading phase (%s) before "
                 "the end of the run; their mu_s and mu_d are undefined (null). Lengthen --duration.\n",
                 scene.reps - result.mu_s.n, scene.reps, loading_end);
  if (!scene.run.stop_after_mu_s && result.mu_d.n < result.mu_s.n)
    std::fprintf(stderr,
                 "springblock: warning: %d of %d repetitions that slipped had no sample in their mu_d window; "
                 "their mu_d is undefined (null). Lower --mu-d-skip or lengthen --duration.\n",
                 result.mu_s.n - result.mu_d.n, result.mu_s.n);
  auto j = sb::ensemble_json(scene, result, command_line);
  if (!out_path.empty()) sb::write_file_atomic(out_path, j.dump(2) + "\n");
  if (!series_path.empty()) sb::write_file_atomic(series_path, sb::series_tsv(scene, result, command_line));
  if (json) {
    std::cout << j.dump() << "\n";
  } else {
    std::printf("scene: N=%d L_x=%g m pattern=%s contact fraction=%.6g method=%s reps=%d seed=%llu\n",
                scene.geometry.N, scene.geometry.L_x_m, scene.pattern.text().c_str(), result.contact_fraction,
                sb::method_name(scene.run.method).c_str(), scene.reps, (unsigned long long)scene.seed);
    print_statistic("mu_s", result.mu_s, sb::not_measured(scene, result, "mu_s"));
    print_statistic("mu_d", result.mu_d, sb::not_measured(scene, result, "mu_d"));
    std::printf("wall time %.2f s on %d threads\n", result.wall_s, result.threads);
  }
  return 0;
}

int cmd_theory(const FieldOptions& fields, CLI::App* app, bool json) {
  sb::Scene scene;
  fields.apply(scene, app);
  sb::validate(scene);
  const auto d = scene.derived();
  const int N = scene.geometry.N;
  // The single block of the K_int = 0 limit: one block's mass and slider spring, and its share
  // of the load on a surface where every block is in contact.
  sb::theory::SingleBlock b{d.m_kg, d.K_s_N_per_m, scene.material.v_m_per_s, d.F_load_N / N};
  const auto& f = scene.friction;
  const double mu_d_pt = std::min(f.mu_d_mean, f.mu_s_mean);
  auto c = sb::theory::cycle(b, f.mu_s_mean, mu_d_pt);
  const double avg = sb::theory::mu_d_macro_gaussian(b, f.mu_s_mean, f.mu_s_sd, f.mu_d_mean, f.mu_d_sd);
  nlohmann::json j = {{"block", {{"m_kg", b.m_kg}, {"k_N_per_m", b.k_N_per_m}, {"v_m_per_s", b.v_m_per_s}, {"F_n_N", b.F_n_N}}},
                      {"mu_s", f.mu_s_mean}, {"mu_d", mu_d_pt},
                      {"omega_rad_per_s", c.omega}, {"r0_m", c.r0_m}, {"T_d_s", c.T_d_s},
                      {"delta_r_m", c.delta_r_m}, {"T_s_s", c.T_s_s},
                      {"F_stat_mean_over_Fn", c.F_stat_mean_over_Fn}, {"mu_d_macro", c.mu_d_macro},
                      {"mu_d_macro_gaussian", avg},
                      {"gaussian", {{"mu_s_sd", f.mu_s_sd}, {"mu_d_sd", f.mu_d_sd}}}};
  if (json) {
    std::cout << j.dump(2) << "\n";
  } else {
    std::printf("single block: m = %.4g kg, k = K_s = %.4g N/m, v = %.4g m/s, F_n = %.4g N\n", b.m_kg,
                b.k_N_per_m, b.v_m_per_s, b.F_n_N);
    std::printf("mu_s = %.4g, mu_d = %.4g\n", f.mu_s_mean, mu_d_pt);
    std::printf("omega = %.6g rad/s, r0 = %.6g m\n", c.omega, c.r0_m);
    std::printf("T_d = %.6g s (dynamic phase)\nT_s = %.6g s (static phase)\n", c.T_d_s, c.T_s_s);
    std::printf("delta_r = %.6g m (rest offset)\n", c.delta_r_m);
    std::printf("(mu_d)_M = %.6g for these coefficients\n", c.mu_d_macro);
    std::printf("(mu_d)_M = %.6g averaged over mu_s ~ N(%g, %g), mu_d ~ N(%g, %g)\n", avg, f.mu_s_mean,
                f.mu_s_sd, f.mu_d_mean, f.mu_d_sd);
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"springblock: 1-D spring-block friction model of Costagliola, Bosia & Pugno (PRE 2016).\n"
               "Quantities take unit suffixes (7.2cm, 1e-4ms, 10/ms, 5MPa); bare numbers are SI."};
  app.require_subcommand(1);
  FieldOptions run_fields, theory_fields;
  std::string scene_file, out_path, series_path;
  bool json = false, progress = false;
  auto* run = app.add_subcommand("run", "run one scene as an ensemble of repetitions");
  run_fields.add_to(run);
  run->add_option("--scene", scene_file, "JSON scene file; its keys are the option names with '_' (options override it)");
  run->add_flag("--json", json, "print one JSON object on stdout");
  run->add_option("--out", out_path, "write the full JSON results to this file (atomically)");
  run->add_option("--series", series_path, "write mu(t) and the sliding count of repetition 0 as TSV");
  run->add_flag("--progress", progress, "show progress and ETA on stderr even when it is not a terminal");
  run->footer(
      "Exit codes: 0 results printed and written; 2 bad input, named with its allowed range (nothing is "
      "run or written); 3 nothing measured (no repetition slipped, or no sample in the mu_d window; "
      "nothing written); 130 interrupted (nothing written); 1 any other error.");
  int pattern_N = 120;
  std::string pattern_spec = "smooth";
  auto* pattern_cmd = app.add_subcommand("pattern", "print a surface's contact mask (1 = pawl, 0 = groove) and S/S_tot");
  pattern_cmd->add_option("--N", pattern_N, "number of blocks")->check(CLI::Range(1, 1000000));
  pattern_cmd->add_option("--pattern", pattern_spec, "smooth | periodic:NP,NG | hierarchical:G1,G2,... | random:FRACTION");
  std::string pattern_layout = sb::PatternSpec{}.layout_text();
  pattern_cmd->add_option("--layout", pattern_layout, "pawl_first | symmetric | groove_first | one_based (per level, comma separated)")
      ->default_str(pattern_layout);
  bool theory_json = false;
  auto* theory = app.add_subcommand("theory", "closed-form single-block predictions (K_int = 0 limit)");
  theory_fields.add_to(theory);
  theory->add_flag("--json", theory_json, "print JSON");

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::fprintf(stderr, "springblock: %s\nRun 'springblock --help' or 'springblock run --help'.\n", e.what());
    return 2;
  }
  try {
    if (run->parsed())
      return cmd_run(run_fields, run, scene_file, json, out_path, series_path, progress, join_args(argc, argv));
    if (pattern_cmd->parsed()) {
      auto spec = sb::parse_pattern(pattern_spec);
      spec.layout = sb::parse_layout(pattern_layout);
      auto mask = sb::build_contact_mask(spec, pattern_N, 1);
      for (auto m : mask) std::putchar(m ? '1' : '0');
      std::printf("\n%.17g\n", sb::contact_fraction(mask));
      return 0;
    }
    return cmd_theory(theory_fields, theory, theory_json);
  } catch (const sb::InputError& e) {
    // what() already starts with the field name: "pattern: unknown pattern kind ..."
    std::fprintf(stderr, "springblock: invalid %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "springblock: error: %s\n", e.what());
    return 1;
  }
}
