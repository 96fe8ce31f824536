#include "springblock/scene_fields.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <functional>
#include <map>
#include <string>

#include "springblock/units.hpp"

namespace sb {
namespace {

double number(const std::string& key, const std::string& text) {
  return parse_quantity(text, Dimension::Dimensionless, key);
}

long long integer(const std::string& key, const std::string& text) {
  long long x = 0;
  const char* b = text.data();
  const char* e = b + text.size();
  auto [p, ec] = std::from_chars(b, e, x);
  if (ec == std::errc::result_out_of_range && p == e)
    throw InputError(key, "'" + text + "' is too large a whole number (beyond +-9.2e18)");
  if (ec != std::errc() || p != e)
    throw InputError(key, "'" + text + "' is not a whole number");
  return x;
}

bool boolean(const std::string& key, const std::string& text) {
  if (text == "true" || text == "1") return true;
  if (text == "false" || text == "0") return false;
  throw InputError(key, "'" + text + "' is not true or false");
}

// "MEAN,SD" for a micro-coefficient distribution.
std::pair<double, double> mean_sd(const std::string& key, const std::string& text) {
  auto comma = text.find(',');
  if (comma == std::string::npos)
    throw InputError(key, "'" + text + "' must be MEAN,SD (e.g. 1.0,0.1)");
  return {number(key, text.substr(0, comma)), number(key, text.substr(comma + 1))};
}

using Setter = std::function<void(Scene&, const std::string&, const std::string&)>;

struct Entry {
  SceneField field;
  Setter set;
};

// The chain and its surface.
std::vector<Entry> chain_and_surface_entries() {
  return {
    {{"N", "number of blocks (default 200)", "360"},
     [](Scene& s, auto& k, auto& v) {
       auto n = integer(k, v);
       if (n < 1 || n > 1000000) throw InputError(k, "N = " + v + " is outside [1, 1000000]");
       s.geometry.N = static_cast<int>(n);
     }},
    {{"length", "total length L_x (default 4cm; m, cm, mm, um)", "7.2cm"},
     [](Scene& s, auto& k, auto& v) { s.geometry.L_x_m = parse_quantity(v, Dimension::Length, k); }},
    {{"pattern", "surface: smooth (default) | periodic:NP,NG | hierarchical:G1,G2,... | hierarchical:P1/G1,P2/G2,... | "
      "random:FRACTION | mask:0110... (one 0/1 per block, N of them) | mask:@FILE",
      "periodic:2,1"},
     [](Scene& s, auto&, auto& v) {
       const auto layout = s.pattern.layout;  // a separate field: keep it whatever the order
       s.pattern = parse_pattern(v);
       s.pattern.layout = layout;
     }},
    {{"layout",
      "where each level's pawls and grooves sit on the run they divide: pawl_first, symmetric, groove_first "
      "or one_based; a comma list gives one per level, the last for deeper levels (default symmetric,pawl_first)",
      "symmetric"},
     [](Scene& s, auto&, auto& v) { s.pattern.layout = parse_layout(v); }},
  };
}

// The micro coefficients and how blocks are coupled.
std::vector<Entry> friction_entries() {
  return {
    {{"mu_s", "micro static coefficient MEAN,SD (default 1.0,0.1)", "1.0,0.1"},
     [](Scene& s, auto& k, auto& v) {
       std::tie(s.friction.mu_s_mean, s.friction.mu_s_sd) = mean_sd(k, v);
     }},
    {{"mu_d", "micro dynamic coefficient MEAN,SD (default 0.5,0.01); the mean must not exceed mu_s's", "0.5,0.01"},
     [](Scene& s, auto& k, auto& v) {
       std::tie(s.friction.mu_d_mean, s.friction.mu_d_sd) = mean_sd(k, v);
     }},
    {{"pair_policy", "a draw with mu_d > mu_s: clip (mu_d := mu_s, default) or keep", "clip"},
     [](Scene& s, auto& k, auto& v) {
       if (v == "clip") s.friction.pair_policy = FrictionDistribution::PairPolicy::Clip;
       else if (v == "keep") s.friction.pair_policy = FrictionDistribution::PairPolicy::Keep;
       else throw InputError(k, "'" + v + "' is not one of: clip, keep");
     }},
    {{"k_int_scale", "multiplies K_int (default 1; 0 decouples the blocks)", "0"},
     [](Scene& s, auto& k, auto& v) { s.k_int_scale = number(k, v); }},
    {{"materials", "TSV file of per-block fields, one row per block, columns among contact, mu_s, mu_s_sd, mu_d, "
                   "mu_d_sd, k_int_scale, k_s_scale, mass_scale (default none: uniform)", "examples/graded_materials.tsv"},
     [](Scene& s, auto&, auto& v) {
       auto segments = std::move(s.materials.segments);  // a scene file's segments lie over any file
       s.materials = read_materials_tsv(v);
       s.materials.segments = std::move(segments);
     }},
  };
}

// Material, load and drive.
std::vector<Entry> material_entries() {
  return {
    {{"damping", "viscous damping gamma (default 10/ms; /s, /ms, Hz; 0 for none)", "10/ms"},
     [](Scene& s, auto& k, auto& v) { s.material.gamma_per_s = parse_quantity(v, Dimension::Rate, k); }},
    {{"velocity", "slider velocity v (default 0.05cm/s)", "0.05cm/s"},
     [](Scene& s, auto& k, auto& v) { s.material.v_m_per_s = parse_quantity(v, Dimension::Velocity, k); }},
    {{"pressure", "total load pressure P (default 1MPa)", "1MPa"},
     [](Scene& s, auto& k, auto& v) { s.material.P_Pa = parse_quantity(v, Dimension::Pressure, k); }},
    {{"shear_modulus", "G (default 5MPa)", "5MPa"},
     [](Scene& s, auto& k, auto& v) { s.material.G_Pa = parse_quantity(v, Dimension::Pressure, k); }},
    {{"young_modulus", "E (default 15MPa)", "15MPa"},
     [](Scene& s, auto& k, auto& v) { s.material.E_Pa = parse_quantity(v, Dimension::Pressure, k); }},
    {{"density", "rho (default 1.2g/cm3)", "1.2g/cm3"},
     [](Scene& s, auto& k, auto& v) { s.material.rho_kg_per_m3 = parse_quantity(v, Dimension::Density, k); }},
    {{"l_y", "transversal width l_y (default 1cm)", "1cm"},
     [](Scene& s, auto& k, auto& v) { s.material.l_y_m = parse_quantity(v, Dimension::Length, k); }},
    {{"l_z", "height l_z (default 0.1cm)", "0.1cm"},
     [](Scene& s, auto& k, auto& v) { s.material.l_z_m = parse_quantity(v, Dimension::Length, k); }},
  };
}

// Repetitions and who runs them.
std::vector<Entry> ensemble_entries() {
  return {
    {{"reps", "repetitions with independent draws (default 20)", "20"},
     [](Scene& s, auto& k, auto& v) {
       auto n = integer(k, v);
       if (n < 1 || n > 1000000) throw InputError(k, "reps = " + v + " is outside [1, 1000000]");
       s.reps = static_cast<int>(n);
     }},
    {{"seed", "seed of repetition 0's stream (default 1); fixes the result at any thread count", "7"},
     [](Scene& s, auto& k, auto& v) {
       // Every 64-bit seed, as results record them.
       std::uint64_t n = 0;
       const auto [end, ec] = std::from_chars(v.data(), v.data() + v.size(), n);
       if (ec != std::errc() || end != v.data() + v.size())
         throw InputError(k, "seed = " + v + " is not a whole number in [0, 18446744073709551615]");
       s.seed = n;
     }},
    {{"threads", "threads over repetitions (default 0 = all cores: OMP_NUM_THREADS if set, else every hardware thread)", "2"},
     [](Scene& s, auto& k, auto& v) {
       auto n = integer(k, v);
       if (n < 0 || n > 1024) throw InputError(k, "threads = " + v + " is outside [0, 1024]");
       s.threads = static_cast<int>(n);
     }},
  };
}

// The integrator.
std::vector<Entry> integration_entries() {
  return {
    {{"method", "integrator: event (default; exact switching, adaptive) or rk4 (the paper's fixed step --dt)", "rk4"},
     [](Scene& s, auto&, auto& v) { s.run.method = parse_method(v); }},
    {{"dt", "RK4 step h (default 1e-4ms; s, ms, us)", "1e-4ms"},
     [](Scene& s, auto& k, auto& v) { s.run.dt_s = parse_quantity(v, Dimension::Time, k); }},
    {{"tol", "event method relative tolerance (default 1e-8)", "1e-8"},
     [](Scene& s, auto& k, auto& v) { s.run.tol = number(k, v); }},
    {{"modal_max_run", "event method: mobile runs of up to this many blocks that keep moving are solved exactly by their modes, not stepped (default " +
          std::to_string(kDefaultModalMaxRun) + "; 0 steps all)", std::to_string(kDefaultModalMaxRun)},
     [](Scene& s, auto& k, auto& v) {
       const auto n = integer(k, v);
       if (n < 0 || n > 64) throw InputError(k, "modal_max_run = " + v + " is outside [0, 64]");
       s.run.modal_max_run = static_cast<int>(n);
     }},
    {{"modal_max_groove", "event method: ringing groove-only runs of up to this many blocks are solved exactly by their modes, not stepped (default " +
          std::to_string(kDefaultModalMaxGroove) + "; 0 steps them)", std::to_string(kDefaultModalMaxGroove)},
     [](Scene& s, auto& k, auto& v) {
       const auto n = integer(k, v);
       if (n < 0 || n > kLongestModalGroove)
         throw InputError(k, "modal_max_groove = " + v + " is outside [0, " + std::to_string(kLongestModalGroove) + "]");
       s.run.modal_max_groove = static_cast<int>(n);
     }},
    {{"stepper", "event method: how sliding runs move: exact (default; by their modes, no step-size error) or dopri5 (Dormand-Prince steps under --tol)", "dopri5"},
     [](Scene& s, auto&, auto& v) { s.run.stepper = parse_stepper(v); }},
    {{"exact_max_run", "event method, exact stepper: longest run it moves by its modes; longer ones are stepped by Dormand-Prince (default " +
          std::to_string(kDefaultExactMaxRun) + ")", std::to_string(kDefaultExactMaxRun)},
     [](Scene& s, auto& k, auto& v) {
       const auto n = integer(k, v);
       if (n < 1 || n > 512) throw InputError(k, "exact_max_run = " + v + " is outside [1, 512]");
       s.run.exact_max_run = static_cast<int>(n);
     }},
  };
}

// Run length, sampling, how mu_s and mu_d are read off mu(t), and what is kept.
std::vector<Entry> run_and_extraction_entries() {
  return {
    {{"duration", "simulated time: a time (e.g. 1s) or a multiple of the loading time t0 (e.g. 4t0, the default)", "4t0"},
     [](Scene& s, auto& k, auto& v) {
       if (v.size() > 2 && v.substr(v.size() - 2) == "t0") {
         s.run.duration_t0 = number(k, v.substr(0, v.size() - 2));
         s.run.duration_s = 0;
       } else {
         s.run.duration_s = parse_quantity(v, Dimension::Time, k);
         if (!(s.run.duration_s > 0)) throw InputError(k, "duration = " + v + " must be > 0");
       }
     }},
    {{"sample_dt", "spacing of mu(t) samples (default 1e-3ms; at most duration/2)", "1e-3ms"},
     [](Scene& s, auto& k, auto& v) { s.run.sample_dt_s = parse_quantity(v, Dimension::Time, k); }},
    {{"peak_rule", "end of the loading phase for mu_s: all_slipped (every contact block has slid once), drop, or "
                   "all_slipped's moment unless earlier: slid_or_drop (default), slid_or_relative_drop, slid_or_event", "slid_or_drop"},
     [](Scene& s, auto&, auto& v) { s.rules.peak_rule = parse_peak_rule(v); }},
    {{"peak_drop", "with --peak-rule drop or slid_or_drop: mu falling this far below its running max ends loading (default 0.1)", "0.1"},
     [](Scene& s, auto& k, auto& v) { s.rules.peak_drop = number(k, v); }},
    {{"peak_drop_fraction", "with --peak-rule slid_or_relative_drop: mu falling below (1 - this) times its running max ends loading (default 0.1)", "0.1"},
     [](Scene& s, auto& k, auto& v) { s.rules.peak_drop_fraction = number(k, v); }},
    {{"peak_event_fraction", "with --peak-rule slid_or_event: a slip event moving at least this share of the contact blocks ends loading (default 0.5)", "0.5"},
     [](Scene& s, auto& k, auto& v) { s.rules.peak_event_fraction = number(k, v); }},
    {{"mu_d_skip", "mu_d window starts this many t0 after the first slip, before the end of the run (default 0.25)", "0.25"},
     [](Scene& s, auto& k, auto& v) { s.rules.mu_d_skip_t0 = number(k, v); }},
    {{"stop_after_mu_s", "stop each repetition at the first macroscopic slip; mu_d is then not measured (true/false, default false)", "false"},
     [](Scene& s, auto& k, auto& v) { s.run.stop_after_mu_s = boolean(k, v); }},
    {{"slip_events", "record every repetition's slip events: start, duration, blocks, episodes and total slip (true/false, default false)", "true"},
     [](Scene& s, auto& k, auto& v) { s.observe.slip_events = boolean(k, v); }},
    {{"stress_times", "comma-separated times for per-block stress snapshots of repetition 0, taken in time order (default none)", "0.2s,0.3s"},
     [](Scene& s, auto& k, auto& v) {
       s.observe.stress_times_s.clear();
       std::size_t start = 0;
       while (start <= v.size()) {
         auto comma = v.find(',', start);
         auto piece = v.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
         s.observe.stress_times_s.push_back(parse_quantity(piece, Dimension::Time, k));
         if (comma == std::string::npos) break;
         start = comma + 1;
       }
       // The observer takes them in time order: out of order, an earlier time would be taken at
       // the later one's sample.
       std::sort(s.observe.stress_times_s.begin(), s.observe.stress_times_s.end());
     }},
  };
}

// In the order of the help text: the groups above, one after another.
const std::vector<Entry>& entries() {
  static const std::vector<Entry> table = [] {
    std::vector<Entry> all;
    for (auto group : {chain_and_surface_entries, friction_entries, material_entries, ensemble_entries,
                       integration_entries, run_and_extraction_entries})
      for (auto& e : group()) all.push_back(std::move(e));
    return all;
  }();
  return table;
}

}  // namespace

const std::vector<SceneField>& scene_fields() {
  static const std::vector<SceneField> fields = [] {
    std::vector<SceneField> f;
    for (auto& e : entries()) f.push_back(e.field);
    return f;
  }();
  return fields;
}

void set_scene_field(Scene& s, const std::string& key, const std::string& value) {
  for (auto& e : entries())
    if (e.field.key == key) return e.set(s, key, value);
  throw InputError(key, "unknown scene field");
}

}  // namespace sb
