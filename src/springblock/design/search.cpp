#include "springblock/design/search.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numeric>

namespace sb::design {
namespace {

// Adds one stage's repetitions of a candidate to its estimate.
void accumulate(Estimate& e, const EnsembleResult& r, int rung) {
  for (const RunResult& run : r.runs) {
    ++e.reps;
    e.cpu_s += run.cpu_s;
    if (std::isfinite(run.mu_s)) e.mu_s.push_back(run.mu_s);
    if (std::isfinite(run.mu_d)) e.mu_d.push_back(run.mu_d);
    if (std::isfinite(run.mu_s) && std::isfinite(run.mu_d) && run.mu_d > 0) e.ratio.push_back(run.mu_s / run.mu_d);
  }
  e.last_rung = rung;
}

// Whether a rung may stop each repetition at its first slip: when the query needs no mu_d, or
// in rung 0 when mu_s is targeted too (its optimistic score then ranks on mu_s alone, and the
// full runs are left to the candidates mu_s did not rule out).
bool rung_stops_at_slip(const Target& t, int rung) {
  return !t.needs_mu_d() || (rung == 0 && t.mu_s.set);
}

double prior(const SearchOptions& o, int k) {
  return k < static_cast<int>(o.mu_d_prior.size()) ? o.mu_d_prior[k] : std::nan("");
}

// The factor a rung's survivors are cut by: eta, or, before the first rung of full runs after one
// stopped at the first slip, the ratio of their costs per repetition when it is known (at least
// eta). Successive halving spends about the same budget on every rung (Karnin et al. 2013); a
// full run costs 10 to 30 runs to the first slip, so the same cut would make that rung cost 10
// to 30 times the screen.
double cut(const SearchOptions& o, const RungReport& r) {
  const int reps = r.candidates * r.reps_added;
  if (!r.stop_after_mu_s || o.full_rep_cpu_s <= 0 || reps == 0 || r.cpu_s <= 0) return o.eta;
  return std::max<double>(o.eta, o.full_rep_cpu_s / (r.cpu_s / reps));
}

}  // namespace

std::vector<EnsembleResult> run_stage(const std::vector<Scene>& scenes, const std::atomic<bool>* interrupt,
                                      const StageProgress& progress, const std::string& label, std::size_t chunk) {
  std::vector<EnsembleResult> out;
  out.reserve(scenes.size());
  const auto start = std::chrono::steady_clock::now();
  const double n = static_cast<double>(scenes.size());
  for (std::size_t first = 0; first < scenes.size(); first += chunk) {
    const std::size_t last = std::min(scenes.size(), first + chunk);
    const std::vector<Scene> part(scenes.begin() + static_cast<std::ptrdiff_t>(first),
                                  scenes.begin() + static_cast<std::ptrdiff_t>(last));
    std::function<void(double, double)> report;
    if (progress)
      report = [&, first, last](double f, double) {
        const double t = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        progress(label, (static_cast<double>(first) + f * static_cast<double>(last - first)) / n, t);
      };
    auto results = run_ensembles(part, interrupt, report);
    for (auto& r : results) out.push_back(std::move(r));
    if (interrupt && interrupt->load()) {
      out.resize(scenes.size());  // the rest never ran: interrupted, no repetition
      for (std::size_t k = last; k < scenes.size(); ++k) out[k].interrupted = true;
      break;
    }
  }
  return out;
}

Statistic Estimate::stat(Quantity q) const {
  return summarize(q == Quantity::MuS ? mu_s : q == Quantity::MuD ? mu_d : ratio);
}

std::uint64_t stage_seed(std::uint64_t user_seed, int stage) {
  // A tag, so that a stage's seed is not the user seed of some other query's repetition stream.
  return rep_seed(user_seed ^ 0x64657369676e5eedULL, stage);
}

Scene candidate_scene(const Scene& base, const Candidate& c, int reps, std::uint64_t seed, bool stop_after_mu_s) {
  Scene s = base;
  s.pattern = c.spec;
  s.reps = reps;
  s.seed = seed;
  s.run.stop_after_mu_s = stop_after_mu_s;
  s.observe = Observables{};
  return s;
}

double optimistic_score(const Target& t, const Estimate& e, double prior, double margin) {
  Target measured = t;
  double from_prior = 0;
  if (e.mu_d.empty()) {
    measured.mu_d.set = measured.ratio.set = false;
    if (measured.objective != Quantity::MuS) measured.goal = Goal::None;
    if (t.mu_d.set && std::isfinite(prior)) from_prior = std::max(0.0, distance(t.mu_d, prior) - margin);
  }
  // The estimate keeps only finite values, so summarize's mean is the plain mean (NaN if none).
  return score(measured, summarize(e.mu_s).mean, e.mu_d.empty() ? 1.0 : summarize(e.mu_d).mean) + from_prior;
}

SearchResult successive_halving(const Scene& base, const std::vector<Candidate>& candidates, const Target& target,
                                const SearchOptions& o, const std::atomic<bool>* interrupt,
                                const StageProgress& progress, std::vector<int> alive) {
  SearchResult out;
  out.estimates.resize(candidates.size());
  if (alive.empty()) {
    alive.resize(candidates.size());
    std::iota(alive.begin(), alive.end(), 0);
  }
  int reps_total = 0;
  for (int rung = 0;; ++rung) {
    const int target_reps = rung == 0 ? o.screen_reps : std::min(o.max_reps, reps_total * o.growth);
    RungReport rep{static_cast<int>(alive.size()), target_reps - reps_total, target_reps,
                   rung_stops_at_slip(target, rung), stage_seed(base.seed, rung + 1), 0, 0};
    std::vector<Scene> scenes;
    for (int k : alive) scenes.push_back(candidate_scene(base, candidates[k], rep.reps_added, rep.seed, rep.stop_after_mu_s));
    const std::string label = "rung " + std::to_string(rung) + ": " + std::to_string(alive.size()) + " candidates x " +
                              std::to_string(rep.reps_added) + (rep.stop_after_mu_s ? " reps to first slip" : " full reps");
    const auto results = run_stage(scenes, interrupt, progress, label);
    for (std::size_t i = 0; i < alive.size(); ++i) {
      accumulate(out.estimates[alive[i]], results[i], rung);
      rep.wall_s += results[i].wall_s;
      for (const auto& r : results[i].runs) rep.cpu_s += r.cpu_s;
      out.interrupted = out.interrupted || results[i].interrupted;
    }
    out.rungs.push_back(rep);
    reps_total = target_reps;
    std::vector<double> key(candidates.size());
    for (int k : alive) key[k] = optimistic_score(target, out.estimates[k], prior(o, k), o.prior_margin);
    std::stable_sort(alive.begin(), alive.end(), [&](int a, int b) { return key[a] < key[b]; });
    // Stop at the final pool (or the repetition cap) unless mu_d is wanted and still unmeasured.
    const bool mu_d_pending = target.needs_mu_d() && rep.stop_after_mu_s;
    const bool done = (static_cast<int>(alive.size()) <= o.final_pool || reps_total >= o.max_reps) && !mu_d_pending;
    if (out.interrupted || done) break;
    const int keep = std::max(o.final_pool, static_cast<int>(std::ceil(alive.size() / cut(o, rep))));
    alive.resize(std::min(alive.size(), static_cast<std::size_t>(keep)));
  }
  out.ranking = alive;
  return out;
}

}  // namespace sb::design
