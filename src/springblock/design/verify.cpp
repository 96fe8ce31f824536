#include "springblock/design/verify.hpp"

#include <algorithm>
#include <cmath>

namespace sb::design {

bool meets_target(const Target& t, const Statistic& mu_s, const Statistic& mu_d, const Statistic& ratio) {
  return meets(t.mu_s, mu_s) && meets(t.mu_d, mu_d) && meets(t.ratio, ratio);
}

std::vector<Verified> verify(const Scene& base, const std::vector<Candidate>& candidates, const std::vector<int>& ranking,
                             const Target& target, int count, int reps, const std::atomic<bool>* interrupt,
                             const StageProgress& progress, bool& interrupted) {
  const int n = std::min<int>(count, static_cast<int>(ranking.size()));
  const std::uint64_t seed = stage_seed(base.seed, kVerifyStage);
  std::vector<Scene> scenes;
  for (int i = 0; i < n; ++i) scenes.push_back(candidate_scene(base, candidates[ranking[i]], reps, seed, false));
  const std::string label = "verification: " + std::to_string(n) + " candidates x " + std::to_string(reps) + " fresh full reps";
  const auto results = run_stage(scenes, interrupt, progress, label);
  std::vector<Verified> out;
  interrupted = false;
  for (int i = 0; i < n; ++i) {
    Estimate e;
    for (const auto& r : results[i].runs) {
      if (std::isfinite(r.mu_s)) e.mu_s.push_back(r.mu_s);
      if (std::isfinite(r.mu_d)) e.mu_d.push_back(r.mu_d);
      if (std::isfinite(r.mu_s) && std::isfinite(r.mu_d) && r.mu_d > 0) e.ratio.push_back(r.mu_s / r.mu_d);
    }
    Verified v{ranking[i], i, e.stat(Quantity::MuS), e.stat(Quantity::MuD), e.stat(Quantity::Ratio), false, 0,
               results[i].wall_s};
    v.meets_target = meets_target(target, v.mu_s, v.mu_d, v.ratio);
    v.score = score(target, v.mu_s.n ? v.mu_s.mean : std::nan(""), v.mu_d.n ? v.mu_d.mean : std::nan(""));
    interrupted = interrupted || results[i].interrupted;
    out.push_back(v);
  }
  std::stable_partition(out.begin(), out.end(), [](const Verified& v) { return v.meets_target; });
  return out;
}

}  // namespace sb::design
