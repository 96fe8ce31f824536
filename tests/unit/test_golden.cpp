// Bit-identical results across a refactoring: a fixed set of short scenes, one per integrator
// path and surface kind, run now and compared with values recorded before the change
// (tests/golden/runs.txt). Every double is compared through its exact hexadecimal form, and the
// whole mu(t) series of repetition 0 through a hash of its bytes, so any change of any sample of
// any run fails here, naming the scene.
//
// To record (only when a change of results is intended and explained in its commit):
//   SPRINGBLOCK_GOLDEN_RECORD=1 build/tests/test_golden
// rewrites tests/golden/runs.txt in the source tree.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "springblock/ensemble.hpp"

using namespace sb;

namespace {

const std::string kReference = std::string(SPRINGBLOCK_SOURCE_DIR) + "/tests/golden/runs.txt";

std::string hex(double x) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%a", x);
  return buf;
}

// FNV-1a over the bytes of every sample: cheap, and any bit of any sample changes it.
std::uint64_t series_hash(const std::vector<Sample>& series) {
  std::uint64_t h = 1469598103934665603ull;
  auto mix = [&](const void* p, std::size_t n) {
    const auto* b = static_cast<const unsigned char*>(p);
    for (std::size_t i = 0; i < n; ++i) h = (h ^ b[i]) * 1099511628211ull;
  };
  for (const Sample& s : series) {
    mix(&s.t, sizeof s.t);
    mix(&s.mu, sizeof s.mu);
    mix(&s.mu_signed, sizeof s.mu_signed);
    mix(&s.n_sliding, sizeof s.n_sliding);
  }
  return h;
}

struct Case {
  std::string name;
  Scene scene;
};

Scene base(const char* pattern, Method m, int N, double length_m, double duration_t0) {
  Scene s;
  s.geometry = {N, length_m};
  s.pattern = parse_pattern(pattern);
  s.run.method = m;
  s.run.duration_t0 = duration_t0;
  s.run.sample_dt_s = 1e-4;  // coarse: the series hash sees every sample, few are needed
  s.observe.series = true;
  s.reps = 2;
  s.seed = 11;
  s.threads = 1;
  return s;
}

// One scene per path through the integrators: RK4 (smooth, periodic), the event method on every
// surface kind, its decoupled solver (K_int = 0), undamped modal runs, the drop rule, and a
// non-default layout; its Dormand-Prince stepper, and the exact stepper falling back to it for
// long runs.
std::vector<Case> cases() {
  std::vector<Case> out;
  out.push_back({"rk4_smooth", base("smooth", Method::RK4, 40, 0.008, 1.2)});
  {
    // Grooves ring, so RK4 steps all the way: a short chain, one repetition, twice the paper's
    // step (still inside RK4's stability limit) keep it to a fraction of a second.
    Scene s = base("periodic:2,2", Method::RK4, 12, 0.0024, 1.15);
    s.run.dt_s = 2e-7;
    s.reps = 1;
    out.push_back({"rk4_periodic_2_2", s});
  }
  out.push_back({"event_smooth", base("smooth", Method::Event, 120, 0.024, 1.5)});
  out.push_back({"event_periodic_10_10", base("periodic:10,10", Method::Event, 360, 0.072, 1.2)});
  out.push_back({"event_hierarchical_20_2_1", base("hierarchical:20,2,1", Method::Event, 240, 0.048, 1.2)});
  out.push_back({"event_random_0.4", base("random:0.4", Method::Event, 200, 0.04, 1.2)});
  {
    Scene s = base("smooth", Method::Event, 100, 0.02, 2.0);
    s.k_int_scale = 0.0;
    s.friction.mu_d_mean = 0.9;
    out.push_back({"event_kint0_r0.9", s});
  }
  {
    Scene s = base("periodic:1,1", Method::Event, 30, 0.006, 1.2);
    s.reps = 1;  // undamped grooves ring to the end: the costliest path per block
    s.material.gamma_per_s = 0.0;
    out.push_back({"event_undamped_periodic_1_1", s});
  }
  {
    Scene s = base("periodic:3,3", Method::Event, 120, 0.024, 1.2);
    s.rules.peak_rule = ExtractionRules::PeakRule::Drop;
    s.pattern.layout = parse_layout("groove_first");
    out.push_back({"event_drop_groove_first_3_3", s});
  }
  {
    Scene s = base("periodic:10,10", Method::Event, 360, 0.072, 1.2);
    s.run.stepper = Stepper::Dopri5;
    out.push_back({"event_dopri5_periodic_10_10", s});
  }
  {
    Scene s = base("smooth", Method::Event, 120, 0.024, 1.5);
    s.run.exact_max_run = 4;
    out.push_back({"event_exact_max_run_4_smooth", s});
  }
  return out;
}

std::string fingerprint(const Case& c) {
  Scene s = c.scene;
  validate(s);
  const EnsembleResult e = run_ensemble(s);
  std::ostringstream os;
  os << c.name;
  for (const RunResult& r : e.runs)
    os << " | rep " << r.rep << " slipped " << r.slipped << " mu_s " << hex(r.mu_s) << " mu_s_signed "
       << hex(r.mu_s_signed) << " t_peak " << hex(r.t_peak_s) << " t_slip " << hex(r.t_slip_s) << " mu_d "
       << hex(r.mu_d) << " window " << r.window_samples << " steps " << r.steps << " rhs " << r.rhs_evals
       << " switches " << r.switches;
  os << " | series " << e.runs.at(0).series.size() << " " << std::hex << series_hash(e.runs.at(0).series);
  return os.str();
}

std::map<std::string, std::string> read_reference() {
  std::map<std::string, std::string> ref;
  std::ifstream in(kReference);
  for (std::string line; std::getline(in, line);)
    if (!line.empty() && line[0] != '#') ref[line.substr(0, line.find(' '))] = line;
  return ref;
}

}  // namespace

TEST(Golden, EveryPathBitIdenticalToTheRecordedRuns) {
  const auto all = cases();
  if (std::getenv("SPRINGBLOCK_GOLDEN_RECORD")) {
    const std::string tmp = kReference + ".tmp";
    {
      std::ofstream out(tmp);
      out << "# tests/unit/test_golden.cpp: one line per scene, doubles in exact hexadecimal.\n";
      for (const Case& c : all) {
        const auto t0 = std::chrono::steady_clock::now();
        out << fingerprint(c) << "\n";
        std::fprintf(stderr, "%-30s %.2f s\n", c.name.c_str(),
                     std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
      }
    }
    ASSERT_EQ(std::rename(tmp.c_str(), kReference.c_str()), 0) << kReference;
    GTEST_SKIP() << "recorded " << kReference;
  }
  const auto ref = read_reference();
  ASSERT_FALSE(ref.empty()) << "no reference at " << kReference;
  for (const Case& c : all) {
    const auto it = ref.find(c.name);
    ASSERT_NE(it, ref.end()) << c.name << " has no recorded line";
    EXPECT_EQ(fingerprint(c), it->second) << c.name << " differs from the recorded run";
  }
}

TEST(Golden, FingerprintSeesAOneUlpChange) {
  // The check can fail: a change of one unit in the last place of one input changes the line.
  auto all = cases();
  Case c = all.at(3);
  const std::string a = fingerprint(c);
  c.scene.material.gamma_per_s = std::nextafter(c.scene.material.gamma_per_s, 1e300);
  EXPECT_NE(fingerprint(c), a);
}
