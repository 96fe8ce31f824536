#include "springblock/design/query.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "springblock/errors.hpp"

namespace sb::design {
namespace {

// The classes' mu_d as every member's prior, and their measured cost of a full repetition.
void class_hints(const ClassPrune& c, const ClassOptions& co, std::size_t n, SearchOptions& so) {
  so.mu_d_prior.assign(n, std::nan(""));
  so.prior_margin = co.margin;
  for (const auto& k : c.classes)
    for (int m : k.member_list) so.mu_d_prior[m] = k.mu_d.n > 0 ? k.mu_d.mean : std::nan("");
  const int reps = static_cast<int>(c.classes.size()) * co.reps;
  so.full_rep_cpu_s = reps > 0 ? c.cpu_s / reps : 0;
}

}  // namespace

void validate(const Query& q) {
  validate(q.space, q.base.geometry.N);
  validate_given(q.space, q.base);
  require(q.target.any(), "target",
          "no target given; give --target-mu-s, --target-mu-d, --target-ratio, --minimise or --maximise");
  require(q.top >= 1 && q.top <= 100, "top", std::to_string(q.top) + " is outside [1, 100]");
  require(q.verify.reps >= 2 && q.verify.reps <= 1000, "verify_reps",
          std::to_string(q.verify.reps) + " is outside [2, 1000] (a standard error needs 2)");
  require(q.verify.max_reps >= q.verify.reps && q.verify.max_reps <= 10000, "verify_max_reps",
          std::to_string(q.verify.max_reps) + " is outside [verify_reps = " + std::to_string(q.verify.reps) + ", 10000]");
  require(q.verify.resolution > 0 && q.verify.resolution <= 1, "resolution",
          printed(q.verify.resolution) + " is outside (0, 1]");
  const auto& s = q.search;
  require(s.screen_reps >= 1 && s.screen_reps <= 100, "screen_reps", std::to_string(s.screen_reps) + " is outside [1, 100]");
  require(s.eta >= 2 && s.eta <= 100, "eta", std::to_string(s.eta) + " is outside [2, 100]");
  require(s.growth >= 2 && s.growth <= 10, "growth", std::to_string(s.growth) + " is outside [2, 10]");
  require(s.max_reps >= s.screen_reps && s.max_reps <= 1000, "max_reps",
          std::to_string(s.max_reps) + " is outside [screen_reps = " + std::to_string(s.screen_reps) + ", 1000]");
  require(q.classes.bin_width > 0 && q.classes.bin_width <= 1, "class_width",
          printed(q.classes.bin_width) + " is outside (0, 1]");
  require(q.classes.margin >= 0 && q.classes.margin <= 1, "class_margin", printed(q.classes.margin) + " is outside [0, 1]");
  require(s.final_pool >= 1 && s.final_pool <= 10000, "final_pool", std::to_string(s.final_pool) + " is outside [1, 10000]");
}

Outcome run_design(const Query& q, const std::atomic<bool>* interrupt, const StageProgress& progress) {
  const auto wall0 = std::chrono::steady_clock::now();
  Outcome out;
  out.candidates = generate(q.space, q.base);
  std::vector<int> alive;  // empty: all
  out.classes_used = q.class_prune && q.target.mu_d.set && !out.candidates.kept.empty();
  if (out.classes_used) {
    out.classes = prune_by_contact_class(q.base, out.candidates.kept, q.target, q.classes, interrupt, progress);
    out.interrupted = out.classes.interrupted;
    alive = out.classes.kept;
  }
  if (!out.interrupted && !out.candidates.kept.empty() && !(out.classes_used && alive.empty())) {
    SearchOptions so = q.search;
    so.final_pool = std::max(so.final_pool, q.top);  // never halve below what is verified
    if (out.classes_used) class_hints(out.classes, q.classes, out.candidates.kept.size(), so);
    out.search = successive_halving(q.base, out.candidates.kept, q.target, so, interrupt, progress, alive);
    out.interrupted = out.search.interrupted;
  }
  if (!out.interrupted && !out.search.ranking.empty()) {
    out.verified = verify(q.base, out.candidates.kept, out.search.ranking, q.target, q.top, q.verify, interrupt, progress,
                          out.interrupted);
    for (const auto& v : out.verified) out.feasible = out.feasible || v.meets_target;
  }
  out.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  return out;
}

}  // namespace sb::design
