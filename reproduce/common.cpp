#include "common.hpp"

#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <atomic>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>

#include "springblock/ensemble.hpp"
#include "springblock/integrate/integrator.hpp"
#include "springblock/io.hpp"
#include "springblock/scene_fields.hpp"
#include "springblock/surface.hpp"
#include "springblock/errors.hpp"

namespace repro {
namespace {

std::atomic<bool> g_interrupt{false};
extern "C" void on_signal(int) { g_interrupt.store(true); }

// Figure scripts need the stick-slip shape, not 10^5 points per trace.
constexpr std::size_t kMaxSeriesPoints = 40000;

std::string join_args(int argc, char** argv) {
  std::string s;
  for (int i = 0; i < argc; ++i) s += (i ? " " : "") + std::string(argv[i]);
  return s;
}

// The event integrator is being written alongside this code; until the factory knows it we
// fall back to the paper's RK4 rather than refuse to run, and say so where it will be seen.
sb::Method resolve_method(const std::string& requested, const std::string& target) {
  sb::Method m = sb::parse_method(requested);
  if (m != sb::Method::Event) return m;
  sb::RunControl probe;
  probe.method = sb::Method::Event;
  try {
    (void)sb::make_integrator(probe);
    return m;
  } catch (const sb::InputError& e) {
    std::fprintf(stderr, "%s: warning: method 'event' is not available (%s); using rk4\n", target.c_str(),
                 e.what());
    return sb::Method::RK4;
  }
}

std::string format_seconds(double s) {
  char buf[32];
  if (s < 120) std::snprintf(buf, sizeof buf, "%.0fs", s);
  else if (s < 7200) std::snprintf(buf, sizeof buf, "%.1fmin", s / 60);
  else std::snprintf(buf, sizeof buf, "%.1fh", s / 3600);
  return buf;
}

// Repetitions of every tier, so a reader of one tier's results can say what another would resolve.
nlohmann::json tier_reps_json() {
  nlohmann::json j = nlohmann::json::object();
  for (const auto& t : tiers()) j[t.name] = t.reps;
  return j;
}

// Relative cost of a scene for the overall ETA: simulated block-seconds over all repetitions.
double cost(const sb::Scene& s) { return s.reps * s.duration() * s.geometry.N; }

std::string mask_text(const sb::Scene& s) {
  std::string m;
  for (auto b : sb::build_contact_mask(s.pattern, s.geometry.N, 0)) m += b ? '1' : '0';
  return m;
}

// What decides a scene's trajectories and extraction, less the seed and the pattern's spelling.
nlohmann::json definition_without_seed(nlohmann::json j) {
  j.erase("seed");
  j.erase("pattern");
  return j;
}

nlohmann::json num(double x) { return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(nullptr); }

nlohmann::json scene_record(const LabelledScene& ls, const sb::EnsembleResult& r, const std::string& cmd) {
  nlohmann::json result = sb::ensemble_json(ls.scene, r, cmd);
  result.erase("provenance");  // the document carries one provenance block
  if (!ls.keep_runs) result.erase("runs");
  nlohmann::json rec = {{"id", ls.id}, {"label", ls.label}, {"x", ls.x}, {"result", result}};
  if (ls.scene.pattern.kind != sb::SurfaceKind::Random) rec["contact_mask"] = mask_text(ls.scene);
  if (r.runs.empty()) return rec;
  const auto& run0 = r.runs[0];
  if (!run0.series.empty()) {
    const std::size_t stride = (run0.series.size() + kMaxSeriesPoints - 1) / kMaxSeriesPoints;
    nlohmann::json t = nlohmann::json::array(), mu = t, mus = t, ns = t;
    for (std::size_t i = 0; i < run0.series.size(); i += stride) {
      const auto& s = run0.series[i];
      t.push_back(s.t), mu.push_back(num(s.mu)), mus.push_back(num(s.mu_signed)), ns.push_back(s.n_sliding);
    }
    rec["series"] = {{"t_s", t}, {"mu", mu}, {"mu_signed", mus}, {"n_sliding", ns}, {"stride", stride}};
  }
  if (!run0.stress.empty()) {
    nlohmann::json st = nlohmann::json::array();
    for (const auto& snap : run0.stress)
      st.push_back({{"t_s", snap.t}, {"sigma_over_P", snap.sigma_over_P}, {"f_over_Fn", snap.f_over_Fn}});
    rec["stress"] = st;
  }
  return rec;
}


std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> out;
  std::stringstream in(s);
  std::string piece;
  while (std::getline(in, piece, sep)) out.push_back(piece);
  return out;
}

}  // namespace

