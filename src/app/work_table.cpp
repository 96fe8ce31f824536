#include "work_table.hpp"

#include <cstdio>

namespace sb::app {

// Sums over the repetitions, so a reader sees the ensemble's cost: each kind of work's count and
// time, its share of the repetitions' wall time, and the rest ("other": the driver's
// bookkeeping, step-size control, chain set-up), which the timed kinds leave out.
void print_work_table(const EnsembleResult& result) {
  WorkProfile w;
  double wall = 0;
  for (const auto& r : result.runs) w.add(r.work), wall += r.wall_s;
  std::fprintf(stderr, "work profile, summed over %zu repetitions (%.3f s of repetition wall time):\n",
               result.runs.size(), wall);
#define SB_COUNT(name, doc) std::fprintf(stderr, "  %-18s %12lld  %s\n", #name, static_cast<long long>(w.name), doc);
  SB_WORK_COUNTS(SB_COUNT)
#undef SB_COUNT
  if (!w.timed || wall <= 0) return;
  double timed = 0;
  auto row = [&](const char* name, double s, const char* doc) {
    std::fprintf(stderr, "  %-18s %10.4f s %5.1f%%  %s\n", name, s, 100 * s / wall, doc);
  };
#define SB_TIME(name, doc) row(#name, w.name, doc), timed += w.name;
  SB_WORK_TIMES(SB_TIME)
#undef SB_TIME
  row("other_s", wall - timed, "driver, step-size control, chain set-up, timer overhead");
}

}  // namespace sb::app
