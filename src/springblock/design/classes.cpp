#include "springblock/design/classes.hpp"

#include <algorithm>
#include <cmath>
#include <map>

namespace sb::design {
namespace {

// Whether a class whose mu_d is `mu_d` (give or take `margin`) can still meet the target's mu_d
// interval. A ratio target is not pruned on: it needs mu_s too, which varies within a class.
bool class_can_meet(const Target& t, const Statistic& mu_d, double margin) {
  if (mu_d.n == 0) return true;  // nothing measured: nothing to prune on
  if (t.mu_d.set && distance(t.mu_d, mu_d.mean) > margin) return false;
  return true;
}

}  // namespace

ClassPrune prune_by_contact_class(const Scene& base, const std::vector<Candidate>& candidates, const Target& target,
                                  const ClassOptions& o, const std::atomic<bool>* interrupt,
                                  const StageProgress& progress) {
  ClassPrune out;
  std::map<int, std::vector<int>> bins;  // bin index -> members
  for (int k = 0; k < static_cast<int>(candidates.size()); ++k)
    bins[static_cast<int>(std::floor(candidates[k].contact_fraction / o.bin_width))].push_back(k);
  out.seed = stage_seed(base.seed, kClassStage);
  std::vector<Scene> scenes;
  for (const auto& [bin, members] : bins) {
    ContactClass c;
    c.lo = bin * o.bin_width, c.hi = (bin + 1) * o.bin_width;
    c.members = static_cast<int>(members.size());
    c.member_list = members;
    const double centre = (c.lo + c.hi) / 2;
    c.representative = *std::min_element(members.begin(), members.end(), [&](int a, int b) {
      return std::abs(candidates[a].contact_fraction - centre) < std::abs(candidates[b].contact_fraction - centre);
    });
    out.classes.push_back(c);
    scenes.push_back(candidate_scene(base, candidates[c.representative], o.reps, out.seed, false));
  }
  const std::string label = "contact-fraction classes: " + std::to_string(scenes.size()) + " representatives x " +
                            std::to_string(o.reps) + " full reps";
  const auto results = run_stage(scenes, interrupt, progress, label);
  std::size_t i = 0;
  for (const auto& [bin, members] : bins) {
    ContactClass& c = out.classes[i];
    c.mu_d = results[i].mu_d;
    c.kept = class_can_meet(target, c.mu_d, o.margin);
    if (c.kept) out.kept.insert(out.kept.end(), members.begin(), members.end());
    for (const auto& r : results[i].runs) out.cpu_s += r.cpu_s;
    out.interrupted = out.interrupted || results[i].interrupted;
    ++i;
  }
  std::sort(out.kept.begin(), out.kept.end());
  return out;
}

}  // namespace sb::design
