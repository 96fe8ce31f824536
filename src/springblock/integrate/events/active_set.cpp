#include "springblock/integrate/events/active_set.hpp"
#include "springblock/infinity.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>

namespace sb::event_detail {
namespace {

// The scans for runs and for switched blocks read 8 blocks' bytes at once to skip stretches with
// nothing to do: the blocks visited, and their order, are those of the byte-by-byte loop, so
// results are bit-identical.
std::uint64_t load8(const void* p) {
  std::uint64_t x;
  std::memcpy(&x, p, sizeof x);
  return x;
}
constexpr std::uint64_t kOnes = 0x0101010101010101ULL;
// A settled run's neglected transient, as a fraction of the stepper's absolute tolerance.
constexpr double kSettleFrac = 0.1;

// lo in or out of the sorted list.
void keep_listed(std::vector<int>& list, int lo, bool in) {
  const auto at = std::lower_bound(list.begin(), list.end(), lo);
  const bool held = at != list.end() && *at == lo;
  if (in && !held) list.insert(at, lo);
  else if (!in && held) list.erase(at);
}

}  // namespace

ActiveSet::ActiveSet(const Chain& c, RunStore& store, bool settle_grooves, double atol_u, double atol_v,
                     int modal_max_run, int modal_max_groove, double t_end)
    : rules_{c.K_int,
             settle_grooves,
             settle_grooves && c.K_int > 0 ? modal_max_run : 0,
             settle_grooves && c.K_int > 0 ? modal_max_groove : 0,
             4.0 * M_PI / c.omega_max(),
             kSettleFrac * atol_u,
             kSettleFrac * atol_v,
             t_end},
      modal_(c, store),
      prev_{std::vector<std::int8_t>(c.N, 0), std::vector<std::uint8_t>(c.N, kStuck), std::vector<std::uint8_t>(c.N, 0), {}},
      kind_(c.N, kStuck),
      store_(store),
      events_(c.N),
      forces_(c.N) {
  modal_.set_settle_scales(rules_.eps_u, rules_.eps_v);
  runs_.reserve(c.N);
  list_.stepped.reserve(c.N);
  list_.watched.reserve(c.N);
}

bool ActiveSet::settled_now(const State& s, BlockRange r) const {
  if (!rules_.settle_grooves) return false;
  const RunShape& sh = store_.shapes().of(r);
  const double uL = sh.path.left ? s.u[r.lo - 1] : 0.0, uR = sh.path.right ? s.u[r.hi] : 0.0;
  for (int k = 0; k < r.size(); ++k) {
    const int i = r.lo + k;
    const double A = sh.path.A(k, uL, uR);
    if (std::fabs(s.u[i] - (A + sh.path.B[k] * s.t)) > rules_.eps_u) return false;
    if (std::fabs(s.v[i] - sh.path.B[k]) > rules_.eps_v) return false;
  }
  return true;
}

// The whole chain is one region with nothing classified before it (every block stuck in kind_,
// no run, no mark): every run is new, every modal run projected, every event time computed.
void ActiveSet::rebuild(const Chain& c, const State& s) {
  if (work_.classifications > 0) throw std::logic_error("ActiveSet::rebuild: a new set only");
  ++work_.classifications;
  renew_region(c, s, nullptr, {0, N()});
  list_stepped(s);
  update_events(c, s, nullptr, true);
}

void ActiveSet::find_runs(const Chain& c, const State& s, int lo, int hi, std::vector<Run>& out) const {
  const std::uint8_t* contact = c.contact.data();
  const std::int8_t* dir = s.dir.data();
  for (int i = lo; i < hi;) {
    // Eight stuck contact blocks in a row: nothing starts here.
    if (i + 8 <= hi && load8(contact + i) == kOnes && load8(dir + i) == 0) {
      i += 8;
      continue;
    }
    const bool mobile_i = !contact[i] || dir[i] != 0;
    if (!mobile_i) {
      ++i;
      continue;
    }
    int j = i;
    bool grooves = !contact[i];
    // Without internal springs every block is its own system.
    if (rules_.K_int > 0)
      while (j + 1 < hi) {
        if (j + 9 <= hi && load8(contact + j + 1) == 0) {  // eight groove blocks: all mobile
          j += 8;
          continue;
        }
        if (contact[j + 1] && dir[j + 1] == 0) break;
        ++j;
        grooves = grooves && !contact[j];
      }
    out.push_back(Run{{i, j + 1}, kStepped, grooves, s.t});
    i = j + 1;
  }
}

bool ActiveSet::switched(const State& s, const std::uint8_t* touched, int i) const {
  return i >= 0 && i < N() && (s.dir[i] != prev_.dir[i] || (touched != nullptr && touched[i]));
}

bool ActiveSet::untouched(const State& s, const std::uint8_t* touched, BlockRange r) const {
  // Eight blocks at a time, as find_runs: a long groove run is checked in a few words.
  const int lo = std::max(r.lo - 1, 0), hi = std::min(r.hi + 1, N());
  const std::int8_t* dir = s.dir.data();
  const std::int8_t* prev = prev_.dir.data();
  int i = lo;
  for (; i + 8 <= hi; i += 8)
    if (load8(dir + i) != load8(prev + i) || (touched != nullptr && load8(touched + i) != 0)) return false;
  for (; i < hi; ++i)
    if (switched(s, touched, i)) return false;
  return true;
}

// A grooves-only run is always a whole groove segment; it keeps its A, B while it stays
// grooves-only, because its stuck boundary blocks have not moved since they were computed.
ActiveSet::Kind ActiveSet::classify(const Run& r, const State& s, const std::uint8_t* touched) {
  if (r.grooves) {
    const std::uint8_t was = kind_[r.span.lo];
    if (was == kSettled) return kSettled;
    // A modal groove run that nothing in or beside it switched is kept, and was not brought to
    // s.t (materialise_near): whether its transient is gone comes from its modes' envelope.
    if (was == kModal && untouched(s, touched, r.span) && modal_.same_run(r.span.lo, r.span.hi))
      return s.t >= modal_.settled_after(r.span.lo) ? kSettled : kModal;
    // Was stepped, or modal and touched (ringing, or part of an active run), or never
    // classified: judged against its path.
    if (settled_now(s, r.span)) return kSettled;
  }
  // A run holding a contact block starts stepped; promote_runs() makes it modal if it lasts.
  return r.grooves && r.span.hi - r.span.lo <= rules_.modal_max_groove ? kModal : kStepped;
}

// A run that stays modal with nothing in or beside it switched keeps its coordinates and its
// blocks' event times: assign is not called for it.
void ActiveSet::assign(const Chain& c, const State& s, Run& r, Kind kind) {
  r.kind = kind;
  std::fill(kind_.begin() + r.span.lo, kind_.begin() + r.span.hi, kind);
  keep_listed(list_.live, r.span.lo, kind == kStepped);
  if (r.grooves) keep_listed(list_.live_grooves, r.span.lo, kind == kStepped);
  if (kind == kSettled) {
    if (store_.owner(r.span.lo) != RunStore::kSettled || store_.exact(r.span) == nullptr)
      store_.project(c, r.span, s.t, s.u.data(), s.v.data(), s.dir.data(), RunStore::kSettled, false);
    return;
  }
  if (kind != kModal) return;
  modal_.add(c, s, r.span.lo, r.span.hi, r.grooves);
  if (r.grooves && modal_.settled_after(r.span.lo) < kInf) list_.settling.push({modal_.settled_after(r.span.lo), r.span.lo});
  std::fill(prev_.fresh.begin() + r.span.lo, prev_.fresh.begin() + r.span.hi, 1);
  prev_.fresh_runs.push_back(r.span);
}

void ActiveSet::drop_old(const Run& r) {
  if (r.kind == kModal) modal_.drop(r.span.lo);
  else if (r.kind == kSettled && store_.owner(r.span.lo) == RunStore::kSettled) store_.drop(r.span.lo);
}

bool ActiveSet::settling(const std::pair<double, int>& e) const {
  const int lo = e.second;
  return kind_[lo] == kModal && modal_.run_start(lo) == lo && modal_.settled_after(lo) == e.first;
}

ActiveSet::Run& ActiveSet::seek(std::size_t& cursor, int lo) {
  std::size_t step = 1;
  while (cursor + step < runs_.size() && runs_[cursor + step].span.lo < lo) step *= 2;
  const auto first = runs_.begin() + static_cast<std::ptrdiff_t>(cursor + step / 2);
  const auto last = runs_.begin() + static_cast<std::ptrdiff_t>(std::min(cursor + step + 1, runs_.size()));
  const auto at = std::lower_bound(first, last, lo, [](const Run& r, int i) { return r.span.lo < i; });
  cursor = static_cast<std::size_t>(at - runs_.begin());
  return *at;
}

void ActiveSet::list_stepped(const State& s) {
  list_.stepped.clear();
  list_.watched.clear();
  list_.ringing.clear();
  list_.next_promotion = kInf;
  auto list = [&](const Run& r) {
    if (r.kind != kStepped) return;
    if (r.grooves) list_.ringing.push_back(static_cast<int>(&r - runs_.data()));
    else if (r.span.hi - r.span.lo <= rules_.modal_max) list_.next_promotion = std::min(list_.next_promotion, r.formed + rules_.promote_age);
    list_.stepped.push_back(r.span);
    // In block order; a stuck block between two stepped runs is listed once.
    if (rules_.K_int > 0 && r.span.lo > 0 && (list_.watched.empty() || list_.watched.back() != r.span.lo - 1))
      list_.watched.push_back(r.span.lo - 1);
    for (int i = r.span.lo; i < r.span.hi; ++i)
      if (s.dir[i] != 0) list_.watched.push_back(i);
    if (rules_.K_int > 0 && r.span.hi < N()) list_.watched.push_back(r.span.hi);
  };
  // The same runs in the same order either way: a pass over every run where most are stepped (a
  // smooth chain), the stepped ones sought where they are few among settled and modal runs.
  if (2 * list_.live.size() >= runs_.size()) {
    for (const Run& r : runs_) list(r);
  } else {
    std::size_t cursor = 0;
    for (int lo : list_.live) list(seek(cursor, lo));
  }
}

void ActiveSet::materialise(double t, double* u, double* v, bool at_sample, bool ends_only) {
  // A settled run is grooves only, so ends_only leaves its interior rows as they are, as for a
  // modal groove run (materialise_near writes a whole run before a switch reads it).
  for (const Run& r : runs_)
    if (r.kind == kSettled) store_.write_path(store_.run(r.span.lo), t, u, v, ends_only);
  if (any_modal()) modal_.materialise(t, u, v, at_sample, ends_only ? ModalRuns::Rows::kGrooveEnds : ModalRuns::Rows::kEvery);
}

void ActiveSet::materialise_live(double t, double* u, double* v) {
  for (int i : forces_.live_blocks())
    for (int j : {i - 1, i + 1})
      if (j >= 0 && j < N() && kind_[j] == kSettled) u[j] = store_.path_u(j, t), v[j] = store_.B(j);
  // The live blocks are the stuck neighbours of the modal runs: only end rows are read.
  if (any_modal()) modal_.materialise(t, u, v, true, ModalRuns::Rows::kEnds);
}

void ActiveSet::materialise_near(double t, double* u, double* v, const std::vector<int>& blocks) {
  work_.done.clear();
  for (int b : blocks)
    for (int j = b - 1; j <= b + 1; ++j) {
      if (j < 0 || j >= N() || (kind_[j] != kSettled && kind_[j] != kModal)) continue;
      // The whole run: it may merge into a new run that is stepped or projected from s.u. Its
      // end rows being current says nothing of its interior (a sample writes only the ends),
      // so only a run written in this call is skipped (a few runs at most).
      const RunStore::Run& r = store_.run(j);
      if (std::find(work_.done.begin(), work_.done.end(), r.lo) != work_.done.end()) continue;
      if (kind_[j] == kSettled) store_.write_path(r, t, u, v);
      else modal_.materialise_run(j, t, u, v);
      work_.done.push_back(r.lo);
    }
}

}  // namespace sb::event_detail
