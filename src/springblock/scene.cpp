#include "springblock/scene.hpp"

#include <gsl/gsl_randist.h>
#include <gsl/gsl_rng.h>

#include <cmath>
#include <memory>

#include "springblock/errors.hpp"

namespace sb {

std::string method_name(Method m) { return m == Method::RK4 ? "rk4" : "event"; }

Method parse_method(const std::string& text) {
  if (text == "rk4") return Method::RK4;
  if (text == "event") return Method::Event;
  throw InputError("method", "'" + text + "' is not one of: rk4, event");
}

std::string stepper_name(Stepper s) { return s == Stepper::Exact ? "exact" : "dopri5"; }

Stepper parse_stepper(const std::string& text) {
  if (text == "exact") return Stepper::Exact;
  if (text == "dopri5") return Stepper::Dopri5;
  throw InputError("stepper", "'" + text + "' is not one of: exact, dopri5");
}

namespace {
struct PeakRuleName {
  ExtractionRules::PeakRule rule;
  const char* name;
};
constexpr PeakRuleName kPeakRules[] = {{ExtractionRules::PeakRule::AllSlipped, "all_slipped"},
                                       {ExtractionRules::PeakRule::Drop, "drop"},
                                       {ExtractionRules::PeakRule::SlidOrDrop, "slid_or_drop"},
                                       {ExtractionRules::PeakRule::SlidOrRelativeDrop, "slid_or_relative_drop"},
                                       {ExtractionRules::PeakRule::SlidOrEvent, "slid_or_event"}};
}  // namespace

std::string peak_rule_name(ExtractionRules::PeakRule r) {
  for (const auto& p : kPeakRules)
    if (p.rule == r) return p.name;
  return "?";
}

ExtractionRules::PeakRule parse_peak_rule(const std::string& text) {
  std::string names;
  for (const auto& p : kPeakRules) {
    if (text == p.name) return p.rule;
    names += (names.empty() ? "" : ", ") + std::string(p.name);
  }
  throw InputError("peak_rule", "'" + text + "' is not one of: " + names);
}

double Scene::t0_s() const {
  const auto d = derived();
  auto mask = contact_mask(pattern, geometry.N, 0);
  double fraction = pattern.kind == SurfaceKind::Random ? 1.0 - pattern.groove_fraction
                                                         : contact_fraction(mask);
  if (materials.given()) {  // a contact column overrides the pattern
    const auto m = resolve_materials(*this);
    if (m.has(BlockField::Contact)) {
      double n = 0;
      for (double x : m.column[index_of(BlockField::Contact)]) n += x;
      fraction = n / geometry.N;
    }
  }
  const double F_n = d.F_load_N / (fraction * geometry.N);
  return friction.mu_s_mean * F_n / (d.K_s_N_per_m * material.v_m_per_s);
}

double Scene::duration() const { return run.duration_s > 0 ? run.duration_s : run.duration_t0 * t0_s(); }

std::uint64_t rep_seed(std::uint64_t seed, int rep) {
  // SplitMix64 finaliser over (seed, rep): consecutive repetitions get unrelated streams.
  std::uint64_t z = seed + 0x9E3779B97F4A7C15ULL * (static_cast<std::uint64_t>(rep) + 1);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  return z ^ (z >> 31);
}

Chain build_chain(const Scene& s, int rep) {
  const auto d = s.derived();
  Chain c;
  c.N = s.geometry.N;
  c.K_s = d.K_s_N_per_m;
  c.K_int = d.K_int_N_per_m;
  c.m = d.m_kg;
  c.gamma = s.material.gamma_per_s;
  c.v_slider = s.material.v_m_per_s;
  const std::uint64_t seed = rep_seed(s.seed, rep);
  // Per-block fields where the scene gives them (materials.hpp); a uniform scene resolves none.
  const ResolvedMaterials mat = resolve_materials(s);
  if (mat.has(BlockField::Contact)) {
    c.contact.clear();
    for (double x : mat.column[index_of(BlockField::Contact)]) c.contact.push_back(x != 0.0);
  } else {
    c.contact = contact_mask(s.pattern, c.N, seed ^ 0x5DEECE66DULL);
  }
  c.n_contact = 0;
  for (auto x : c.contact) c.n_contact += x;
  c.F_load = d.F_load_N;
  c.F_n = d.F_load_N / c.n_contact;  // the load is shared by the blocks still in contact

  // GSL's generators and ziggurat Gaussian give the same stream on every platform, unlike
  // std::normal_distribution.
  std::unique_ptr<gsl_rng, decltype(&gsl_rng_free)> rng(gsl_rng_alloc(gsl_rng_mt19937), &gsl_rng_free);
  gsl_rng_set(rng.get(), static_cast<unsigned long>(seed));
  auto draw = [&](double mean, double sd) {
    if (sd == 0) return mean;
    for (int tries = 0; tries < 100000; ++tries) {
      double x = mean + gsl_ran_gaussian_ziggurat(rng.get(), sd);
      if (x >= 0) return x;  // truncation at 0: a negative friction coefficient is unphysical
    }
    throw InputError("mu_s", "the Gaussian is almost entirely below 0; raise the mean");
  };
  c.mu_s.resize(c.N);
  c.mu_d.resize(c.N);
  c.f_static.resize(c.N);
  c.f_kinetic.resize(c.N);
  for (int i = 0; i < c.N; ++i) {
    // Draw for every block, groove or not, so the same seed gives the same coefficients on the
    // shared pawl blocks of two surfaces: comparisons between patterns are paired. Per-block
    // means and spreads draw from the same stream in the same order, so a materials file of the
    // scene's own values gives the uniform scene's chain bit for bit.
    const auto& f = s.friction;
    double ms = draw(mat.at(BlockField::MuS, i, f.mu_s_mean), mat.at(BlockField::MuSSd, i, f.mu_s_sd));
    double md = draw(mat.at(BlockField::MuD, i, f.mu_d_mean), mat.at(BlockField::MuDSd, i, f.mu_d_sd));
    if (s.friction.pair_policy == FrictionDistribution::PairPolicy::Clip && md > ms) md = ms;
    if (!c.contact[i]) ms = md = 0.0;
    c.mu_s[i] = ms;
    c.mu_d[i] = md;
    // A kept pair with mu_d > mu_s cannot start to slide at mu_s F_n: once moving, kinetic
    // friction exceeds the pull and drives it back to rest, and at rest static friction cannot
    // hold it, so both sides push it onto v = 0 (a Filippov sliding mode). It therefore holds
    // until the pull reaches mu_d F_n: its effective static threshold is max(mu_s, mu_d) F_n.
    // RK4 reproduces this by chattering; stating it here gives every integrator the same law.
    c.f_static[i] = std::max(ms, md) * c.F_n;
    c.f_kinetic[i] = md * c.F_n;
  }
  if (mat.mechanical()) c.blocks = block_mechanics(mat, c);
  return c;
}

}  // namespace sb