const std::vector<Tier>& tiers() {
  static const std::vector<Tier> all = {{"paper", 20, 4.0, false}, {"quick", 6, 4.0, false}, {"smoke", 2, 2.0, true}};
  return all;
}

// Seed of one scene: FNV-1a of its id folded into the run's seed, mixed once more.
std::uint64_t scene_seed(std::uint64_t seed, const std::string& id) {
  std::uint64_t h = 1469598103934665603ULL;
  for (unsigned char c : id) h = (h ^ c) * 1099511628211ULL;
  return sb::rep_seed(seed ^ h, 0) >> 1;  // keep it printable as a signed 64-bit integer
}

Tier tier_named(const std::string& name) {
  for (const auto& t : tiers())
    if (t.name == name) return t;
  throw sb::InputError("tier", "'" + name + "' is not one of: paper, quick, smoke");
}

sb::Scene Context::base_scene() const {
  sb::Scene s;
  s.run.method = method;
  s.reps = tier.reps;
  s.run.duration_t0 = tier.duration_t0;
  s.seed = opt.seed;
  s.threads = opt.threads;
  // Before any pattern is set: the pattern field keeps the layout it finds.
  if (!opt.layout.empty()) s.pattern.layout = sb::parse_layout(opt.layout);
  return s;
}

void set(sb::Scene& s, const std::string& key, const std::string& value) { sb::set_scene_field(s, key, value); }

sb::Scene Context::chain(int N, const std::string& length, const std::string& pattern) const {
  sb::Scene s = base_scene();
  set(s, "N", std::to_string(N));
  set(s, "length", length);
  set(s, "pattern", pattern);
  return s;
}

nlohmann::json read_json(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot open " + path);
  try {
    return nlohmann::json::parse(in);
  } catch (const nlohmann::json::exception& e) {
    throw std::runtime_error(path + " is not valid JSON: " + e.what());
  }
}

const nlohmann::json& input_document(const Context& ctx, const std::string& target) {
  // A table's document is megabytes and a driver may ask for it once per scene it borrows.
  static std::map<std::string, nlohmann::json> cache;
  for (const auto& path : ctx.opt.inputs) {
    auto it = cache.find(path);
    if (it == cache.end()) it = cache.emplace(path, read_json(path)).first;
    if (it->second.value("target", "") == target) return it->second;
  }
  throw sb::InputError("input", ctx.opt.target + " needs --input <" + target + ".json>");
}

