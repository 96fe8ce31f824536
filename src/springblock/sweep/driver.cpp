#include "springblock/sweep/driver.hpp"

#include <algorithm>
#include <chrono>
#include <map>
#include <memory>

#include "springblock/errors.hpp"
#include "springblock/io.hpp"
#include "springblock/sweep/expand.hpp"

namespace sb::sweep {
namespace {

using Clock = std::chrono::steady_clock;

std::string unit_name(const std::vector<Unit>& units, int id) {
  return std::to_string(id) + " (scene " + std::to_string(units[id].scene) + " rep " + std::to_string(units[id].rep) + ")";
}

// "rank 1: 3 (scene 1 rep 0), 7 (...); rank 2: ..." for (unit, rank) pairs in flight or lost.
std::string by_rank(const std::vector<std::pair<int, int>>& list, const std::vector<Unit>& units) {
  std::map<int, std::string> per_rank;
  for (const auto& [unit, rank] : list) {
    auto& s = per_rank[rank];
    s += (s.empty() ? "" : ", ") + unit_name(units, unit);
  }
  std::string out;
  for (auto& [rank, s] : per_rank) out += (out.empty() ? "" : "; ") + ("rank " + std::to_string(rank) + ": " + s);
  return out;
}

// What the coordinator keeps while units come in: the checkpoint, the results as scenes complete,
// the per-unit records file if asked, counts for the progress and the cost of writing the
// checkpoint. Nothing here grows with a unit's record: per unit only a few bytes (its scene,
// whether it is done, where its record starts in the checkpoint).
struct Ledger {
  Checkpoint& checkpoint;
  StreamedResults& results;
  const std::vector<Unit>& units;
  std::vector<double> scene_cost;  // unit_cost of each scene's units
  std::unique_ptr<LineFile> unit_records;
  double cost_total = 0, cost_before = 0, cost_now = 0;
  int computed = 0;
  double checkpoint_s = 0;
  Clock::time_point start = Clock::now();
  double cost(int id) const { return scene_cost[units[id].scene]; }
  double elapsed() const { return std::chrono::duration<double>(Clock::now() - start).count(); }
};

Progress progress(const Ledger& l, const parallel::Scheduler& s) {
  Progress p;
  p.done = l.checkpoint.done_count();
  p.total = static_cast<int>(l.units.size());
  p.computed = l.computed;
  p.ranks = s.ranks();
  p.threads = s.threads();
  p.fraction = (l.cost_before + l.cost_now) / l.cost_total;
  p.elapsed_s = l.elapsed();
  if (l.cost_now > 0) p.eta_s = p.elapsed_s * (l.cost_total - l.cost_before - l.cost_now) / l.cost_now;
  return p;
}

// Times a write to the checkpoint into the ledger's checkpoint_s.
template <class Write>
void timed(Ledger& l, Write write) {
  const auto t0 = Clock::now();
  write();
  l.checkpoint_s += std::chrono::duration<double>(Clock::now() - t0).count();
}

parallel::Hooks hooks(Ledger& l, const Events& events, const parallel::Scheduler& s) {
  parallel::Hooks h;
  h.assigned = [&l](const std::vector<int>& ids, int rank) { timed(l, [&] { l.checkpoint.assigned(ids, rank); }); };
  h.settled = [&l] {
    timed(l, [&] { l.checkpoint.flush(); });
    if (l.unit_records) l.unit_records->flush();
  };
  h.finished = [&l](int id, int, nlohmann::json result) {
    const auto& line = result.at("record").get_ref<const std::string&>();
    timed(l, [&] { l.checkpoint.finished(id, line); });
    if (l.unit_records) l.unit_records->hold(line);
    l.results.add(l.units[id].scene, l.units[id].rep, result.at("numbers"));
    l.cost_now += l.cost(id);
    ++l.computed;
  };
  if (events.progress) h.tick = [&l, &events, &s] { events.progress(progress(l, s)); };
  return h;
}

// Units not in the checkpoint, the dearest first (unit_cost), so that no long unit starts last;
// equal costs keep their order.
std::vector<int> pending_units(const Ledger& l) {
  std::vector<int> ids;
  for (int id = 0; id < static_cast<int>(l.units.size()); ++id)
    if (!l.checkpoint.done(id)) ids.push_back(id);
  std::stable_sort(ids.begin(), ids.end(), [&](int a, int b) { return l.cost(a) > l.cost(b); });
  return ids;
}

Resumed resumed(const Checkpoint& cp, const std::vector<Unit>& units, int pending) {
  Resumed r{cp.path(), cp.done_count(), static_cast<int>(units.size()), pending,
            static_cast<int>(cp.lost().size()), ""};
  std::vector<std::pair<int, int>> lost;
  for (const auto& u : cp.lost()) lost.emplace_back(u.unit, u.rank);
  r.lost_units = by_rank(lost, units);
  return r;
}

nlohmann::json header(const OutputOptions& o, const std::vector<SweepScene>& scenes, const Ledger& l,
                      const parallel::Outcome& out, const parallel::Scheduler& s, const std::string& command_line) {
  return {{"kind", "sweep"},
          {"file", o.file},
          {"scenes", scenes.size()},
          {"units", l.units.size()},
          {"computed_units", l.computed},
          {"resumed_units", l.checkpoint.done_count() - l.computed},
          {"ranks", s.ranks()},
          {"threads_per_rank", s.threads()},
          {"wall_s", l.elapsed()},
          {"lost_ranks", out.lost_ranks},
          {"messages", out.messages},
          {"message_s", out.message_s},
          {"checkpoint_s", l.checkpoint_s},
          {"provenance", provenance(command_line)}};
}

Report report(const OutputOptions& o, const std::vector<SweepScene>& scenes, const Ledger& l,
              const parallel::Outcome& out, const parallel::Scheduler& s) {
  Report r;
  r.interrupted = out.interrupted;
  r.scenes = static_cast<int>(scenes.size());
  r.units = static_cast<int>(l.units.size());
  r.computed = l.computed;
  r.resumed = l.checkpoint.done_count() - l.computed;
  r.ranks = s.ranks();
  r.threads = s.threads();
  r.wall_s = l.elapsed();
  r.out = out_path(o);
  r.partial = l.results.partial();
  r.checkpoint = l.checkpoint.path();
  r.scenes_complete = l.results.scenes_complete();
  std::vector<std::pair<int, int>> flight;
  for (const auto& f : out.unfinished) flight.emplace_back(f.id, f.rank);
  r.in_flight = by_rank(flight, l.units);
  r.notes = out.notes;
  r.summary = l.results.summary();
  return r;
}

}  // namespace

Report run_sweep(const Spec& spec, const OutputOptions& o, parallel::Scheduler& sched,
                 const std::atomic<bool>* interrupt, const Events& events, const std::string& command_line) {
  const bool lead = sched.coordinator();
  Report quiet;  // what another rank returns
  quiet.coordinator = false;
  std::vector<SweepScene> scenes;
  std::vector<Unit> units;
  try {
    scenes = expand(spec);  // on every rank: a unit id means the same there
    units = make_units(scenes);
  } catch (const InputError&) {
    if (lead) throw;
    // Rank 0 found the same and says so. A worker failing first would make mpirun abort the
    // job, at times before rank 0 has printed a word: it leaves quietly instead.
    quiet.refused = true;
    return quiet;
  }
  StreamedResults results(scenes, out_path(o));
  std::unique_ptr<Checkpoint> cp;
  std::exception_ptr refused;
  if (lead) try {
      cp = open_checkpoint(o, scenes, units, results);
    } catch (...) {
      refused = std::current_exception();
    }
  if (!sched.agree(!refused)) {
    if (refused) std::rethrow_exception(refused);
    quiet.refused = true;
    return quiet;
  }
  // A unit's result travels as its record's text (written to the checkpoint as it is) and the
  // few numbers its scene's statistics need: the coordinator parses those, not the record.
  auto run_one = [&, rank = sched.rank()](int id, const std::atomic<bool>* stop) -> nlohmann::json {
    auto record = run_unit(scenes, units, id, stop);
    if (record.is_null()) return record;
    record["rank"] = rank;
    return {{"record", record.dump()}, {"numbers", record_numbers(record)}};
  };
  if (!lead) {
    sched.run({}, run_one, {}, interrupt);
    return quiet;
  }
  results.start(partial_header(o, scenes, units, command_line));
  Ledger l{*cp, results, units, {}, nullptr};
  if (!o.units.empty()) l.unit_records = start_unit_records(o.units, *cp);
  for (const auto& s : scenes) l.scene_cost.push_back(unit_cost(s.scene));
  for (int id = 0; id < static_cast<int>(units.size()); ++id) {
    l.cost_total += l.cost(id);
    if (cp->done(id)) l.cost_before += l.cost(id);
  }
  const auto ids = pending_units(l);
  if (o.resume && events.resumed) events.resumed(resumed(*cp, units, static_cast<int>(ids.size())));
  const auto outcome = sched.run(ids, run_one, hooks(l, events, sched), interrupt);
  if (outcome.interrupted) {
    cp->sync();
    return report(o, scenes, l, outcome, sched);
  }
  cp->sync();  // every record on disk before the results are written from them
  results.complete(header(o, scenes, l, outcome, sched, command_line), *cp);
  if (l.unit_records) l.unit_records->rename_to(o.units);
  cp->remove();  // the results hold every unit now
  return report(o, scenes, l, outcome, sched);
}

}  // namespace sb::sweep
