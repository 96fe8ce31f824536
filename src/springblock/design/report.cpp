#include "springblock/design/report.hpp"

#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>

#include "springblock/errors.hpp"
#include "springblock/io.hpp"

namespace sb::design {
namespace {

nlohmann::json interval_json(const Interval& in) {
  if (!in.set) return nullptr;
  return {{"lo", json_number(in.lo)}, {"hi", json_number(in.hi)}, {"text", in.text()}};
}

nlohmann::json target_json(const Target& t) {
  nlohmann::json j = {{"mu_s", interval_json(t.mu_s)}, {"mu_d", interval_json(t.mu_d)}, {"ratio", interval_json(t.ratio)}};
  if (t.goal != Goal::None)
    j["goal"] = (t.goal == Goal::Minimise ? "minimise " : "maximise ") + quantity_name(t.objective);
  return j;
}

nlohmann::json candidate_json(const Candidate& c) {
  nlohmann::json j{{"pattern", c.spec.text()},
                   {"layout", c.spec.layout_text()},
                   {"contact_fraction", json_number(c.contact_fraction)},
                   {"min_feature", c.min_feature},
                   {"same_mask_specs", c.duplicates}};
  if (c.spec.kind == SurfaceKind::Mask) j["pattern_mask"] = mask_record(c.spec);
  return j;
}

nlohmann::json verified_json(const Outcome& o, const Verified& v) {
  nlohmann::json j = candidate_json(o.candidates.kept[v.candidate]);
  const Estimate& e = o.search.estimates[v.candidate];
  j["mu_s"] = v.mu_s;
  j["mu_d"] = v.mu_d;
  j["ratio"] = v.ratio;
  j["meets_target"] = v.meets_target;
  j["score"] = json_number(v.score);
  j["screening_rank"] = v.screening_rank;
  j["reps"] = v.reps;
  j["half_width"] = json_number(v.half_width);
  j["resolved"] = v.resolved;
  j["screening"] = {{"mu_s", e.stat(Quantity::MuS)}, {"mu_d", e.stat(Quantity::MuD)}, {"reps", e.reps}};
  return j;
}

// The contact-fraction classes (classes.hpp), or null when the query did not prune on them.
nlohmann::json classes_json(const Query& q, const Outcome& o) {
  if (!o.classes_used) return nullptr;
  nlohmann::json list = nlohmann::json::array();
  int pruned = 0;
  for (const auto& c : o.classes.classes) {
    list.push_back({{"contact_lo", c.lo}, {"contact_hi", c.hi}, {"members", c.members},
                    {"representative", o.candidates.kept[c.representative].spec.text()}, {"mu_d", c.mu_d}, {"kept", c.kept}});
    if (!c.kept) pruned += c.members;
  }
  return {{"rule", "mu_d of a class's representative farther than margin from the mu_d interval: class pruned"},
          {"bin_width", q.classes.bin_width}, {"margin", q.classes.margin}, {"reps", q.classes.reps},
          {"seed", o.classes.seed}, {"cpu_s", o.classes.cpu_s}, {"candidates_pruned", pruned}, {"classes", list}};
}

nlohmann::json search_json(const Query& q, const Outcome& o) {
  nlohmann::json rungs = nlohmann::json::array();
  for (const auto& r : o.search.rungs)
    rungs.push_back({{"candidates", r.candidates}, {"reps_added", r.reps_added}, {"reps_total", r.reps_total},
                     {"stop_after_mu_s", r.stop_after_mu_s}, {"seed", r.seed}, {"wall_share_s", r.wall_s},
                     {"cpu_s", r.cpu_s}});
  const auto& c = o.candidates;
  nlohmann::json given = nlohmann::json::array();  // the given family's list, as it was given
  for (const auto& spec : q.space.given) given.push_back(spec.text());
  return {{"given", given},
          {"method", "successive halving (Karnin et al. 2013; Jamieson & Talwalkar 2016), eta = " +
                         std::to_string(q.search.eta) + ", repetitions x" + std::to_string(q.search.growth) + " per rung"},
          {"family", family_name(q.space.family)},
          {"bounds", {{"min_np", q.space.min_np}, {"max_np", q.space.max_np}, {"min_ng", q.space.min_ng},
                      {"max_ng", q.space.max_ng}, {"levels", q.space.levels}, {"factors", q.space.factors},
                      {"min_fraction", q.space.min_fraction}, {"max_fraction", q.space.max_fraction},
                      {"fraction_step", q.space.fraction_step}}},
          {"constraints", {{"min_contact", q.space.min_contact}, {"max_contact", q.space.max_contact},
                           {"min_feature", q.space.min_feature}}},
          {"candidates", {{"generated", c.generated}, {"simulated", c.kept.size()}, {"dropped_contact", c.dropped_contact},
                          {"dropped_feature", c.dropped_feature}, {"dropped_same_mask", c.dropped_duplicate}}},
          {"contact_classes", classes_json(q, o)},
          {"rungs", rungs},
          {"verify_reps", q.verify.reps},
          {"verify_max_reps", q.verify.max_reps},
          {"resolution", q.verify.resolution},
          {"verify_seed", stage_seed(q.base.seed, kVerifyStage)}};
}

// Every simulated candidate's screening estimate, for the figure (mu_d null where it was only
// run to its first slip).
nlohmann::json evaluated_json(const Outcome& o) {
  nlohmann::json all = nlohmann::json::array();
  for (std::size_t k = 0; k < o.search.estimates.size(); ++k) {
    const Estimate& e = o.search.estimates[k];
    if (e.last_rung < 0) continue;
    const auto s = e.stat(Quantity::MuS), d = e.stat(Quantity::MuD);
    all.push_back({{"pattern", o.candidates.kept[k].spec.text()},
                   {"contact_fraction", o.candidates.kept[k].contact_fraction},
                   {"mu_s", json_number(s.n ? s.mean : std::nan(""))}, {"mu_s_sem", json_number(s.n > 1 ? s.sem : std::nan(""))},
                   {"mu_d", json_number(d.n ? d.mean : std::nan(""))}, {"mu_d_sem", json_number(d.n > 1 ? d.sem : std::nan(""))},
                   {"reps", e.reps}, {"last_rung", e.last_rung}});
  }
  return all;
}

}  // namespace

std::string meets_rule() {
  return "meets_target: for every target interval, the fresh estimate's [mean - 2 SEM, mean + 2 SEM] overlaps it "
         "(a point target: |mean - target| <= 2 SEM)";
}

std::string order_rule() {
  return "answers ordered by score, the fresh estimate's distance to the target (with a goal, then its objective; "
         "lower first); repetitions doubled "
         "while a distance is unresolved: resolved when every constrained quantity's [mean - 2 SEM, mean + 2 SEM] "
         "lies wholly inside or outside its interval, or 2 SEM <= the resolution";
}

nlohmann::json design_json(const Query& q, const Outcome& o, const std::string& command_line) {
  nlohmann::json best = nlohmann::json::array();
  for (const auto& v : o.verified) best.push_back(verified_json(o, v));
  // The query's chain, material and run control; the pattern, repetitions and stop at the first
  // slip are each stage's (search.rungs, verify_reps), and t0 and the duration in seconds each
  // candidate's (t0 scales with its contact fraction), not the base scene's placeholders.
  nlohmann::json scene = q.base;
  for (const char* chosen : {"pattern", "reps", "stop_after_mu_s", "seed", "t0_s", "duration_s"}) scene.erase(chosen);
  if (q.base.run.duration_s > 0)
    scene["duration_s"] = q.base.run.duration_s;
  else
    scene["duration_t0"] = q.base.run.duration_t0;
  nlohmann::json j = {{"feasible", o.feasible},
                      {"best", best},
                      {"rule", meets_rule()},
                      {"order", order_rule()},
                      {"target", target_json(q.target)},
                      {"search", search_json(q, o)},
                      {"evaluated", evaluated_json(o)},
                      {"scene", scene},
                      {"seed", q.base.seed},
                      {"method", method_name(q.base.run.method)},
                      {"wall_seconds", o.wall_s},
                      {"provenance", provenance(command_line)}};
  if (!o.feasible) {
    // The nearest reachable point: the verified candidate whose fresh means score best.
    std::size_t nearest = 0;
    for (std::size_t i = 1; i < o.verified.size(); ++i)
      if (o.verified[i].score < o.verified[nearest].score) nearest = i;
    j["nearest"] = best.empty() ? nlohmann::json(nullptr) : best[nearest];
    j["why"] = infeasible_reason(q, o);
  }
  return j;
}

}  // namespace sb::design
