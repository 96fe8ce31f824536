#include "springblock/design/verify.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace sb::design {

bool meets_target(const Target& t, const Statistic& mu_s, const Statistic& mu_d, const Statistic& ratio) {
  return meets(t.mu_s, mu_s) && meets(t.mu_d, mu_d) && meets(t.ratio, ratio);
}

namespace {

const Statistic& stat_of(const Verified& v, Quantity q) {
  return q == Quantity::MuS ? v.mu_s : q == Quantity::MuD ? v.mu_d : v.ratio;
}

// The fresh statistics of candidate `candidate` from its ensemble.
Verified measured(const Target& target, int candidate, int rank, const EnsembleResult& r, int reps) {
  Estimate e;
  for (const auto& run : r.runs) {
    if (std::isfinite(run.mu_s)) e.mu_s.push_back(run.mu_s);
    if (std::isfinite(run.mu_d)) e.mu_d.push_back(run.mu_d);
    if (std::isfinite(run.mu_s) && std::isfinite(run.mu_d) && run.mu_d > 0) e.ratio.push_back(run.mu_s / run.mu_d);
  }
  Verified v{candidate, rank, e.stat(Quantity::MuS), e.stat(Quantity::MuD), e.stat(Quantity::Ratio), false, 0, r.wall_s, reps};
  v.meets_target = meets_target(target, v.mu_s, v.mu_d, v.ratio);
  v.score = score(target, v.mu_s.n ? v.mu_s.mean : std::nan(""), v.mu_d.n ? v.mu_d.mean : std::nan(""));
  for (Quantity q : {Quantity::MuS, Quantity::MuD, Quantity::Ratio})
    if (target.of(q).set) v.half_width = std::max(v.half_width, kMeetsZ * stat_of(v, q).sem);
  return v;
}

}  // namespace

bool resolved(const Target& t, const Verified& v, double resolution) {
  for (Quantity q : {Quantity::MuS, Quantity::MuD, Quantity::Ratio}) {
    const Interval& in = t.of(q);
    if (!in.set) continue;
    const Statistic& s = stat_of(v, q);
    if (s.n < 2) return false;
    const double half = kMeetsZ * s.sem, lo = s.mean - half, hi = s.mean + half;
    const bool inside = lo >= in.lo && hi <= in.hi, outside = hi < in.lo || lo > in.hi;
    if (!inside && !outside && half > resolution) return false;
  }
  return true;
}

std::vector<Verified> verify(const Scene& base, const std::vector<Candidate>& candidates, const std::vector<int>& ranking,
                             const Target& target, int count, const VerifyOptions& options,
                             const std::atomic<bool>* interrupt, const StageProgress& progress, bool& interrupted) {
  const int n = std::min<int>(count, static_cast<int>(ranking.size()));
  const std::uint64_t seed = stage_seed(base.seed, kVerifyStage);
  std::vector<Verified> out(n);
  std::vector<int> todo(n);
  for (int i = 0; i < n; ++i) todo[i] = i;
  interrupted = false;
  // Rounds: every finalist still unresolved runs again with twice the repetitions (the first ones
  // are the same repetitions: each is fixed by its index and the stage seed).
  for (int reps = options.reps; !todo.empty() && !interrupted; reps = std::min(2 * reps, options.max_reps)) {
    std::vector<Scene> scenes;
    for (int i : todo) scenes.push_back(candidate_scene(base, candidates[ranking[i]], reps, seed, false));
    const std::string label = "verification: " + std::to_string(todo.size()) + " candidates x " + std::to_string(reps) +
                              " fresh full reps";
    const auto results = run_stage(scenes, interrupt, progress, label);
    std::vector<int> next;
    for (std::size_t k = 0; k < todo.size(); ++k) {
      const int i = todo[k];
      const double wall_before = out[i].wall_s;
      out[i] = measured(target, ranking[i], i, results[k], reps);
      out[i].wall_s += wall_before;
      out[i].resolved = resolved(target, out[i], options.resolution);
      interrupted = interrupted || results[k].interrupted;
      if (!out[i].resolved && reps < options.max_reps) next.push_back(i);
    }
    todo.swap(next);
  }
  std::stable_sort(out.begin(), out.end(), [](const Verified& a, const Verified& b) {
    const double x = std::isfinite(a.score) ? a.score : INFINITY, y = std::isfinite(b.score) ? b.score : INFINITY;
    return x < y;
  });
  return out;
}

}  // namespace sb::design