namespace {
const nlohmann::json& source_record(const Context& ctx, const LabelledScene::Borrow& b) {
  static std::map<std::pair<std::string, std::string>, nlohmann::json> records;
  auto it = records.find({b.target, b.id});
  if (it != records.end()) return it->second;
  const auto& doc = input_document(ctx, b.target);
  for (const auto& rec : doc.at("scenes"))
    if (rec.at("id") == b.id) return records.emplace(std::pair{b.target, b.id}, rec).first->second;
  throw sb::InputError("input", b.target + ".json has no scene '" + b.id + "'");
}

// The source's record under our id, label and coordinates. A trace must be the source's
// repetition 0 again (same seed, same scene): the same first slip to the last bit. Its mu_s and
// mu_d may differ in the last bits only: keeping a series makes the observer evaluate every
// sample one by one where the table's run took quiet stretches in closed form (affine sums).
nlohmann::json borrowed_record(const Context& ctx, const LabelledScene& ls, const sb::EnsembleResult* trace) {
  nlohmann::json rec = source_record(ctx, ls.borrow);
  rec.erase("trajectory_from");  // an id of the source target, meaningless here
  rec["id"] = ls.id, rec["label"] = ls.label, rec["x"] = ls.x;
  rec["borrowed_from"] = ls.borrow.target + "/" + ls.borrow.id;
  if (!trace) return rec;
  const auto& run0 = rec.at("result").at("runs").at(0);
  const auto& mine = trace->runs.at(0);
  auto value = [](const nlohmann::json& a) { return a.is_null() ? std::nan("") : a.get<double>(); };
  auto same = [&](const nlohmann::json& a, double b, double rel) {
    const double x = value(a);
    return std::isnan(x) ? std::isnan(b) : std::fabs(x - b) <= rel * std::fabs(x);
  };
  if (!same(run0.at("mu_s"), mine.mu_s, 1e-12) || !same(run0.at("t_slip_s"), mine.t_slip_s, 0) ||
      !same(run0.at("mu_d"), mine.mu_d, 1e-12))
    throw std::runtime_error(fmt::format("{}: the trace is not repetition 0 of {} (mu_s {} vs {}, t_slip {} vs {}, mu_d {} vs {})",
                                         ls.id, rec["borrowed_from"].get<std::string>(), mine.mu_s,
                                         value(run0.at("mu_s")), mine.t_slip_s, value(run0.at("t_slip_s")),
                                         mine.mu_d, value(run0.at("mu_d"))));
  nlohmann::json traced = scene_record(ls, *trace, "");
  rec["series"] = traced.at("series");
  return rec;
}
}  // namespace

LabelledScene::Borrow find_borrowable(const Context& ctx, const std::vector<std::string>& targets,
                                      const sb::Scene& scene) {
  // A random surface draws a fresh mask per repetition: no mask string stands for it.
  if (scene.pattern.kind == sb::SurfaceKind::Random) return {};
  nlohmann::json mine = scene;
  mine = definition_without_seed(mine);
  const std::string mask = mask_text(scene);
  for (const auto& t : targets) {
    const auto& doc = input_document(ctx, t);
    for (const auto& rec : doc.at("scenes"))
      if (rec.value("contact_mask", "") == mask && definition_without_seed(rec.at("result").at("scene")) == mine)
        return {t, rec.at("id").get<std::string>(), false};
  }
  return {};
}

PatternShape pattern_shape(const std::string& spec) {
  PatternShape shape;
  const auto p = sb::parse_pattern(spec);
  if (p.kind == sb::SurfaceKind::Periodic) shape.n_p = p.n_p, shape.grooves = {p.n_g};
  if (p.kind == sb::SurfaceKind::Hierarchical) shape.grooves = p.levels;
  return shape;
}

std::vector<TableRow> read_table(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot open table " + path);
  std::string line;
  std::map<std::string, std::size_t> col;
  std::vector<TableRow> rows;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    auto f = split(line, '\t');
    if (col.empty()) {
      for (std::size_t i = 0; i < f.size(); ++i) col[f[i]] = i;
      for (const char* need : {"row_id", "pattern", "N", "L_x_cm", "S_over_Stot_num", "S_over_Stot_den", "mu_s",
                               "mu_s_err", "mu_d", "mu_d_err"})
        if (!col.count(need)) throw std::runtime_error(path + ": missing column " + need);
      continue;
    }
    auto get = [&](const char* k) -> const std::string& {
      if (col.at(k) >= f.size()) throw std::runtime_error(path + ": short row: " + line);
      return f[col.at(k)];
    };
    TableRow r;
    r.row_id = get("row_id");
    r.pattern = get("pattern");
    r.N = std::stoi(get("N"));
    r.L_x_cm = std::stod(get("L_x_cm"));
    r.S_num = std::stod(get("S_over_Stot_num"));
    r.S_den = std::stod(get("S_over_Stot_den"));
    r.mu_s = std::stod(get("mu_s"));
    r.mu_s_err = std::stod(get("mu_s_err"));
    r.mu_d = std::stod(get("mu_d"));
    r.mu_d_err = std::stod(get("mu_d_err"));
    rows.push_back(r);
  }
  if (rows.empty()) throw std::runtime_error(path + ": no data rows");
  return rows;
}

