#include "common.hpp"

#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <fstream>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <sstream>
#include <stdexcept>

#include "shell/command_line.hpp"
#include "shell/exit_codes.hpp"
#include "shell/field_options.hpp"
#include "shell/interrupt.hpp"
#include "shell/output.hpp"
#include "shell/progress.hpp"
#include "ranks.hpp"
#include "springblock/ensemble.hpp"
#include "springblock/io.hpp"
#include "springblock/scene_fields.hpp"
#include "springblock/surface.hpp"
#include "springblock/errors.hpp"

namespace repro {
namespace shell = sb::shell;
namespace {

// Figure scripts need the stick-slip shape, not 10^5 points per trace.
constexpr std::size_t kMaxSeriesPoints = 40000;

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

using sb::json_number;

nlohmann::json scene_record(const LabelledScene& ls, const sb::EnsembleResult& r, const std::string& cmd) {
  nlohmann::json result = sb::ensemble_json(ls.scene, r, cmd);
  result.erase("provenance");  // the document carries one provenance block
  if (!ls.keep_runs) result.erase("runs");
  if (!ls.keep_scene_echo) result.erase("scene");
  nlohmann::json rec = {{"id", ls.id}, {"label", ls.label}, {"x", ls.x}, {"result", result}};
  if (ls.keep_scene_echo && ls.scene.pattern.kind != sb::SurfaceKind::Random) rec["contact_mask"] = mask_text(ls.scene);
  if (r.runs.empty()) return rec;
  const auto& run0 = r.runs[0];
  if (!run0.series.empty()) {
    const std::size_t stride = (run0.series.size() + kMaxSeriesPoints - 1) / kMaxSeriesPoints;
    nlohmann::json t = nlohmann::json::array(), mu = t, mus = t, ns = t;
    for (std::size_t i = 0; i < run0.series.size(); i += stride) {
      const auto& s = run0.series[i];
      t.push_back(s.t), mu.push_back(json_number(s.mu)), mus.push_back(json_number(s.mu_signed)), ns.push_back(s.n_sliding);
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

std::vector<std::string> given_inputs(const Context& ctx, const std::vector<std::string>& targets) {
  std::vector<std::string> given;
  for (const auto& t : targets) {
    try {
      input_document(ctx, t);
      given.push_back(t);
    } catch (const sb::InputError&) {
    }
  }
  return given;
}

namespace {
LabelledScene::Borrow find_record(const Context& ctx, const std::vector<std::string>& targets, const sb::Scene& scene,
                                  const std::uint64_t* seed) {
  // A random surface draws a fresh mask per repetition: no mask string stands for it.
  if (scene.pattern.kind == sb::SurfaceKind::Random) return {};
  nlohmann::json mine = scene;
  mine = definition_without_seed(mine);
  const std::string mask = mask_text(scene);
  for (const auto& t : targets) {
    const auto& doc = input_document(ctx, t);
    for (const auto& rec : doc.at("scenes")) {
      const auto& def = rec.at("result").at("scene");
      if (seed && !(def.contains("seed") && def.at("seed").is_number_unsigned() &&
                    def.at("seed").get<std::uint64_t>() == *seed))
        continue;
      if (rec.value("contact_mask", "") == mask && definition_without_seed(def) == mine)
        return {t, rec.at("id").get<std::string>(), false};
    }
  }
  return {};
}
}  // namespace

LabelledScene::Borrow find_borrowable(const Context& ctx, const std::vector<std::string>& targets,
                                      const sb::Scene& scene) {
  return find_record(ctx, targets, scene, nullptr);
}

LabelledScene::Borrow find_borrowable(const Context& ctx, const std::vector<std::string>& targets,
                                      const sb::Scene& scene, std::uint64_t seed) {
  return find_record(ctx, targets, scene, &seed);
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

namespace {

// The command line of a target. --method, --threads and --seed are scene fields: the library
// parses and checks them as for `springblock run`, with the same messages.
struct TargetCommandLine {
  CLI::App app;
  shell::FieldOptions fields;
  Options opt;
};

void add_target_options(TargetCommandLine& cl) {
  auto& app = cl.app;
  Options& opt = cl.opt;
  app.add_option("--tier", opt.tier, "paper (20 repetitions, the default), quick (6) or smoke (2, short; pipeline test only)")
      ->check(CLI::IsMember({"paper", "quick", "smoke"}));
  app.add_option("--out", opt.out, "directory for " + opt.target + ".json");
  cl.fields.add(&app, "method", "integrator: event (default; exact switching, adaptive) or rk4 (the paper's fixed step)")
      ->type_name("TEXT");
  cl.fields.add(&app, "threads", "threads over repetitions, 0 to 1024 (0 = all cores, the default)")->type_name("INT");
  cl.fields.add(&app, "seed", "seed of every scene's repetition streams, >= 0 (default 1)")->type_name("UINT");
  app.add_option("--table", opt.table, "published table TSV this target reproduces");
  app.add_option("--input", opt.inputs, "JSON of another target this one reads")->check(CLI::ExistingFile);
  app.add_option("--only", opt.only, "comma-separated scene ids to run (a subset, for debugging)");
  app.add_option("--layout", opt.layout,
                 "pattern layout of every scene (pawl_first, symmetric, groove_first, one_based; per level, comma "
                 "separated; default: the library's, see paper/choices.md)");
}

// The run's context: the scene fields of the command line read back from a scene that starts
// from the Options' defaults. Throws sb::InputError.
Context make_context(const TargetCommandLine& cl) {
  Options opt = cl.opt;
  sb::Scene fields;
  fields.run.method = sb::parse_method(opt.method);
  fields.threads = opt.threads;
  fields.seed = opt.seed;
  cl.fields.apply(fields);
  opt.method = sb::method_name(fields.run.method);
  opt.threads = fields.threads;
  opt.seed = fields.seed;
  return Context(opt, tier_named(opt.tier), fields.run.method);
}

// The driver's scenes, cut to --only, each with its seed, checked.
std::vector<LabelledScene> planned_scenes(const Context& ctx, const PlanFn& plan) {
  const Options& opt = ctx.opt;
  std::vector<LabelledScene> scenes = plan(ctx);
  if (!opt.only.empty()) {
    auto keep = split(opt.only, ',');
    std::set<std::string> wanted(keep.begin(), keep.end());
    std::erase_if(scenes, [&](const LabelledScene& s) { return !wanted.count(s.id); });
    if (scenes.empty()) throw sb::InputError("only", "no scene of " + opt.target + " has id in '" + opt.only + "'");
  }
  for (auto& s : scenes) {
    if (!s.shared_seed) s.scene.seed = scene_seed(opt.seed, s.id);
    sb::validate(s.scene);
  }
  return scenes;
}

// All scenes' repetitions in one pool (sb::run_ensembles): the threads never wait at the end of
// a scene. Borrowed scenes enter the pool only as their one-repetition trace, if they keep one.
struct Pool {
  std::vector<sb::Scene> scenes;
  std::vector<double> weights;   // progress and ETA are over the whole target, scenes weighted by cost()
  std::vector<int> entry;        // scene -> its pool entry, or -1
  std::vector<std::size_t> owner;  // pool entry -> scene
};

Pool make_pool(const Context& ctx, const std::vector<LabelledScene>& scenes) {
  Pool pool;
  pool.entry.assign(scenes.size(), -1);
  for (std::size_t k = 0; k < scenes.size(); ++k) {
    const auto& ls = scenes[k];
    sb::Scene sim = ls.scene;
    if (!ls.borrow.target.empty()) {
      if (!ls.borrow.trace) continue;
      sim.seed = source_record(ctx, ls.borrow).at("result").at("seed").get<std::uint64_t>();
      sim.reps = 1;
      sim.observe.series = true;
    }
    pool.entry[k] = static_cast<int>(pool.scenes.size());
    pool.owner.push_back(k);
    pool.scenes.push_back(sim), pool.weights.push_back(cost(sim));
  }
  return pool;
}

// The pool's results as the document's scene records, one stderr line per scene.
nlohmann::json scene_records(const Context& ctx, const std::vector<LabelledScene>& scenes, const Pool& pool,
                             const std::vector<sb::EnsembleResult>& results) {
  const char* target = ctx.opt.target.c_str();
  nlohmann::json records = nlohmann::json::array();
  // A statistic no repetition contributed to (mu_d of a scene stopped at its first slip) is
  // "not measured", never a printed nan.
  auto stat = [](const sb::Statistic& x) {
    return x.n > 0 ? fmt::format("{:.4f} +- {:.4f}", x.mean, x.sem) : std::string("not measured");
  };
  for (std::size_t k = 0; k < scenes.size(); ++k) {
    const auto& ls = scenes[k];
    if (!ls.borrow.target.empty()) {
      records.push_back(borrowed_record(ctx, ls, pool.entry[k] >= 0 ? &results[pool.entry[k]] : nullptr));
      std::fprintf(stderr, "[%s]   %s: %s/%s%s\n", target, ls.id.c_str(), ls.borrow.target.c_str(),
                   ls.borrow.id.c_str(), ls.borrow.trace ? " (+ trace of repetition 0)" : "");
      continue;
    }
    const auto& result = results[pool.entry[k]];
    std::fprintf(stderr, "[%s]   %s: mu_s = %s, mu_d = %s (%.1fs of the pool)\n", target, ls.id.c_str(),
                 stat(result.mu_s).c_str(), stat(result.mu_d).c_str(), result.wall_s);
    records.push_back(scene_record(ls, result, ctx.opt.command_line));
    // Observed on another scene's simulation (same trajectory, other rules or run length).
    if (result.trajectory_from >= 0) records.back()["trajectory_from"] = scenes[pool.owner[result.trajectory_from]].id;
  }
  return records;
}

nlohmann::json target_document(const Context& ctx, nlohmann::json records) {
  const Options& opt = ctx.opt;
  return {{"target", opt.target},
          {"tier", ctx.tier.name},
          {"method", sb::method_name(ctx.method)},
          {"method_requested", opt.method},
          {"reps", ctx.tier.reps},
          {"tier_reps", tier_reps_json()},
          {"duration_t0", ctx.tier.duration_t0},
          {"seed", opt.seed},
          {"layout", ctx.base_scene().pattern.layout_text()},
          {"provenance", sb::provenance(opt.command_line)},
          {"scenes", std::move(records)}};
}

std::string output_path(const Options& opt) { return opt.out + "/" + opt.target + ".json"; }

using Clock = std::chrono::steady_clock;

// What a target runs, once its input is read: under mpirun on rank 0, with the other ranks.
struct Prepared {
  std::optional<Context> ctx;
  std::vector<LabelledScene> scenes;
  Pool pool;
  std::unique_ptr<sb::parallel::Scheduler> ranks;  // under mpirun only; ends MPI when it goes
};

// Runs the pool with progress and ETA, on this process's threads or, under mpirun, dealt to the
// ranks, then writes the document; nothing when interrupted.
int simulate_and_write(const Prepared& prepared, const FinishFn& finish, Clock::time_point wall0) {
  const Context& ctx = *prepared.ctx;
  const auto& scenes = prepared.scenes;
  const Pool& pool = prepared.pool;
  sb::parallel::Scheduler* ranks = prepared.ranks.get();
  const std::string& target = ctx.opt.target;
  const auto* interrupt = shell::catch_interrupts();
  auto progress = [&](double f, double elapsed) {
    const std::string eta = f > 0.01 ? shell::format_seconds(shell::eta_seconds(f, elapsed)) : "?";
    shell::show_progress(fmt::format("[{}] {} scenes, {:5.1f}% elapsed {} ETA {}", target, pool.scenes.size(), 100 * f,
                                     shell::format_seconds(elapsed), eta));
  };
  progress(0, 0);
  const auto results = run_scenes(ranks, pool.scenes, interrupt, progress, pool.weights);
  shell::end_progress_line();
  for (const auto& r : results)
    if (r.interrupted) {
      std::fprintf(stderr, "%s: interrupted; nothing written, existing output untouched\n", target.c_str());
      std::fflush(stderr);
      if (ranks) ranks->abort(shell::kInterrupted);  // the other ranks stop too
      return shell::kInterrupted;
    }
  nlohmann::json doc = target_document(ctx, scene_records(ctx, scenes, pool, results));
  // How many processes ran it; the numbers are the same whatever the count.
  doc["provenance"]["ranks"] = ranks ? ranks->ranks() : 1;
  if (finish) finish(ctx, doc);
  doc["wall_seconds"] = std::chrono::duration<double>(Clock::now() - wall0).count();
  const std::string path = output_path(ctx.opt);
  shell::write_output(path, doc.dump(1) + "\n");
  std::fprintf(stderr, "[%s] wrote %s in %s\n", target.c_str(), path.c_str(),
               shell::format_seconds(doc["wall_seconds"].get<double>()).c_str());
  return shell::kOk;
}

// Setup reads tables and other targets' documents: any failure there is the input's (exit 2).
// Under mpirun, rank 0 alone plans, claims the output and makes the pool, and then tells the
// other ranks whether to go on: nothing that can fail on rank 0 comes between that and the run,
// where they wait for it.
int set_up(const TargetCommandLine& cl, const PlanFn& plan, Prepared& p) {
  return shell::guarded(cl.opt.target, [&] {
    p.ctx.emplace(make_context(cl));
    p.ranks = target_ranks(p.ctx->opt.threads);
    std::exception_ptr refused;
    try {
      p.scenes = planned_scenes(*p.ctx, plan);
      // The output is claimed now, not after the run: a bad --out fails before any simulation.
      shell::make_output_directory(p.ctx->opt.out, "out");
      shell::claim_output(output_path(p.ctx->opt), "out");
      p.pool = make_pool(*p.ctx, p.scenes);
    } catch (...) {
      refused = std::current_exception();
    }
    if (p.ranks) p.ranks->agree(!refused);
    if (refused) std::rethrow_exception(refused);
    return int{shell::kOk};
  }, {"cannot set up", shell::kBadInput});
}

}  // namespace

int run_target(int argc, char** argv, const std::string& target, const std::string& summary, const PlanFn& plan,
               const FinishFn& finish) {
  TargetCommandLine cl{CLI::App{target + ": " + summary}, {}, {}};
  cl.opt.target = target;
  cl.opt.command_line = shell::command_line(argc, argv);
  add_target_options(cl);
  const bool speaks = speaking_rank();  // under mpirun, the other ranks read the same options quietly
  if (auto done = shell::parse(cl.app, argc, argv, target, "Run '" + std::string(argv[0]) + " --help' for the options.",
                               !speaks))
    return *done;
  if (!speaks) {
    int threads = 0;
    try {
      threads = make_context(cl).opt.threads;
    } catch (const std::exception&) {
      return shell::kBadInput;  // rank 0 finds the same and says why
    }
    return run_worker_rank(threads);
  }

  const auto wall0 = Clock::now();
  Prepared prepared;
  const int setup = set_up(cl, plan, prepared);
  if (setup != shell::kOk) return setup;
  return shell::guarded(target, [&] { return simulate_and_write(prepared, finish, wall0); });
}

}  // namespace repro
