// The active set after a switch, brought up to date only where the switch can have changed it.
//
// A switch changes whether a handful of blocks are mobile, so the runs (maximal stretches of
// mobile blocks) change only in the stretches around them; everywhere else the runs keep their
// spans, and their kinds too, except for grooves-only runs whose kind changes with time alone (a
// modal groove run whose transient has died becomes settled; a ringing one is checked against
// its affine path). Classifying every run at every switch, as rebuild() does at the start, cost
// O(N) per switch in scans, fills and copies; this costs what the switch changed. It makes the
// same classification to the last bit, because it applies the same rules (classify()) to every
// run whose kind can change and leaves the others as they are:
//   * a run within a renewed region (below) borders a switched block, so a rule could not have
//     kept it anyway;
//   * a run outside the regions has no switched block in it or beside it.
#include <algorithm>

#include "springblock/integrate/events/active_set.hpp"

namespace sb::event_detail {

void ActiveSet::update(const Chain& c, const State& s, const std::uint8_t* touched,
                       const std::vector<int>& touched_list) {
  ++work_.classifications;
  for (const BlockRange& r : prev_.fresh_runs) std::fill(prev_.fresh.begin() + r.lo, prev_.fresh.begin() + r.hi, 0);
  prev_.fresh_runs.clear();
  find_regions(c, s, touched_list);
  for (const BlockRange& region : work_.regions) renew_region(c, s, touched, region);
  retime_grooves(c, s, touched);
  list_stepped(s);
  update_events(c, s, touched, false);
}

// A switched block b can change the runs that hold b - 1, b or b + 1 (the blocks beside a run
// are its borders). Its region is b with the stretches of blocks mobile before or after the
// switch on both sides: the blocks just outside are stuck before and after, so every run, old or
// new, lies inside a region or outside all of them. Overlapping regions are merged.
void ActiveSet::find_regions(const Chain& c, const State& s, const std::vector<int>& touched_list) {
  work_.regions.clear();
  work_.switched.assign(touched_list.begin(), touched_list.end());
  std::sort(work_.switched.begin(), work_.switched.end());
  auto mobile_either = [&](int i) { return !c.contact[i] || s.dir[i] != 0 || prev_.dir[i] != 0; };
  for (int b : work_.switched) {
    if (!work_.regions.empty() && b < work_.regions.back().hi) continue;
    int lo = b, hi = b + 1;
    if (rules_.K_int > 0) {
      while (lo > 0 && mobile_either(lo - 1)) --lo;
      while (hi < N() && mobile_either(hi)) ++hi;
    }
    if (!work_.regions.empty() && lo <= work_.regions.back().hi)
      work_.regions.back().hi = std::max(work_.regions.back().hi, hi);
    else
      work_.regions.push_back({lo, hi});
  }
}

// The region's runs found afresh and classified (classify(), with the previous classification in
// hand, none for rebuild()); the old runs in it leave (a modal one is dropped: none can be kept).
void ActiveSet::renew_region(const Chain& c, const State& s, const std::uint8_t* touched, BlockRange region) {
  auto by_start = [](const Run& r, int i) { return r.span.lo < i; };
  const auto first = std::lower_bound(runs_.begin(), runs_.end(), region.lo, by_start);
  const auto last = std::lower_bound(first, runs_.end(), region.hi, by_start);
  work_.found.clear();
  find_runs(c, s, region.lo, region.hi, work_.found);
  // classify() reads the previous kinds, so every new kind is decided before any is written.
  for (Run& r : work_.found) r.kind = classify(r, s, touched);
  // A settled run found again as the same settled run keeps its record: its ends have been stuck
  // since it was made (a switch of one would have merged it into a larger run), so its path is
  // still the one recorded. Every other old run lets its record go.
  for (auto it = first; it != last; ++it) {
    const auto again = std::lower_bound(work_.found.begin(), work_.found.end(), it->span.lo, by_start);
    const bool kept = it->kind == kSettled && again != work_.found.end() && again->span.lo == it->span.lo &&
                      again->span.hi == it->span.hi && again->kind == kSettled;
    if (!kept) drop_old(*it);
  }
  std::fill(kind_.begin() + region.lo, kind_.begin() + region.hi, kStuck);
  for (std::vector<int>* list : {&list_.live, &list_.live_grooves}) {
    const auto from = std::lower_bound(list->begin(), list->end(), region.lo);
    list->erase(from, std::lower_bound(from, list->end(), region.hi));
  }
  for (Run& r : work_.found) assign(c, s, r, r.kind);
  // The runs after the region move only when their number in it changed (a memmove of the rest
  // of the chain's runs per switch otherwise).
  const std::size_t old_n = static_cast<std::size_t>(last - first), new_n = work_.found.size();
  const auto kept = std::copy(work_.found.begin(), work_.found.begin() + std::min(old_n, new_n), first);
  if (new_n < old_n) runs_.erase(kept, last);
  else runs_.insert(kept, work_.found.begin() + old_n, work_.found.end());
}

// Outside the regions only a grooves-only run that is modal or ringing can change kind, with time.
// A ringing one is stepped (list_.live_grooves). A modal one outside the regions has nothing in or beside
// it switched and is the run modal_ holds, so classify() keeps it modal until s.t reaches its
// settled_after: only those due (list_.settling) are visited. In block order, as a pass over
// every run would visit them. A run that changes kind joins the regions where it lies (wholly
// before region g), so they stay in block order.
void ActiveSet::retime_grooves(const Chain& c, const State& s, const std::uint8_t* touched) {
  work_.visit.assign(list_.live_grooves.begin(), list_.live_grooves.end());
  work_.due.clear();
  while (!list_.settling.empty() && list_.settling.top().first <= s.t) {
    if (settling(list_.settling.top())) work_.due.push_back(list_.settling.top()), work_.visit.push_back(list_.settling.top().second);
    list_.settling.pop();
  }
  std::sort(work_.visit.begin(), work_.visit.end());
  work_.visit.erase(std::unique(work_.visit.begin(), work_.visit.end()), work_.visit.end());
  std::size_t g = 0;  // the first region not before the run
  std::size_t cursor = 0;
  for (int lo : work_.visit) {
    Run& r = seek(cursor, lo);
    while (g < work_.regions.size() && work_.regions[g].hi <= r.span.lo) ++g;
    if (g < work_.regions.size() && work_.regions[g].lo <= r.span.lo) continue;  // renewed
    if (!r.grooves || (r.kind != kModal && r.kind != kStepped)) continue;
    const Kind kind = classify(r, s, touched);
    if (kind == r.kind) continue;
    drop_old(r);
    assign(c, s, r, kind);
    work_.regions.insert(work_.regions.begin() + static_cast<std::ptrdiff_t>(g), r.span);
    ++g;
  }
  // A due run still modal (in a renewed region, kept) is due again at the next switch.
  for (const auto& e : work_.due)
    if (settling(e)) list_.settling.push(e);
}

// Only blocks that switched, changed kind or were projected afresh, and their neighbours, can
// have a new event time (the rules in update_events do nothing for any other block), so only
// they are visited, in index order as rebuild's pass over every block would. They all lie in the
// regions (the retimed runs among them).
void ActiveSet::collect_candidates(const State& s, const std::uint8_t* touched) {
  work_.cand.clear();
  int last = -1;
  for (const BlockRange& r : work_.regions)
    for (int i = r.lo; i < r.hi; ++i) {
      if (s.dir[i] == prev_.dir[i] && kind_[i] == prev_.kind[i] && !prev_.fresh[i] && !touched[i]) continue;
      for (int j = std::max(i - 1, last + 1); j <= std::min(i + 1, N() - 1); ++j) work_.cand.push_back(j), last = j;
    }
}

}  // namespace sb::event_detail