int run_target(int argc, char** argv, const std::string& target, const std::string& summary, const PlanFn& plan,
               const FinishFn& finish) {
  Options opt;
  opt.target = target;
  opt.command_line = join_args(argc, argv);
  CLI::App app{target + ": " + summary};
  app.add_option("--tier", opt.tier, "paper (20 repetitions, the default), quick (6) or smoke (2, short; pipeline test only)")
      ->check(CLI::IsMember({"paper", "quick", "smoke"}));
  app.add_option("--out", opt.out, "directory for " + target + ".json");
  app.add_option("--method", opt.method, "integrator: event (default; falls back to rk4 if absent) or rk4")
      ->check(CLI::IsMember({"event", "rk4"}));
  app.add_option("--threads", opt.threads, "OpenMP threads over repetitions (0 = all cores)")
      ->check(CLI::Range(0, 1024));
  app.add_option("--seed", opt.seed, "seed of every scene's repetition streams");
  app.add_option("--table", opt.table, "published table TSV this target reproduces");
  app.add_option("--input", opt.inputs, "JSON of another target this one reads")->check(CLI::ExistingFile);
  app.add_option("--only", opt.only, "comma-separated scene ids to run (a subset, for debugging)");
  app.add_option("--layout", opt.layout,
                 "pattern layout of every scene (pawl_first, symmetric, groove_first, one_based; per level, comma "
                 "separated; default: the library's, see paper/choices.md)");
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::fprintf(stderr, "%s: %s\nRun '%s --help' for the options.\n", target.c_str(), e.what(), argv[0]);
    return 2;
  }

  const auto wall0 = std::chrono::steady_clock::now();
  std::vector<LabelledScene> scenes;
  Tier tier;
  sb::Method method;
  try {
    tier = tier_named(opt.tier);
    method = resolve_method(opt.method, target);
    Context ctx(opt, tier, method);
    scenes = plan(ctx);
    if (!opt.only.empty()) {
      auto keep = split(opt.only, ',');
      std::set<std::string> wanted(keep.begin(), keep.end());
      std::erase_if(scenes, [&](const LabelledScene& s) { return !wanted.count(s.id); });
      if (scenes.empty()) throw sb::InputError("only", "no scene of " + target + " has id in '" + opt.only + "'");
    }
    for (auto& s : scenes) {
      if (!s.shared_seed) s.scene.seed = scene_seed(opt.seed, s.id);
      sb::validate(s.scene);
    }
  } catch (const sb::InputError& e) {
    std::fprintf(stderr, "%s: invalid %s: %s\n", target.c_str(), e.field.c_str(), e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s: cannot set up: %s\n", target.c_str(), e.what());
    return 2;
  }

  std::signal(SIGINT, on_signal);
  std::signal(SIGTERM, on_signal);
  nlohmann::json records = nlohmann::json::array();
  try {
    // All scenes' repetitions in one pool (sb::run_ensembles): the threads never wait at the
    // end of a scene. Progress and ETA are over the whole target, scenes weighted by cost().
    // Borrowed scenes enter the pool only as their one-repetition trace, if they keep one.
    std::vector<sb::Scene> pool;
    std::vector<double> weights;
    std::vector<int> pooled(scenes.size(), -1);  // scene -> its pool entry
    std::vector<std::size_t> owner;              // pool entry -> scene
    const Context ctx(opt, tier, method);
    for (std::size_t k = 0; k < scenes.size(); ++k) {
      const auto& ls = scenes[k];
      sb::Scene sim = ls.scene;
      if (!ls.borrow.target.empty()) {
        if (!ls.borrow.trace) continue;
        sim.seed = source_record(ctx, ls.borrow).at("result").at("seed").get<std::uint64_t>();
        sim.reps = 1;
        sim.observe.series = true;
      }
      pooled[k] = static_cast<int>(pool.size());
      owner.push_back(k);
      pool.push_back(sim), weights.push_back(cost(sim));
    }
    auto progress = [&](double f, double elapsed) {
      const std::string eta = f > 0.01 ? format_seconds(elapsed * (1 - f) / f) : "?";
      std::fprintf(stderr, "\r[%s] %zu scenes, %5.1f%% elapsed %s ETA %s   ", target.c_str(), pool.size(),
                   100 * f, format_seconds(elapsed).c_str(), eta.c_str());
      std::fflush(stderr);
    };
    progress(0, 0);
    auto results = sb::run_ensembles(pool, &g_interrupt, progress, weights);
    for (const auto& r : results)
      if (r.interrupted) {
        std::fprintf(stderr, "\n%s: interrupted; nothing written, existing output untouched\n", target.c_str());
        return 130;
      }
    std::fprintf(stderr, "\n");
    for (std::size_t k = 0; k < scenes.size(); ++k) {
      const auto& ls = scenes[k];
      if (!ls.borrow.target.empty()) {
        records.push_back(borrowed_record(ctx, ls, pooled[k] >= 0 ? &results[pooled[k]] : nullptr));
        std::fprintf(stderr, "[%s]   %s: %s/%s%s\n", target.c_str(), ls.id.c_str(), ls.borrow.target.c_str(),
                     ls.borrow.id.c_str(), ls.borrow.trace ? " (+ trace of repetition 0)" : "");
        continue;
      }
      const auto& result = results[pooled[k]];
      // A statistic no repetition contributed to (mu_d of a scene stopped at its first slip) is
      // "not measured", never a printed nan.
      auto stat = [](const sb::Statistic& x) {
        return x.n > 0 ? fmt::format("{:.4f} +- {:.4f}", x.mean, x.sem) : std::string("not measured");
      };
      std::fprintf(stderr, "[%s]   %s: mu_s = %s, mu_d = %s (%.1fs of the pool)\n", target.c_str(), ls.id.c_str(),
                   stat(result.mu_s).c_str(), stat(result.mu_d).c_str(), result.wall_s);
      records.push_back(scene_record(ls, result, opt.command_line));
      // Observed on another scene's simulation (same trajectory, other rules or run length).
      if (result.trajectory_from >= 0) records.back()["trajectory_from"] = scenes[owner[result.trajectory_from]].id;
    }
    const Tier& t = tier;
    nlohmann::json doc = {{"target", target},
                          {"tier", t.name},
                          {"method", sb::method_name(method)},
                          {"method_requested", opt.method},
                          {"reps", t.reps},
                          {"tier_reps", tier_reps_json()},
                          {"duration_t0", t.duration_t0},
                          {"seed", opt.seed},
                          {"layout", ctx.base_scene().pattern.layout_text()},
                          {"provenance", sb::provenance(opt.command_line)},
                          {"scenes", records}};
    if (finish) finish(Context(opt, tier, method), doc);
    doc["wall_seconds"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
    std::filesystem::create_directories(opt.out);
    const std::string path = opt.out + "/" + target + ".json";
    sb::write_file_atomic(path, doc.dump(1) + "\n");
    std::fprintf(stderr, "[%s] wrote %s in %s\n", target.c_str(), path.c_str(),
                 format_seconds(doc["wall_seconds"].get<double>()).c_str());
  } catch (const sb::InputError& e) {
    std::fprintf(stderr, "\n%s: invalid %s: %s\n", target.c_str(), e.field.c_str(), e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "\n%s: error: %s\n", target.c_str(), e.what());
    return 1;
  }
  return 0;
}

}  // namespace repro
