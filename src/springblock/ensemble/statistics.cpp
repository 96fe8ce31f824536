// Mean, sample standard deviation and standard error of each observable over the repetitions.
#include "springblock/ensemble/statistics.hpp"

#include <cmath>

namespace sb {

Statistic summarize(const std::vector<double>& values) {
  Statistic s;
  double sum = 0;
  for (double x : values)
    if (std::isfinite(x)) sum += x, ++s.n;
  if (s.n == 0) {
    s.mean = s.std = s.sem = std::nan("");
    return s;
  }
  s.mean = sum / s.n;
  double ss = 0;
  for (double x : values)
    if (std::isfinite(x)) ss += (x - s.mean) * (x - s.mean);
  s.std = s.n > 1 ? std::sqrt(ss / (s.n - 1)) : 0.0;  // sample standard deviation
  s.sem = s.std / std::sqrt(static_cast<double>(s.n));
  return s;
}

const std::vector<Observable>& observables() {
#define SB_ROW(name, unit, extractor, summary) \
  Observable{#name, unit, &FrictionObserver::extractor, summary, &RunResult::name, &EnsembleResult::name},
  static const std::vector<Observable> table = {SB_OBSERVABLES(SB_ROW)};
#undef SB_ROW
  return table;
}

namespace ensemble_detail {

void summarize_runs(EnsembleResult& out) {
  std::vector<double> values(out.runs.size());
  for (const auto& o : observables()) {
    for (std::size_t i = 0; i < out.runs.size(); ++i) values[i] = out.runs[i].*o.value;
    out.*o.statistic = summarize(values);
  }
  out.contact_fraction = out.runs.empty() ? 0 : out.runs[0].contact_fraction;
}

}  // namespace ensemble_detail

EnsembleResult ensemble_from_runs(std::vector<RunResult> runs) {
  EnsembleResult e;
  e.runs = std::move(runs);
  e.finished_reps = static_cast<int>(e.runs.size());
  ensemble_detail::summarize_runs(e);
  return e;
}

}  // namespace sb
