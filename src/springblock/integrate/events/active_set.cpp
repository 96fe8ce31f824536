#include "springblock/integrate/events/active_set.hpp"
#include "springblock/integrate/linear/run_stiffness.hpp"

#include <gsl/gsl_linalg.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

namespace sb::event_detail {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// rebuild() runs after every switch, and its scans over all N blocks were a tenth of a table
// row's time, although a switch changes a handful of blocks. These read 8 blocks' bytes at once
// to skip runs of blocks with nothing to do: the blocks visited, and their order, are those of
// the byte-by-byte loop, so results are bit-identical.
std::uint64_t load8(const void* p) {
  std::uint64_t x;
  std::memcpy(&x, p, sizeof x);
  return x;
}
constexpr std::uint64_t kOnes = 0x0101010101010101ULL;
// A settled run's neglected transient, as a fraction of the stepper's absolute tolerance.
constexpr double kSettleFrac = 0.1;

// Solve the symmetric tridiagonal system (diag, off) x = rhs with GSL (n = 1 by hand: GSL
// rejects an empty off-diagonal).
void solve_tridiag(std::vector<double>& diag, std::vector<double>& off, std::vector<double>& rhs, double* x,
                   int n) {
  if (n == 1) {
    x[0] = rhs[0] / diag[0];
    return;
  }
  gsl_vector_view d = gsl_vector_view_array(diag.data(), n);
  gsl_vector_view e = gsl_vector_view_array(off.data(), n - 1);
  gsl_vector_view b = gsl_vector_view_array(rhs.data(), n);
  gsl_vector_view out = gsl_vector_view_array(x, n);
  gsl_linalg_solve_symm_tridiag(&d.vector, &e.vector, &b.vector, &out.vector);
}

}  // namespace

ActiveSet::ActiveSet(const Chain& c, bool settle_grooves, double atol_u, double atol_v, int modal_max_run,
                     int modal_max_groove, double t_end)
    : N_(c.N),
      K_int_(c.K_int),
      settle_grooves_(settle_grooves),
      modal_max_(settle_grooves && c.K_int > 0 ? modal_max_run : 0),
      modal_max_groove_(settle_grooves && c.K_int > 0 ? modal_max_groove : 0),
      t_end_(t_end),
      modal_(c),
      dir_prev_(c.N, 0),
      kind_prev_(c.N, kStuck),
      eps_u_(kSettleFrac * atol_u),
      eps_v_(kSettleFrac * atol_v),
      kind_(c.N, kStuck),
      A_(c.N, 0.0),
      B_(c.N, 0.0),
      t_cross_(c.N, kInf),
      recheck_(c.N, 0),
      fresh_(c.N, 0),
      diag_(c.N),
      off_(c.N),
      rhs_(c.N) {
  modal_.set_quiet_scales(eps_u_, eps_v_);
  while (P_ < N_) P_ *= 2;
  tree_.assign(2 * P_, -1);
  for (int i = 0; i < N_; ++i) tree_[P_ + i] = i;
  for (int n = P_ - 1; n >= 1; --n) tree_[n] = earlier(tree_[2 * n + 1], tree_[2 * n]) ? tree_[2 * n + 1] : tree_[2 * n];
  tree_real_ = tree_;
  dirty_.assign(N_, 0);
  runs_.reserve(c.N);
  stepped_.reserve(c.N);
  watched_.reserve(c.N);
}

const ActiveSet::Shape& ActiveSet::shape(const Chain& c, int n, bool left, bool right) {
  const auto key = std::make_tuple(n, left, right);
  auto it = shapes_.find(key);
  if (it != shapes_.end()) return it->second;
  Shape sh{std::vector<double>(n), std::vector<double>(n), std::vector<double>(n), std::vector<double>(n)};
  auto solve = [&](auto&& rhs, std::vector<double>& x) {
    for (int k = 0; k < n; ++k) {
      diag_[k] = run_stiffness_diagonal(c.K_s, K_int_, n, k, left, right);
      off_[k] = -K_int_;
      rhs_[k] = rhs(k);
    }
    solve_tridiag(diag_, off_, rhs_, x.data(), n);
  };
  solve([&](int) { return c.K_s * c.v_slider; }, sh.B);
  solve([&](int k) { return -c.m * c.gamma * sh.B[k]; }, sh.a0);
  solve([&](int k) { return k == 0 && left ? K_int_ : 0.0; }, sh.gL);
  solve([&](int k) { return k == n - 1 && right ? K_int_ : 0.0; }, sh.gR);
  return shapes_.emplace(key, std::move(sh)).first->second;
}

void ActiveSet::particular(const Chain& c, const State& s, BlockRange r) {
  const int n = r.hi - r.lo;
  const bool left = r.lo > 0, right = r.hi < N_;  // held by a stuck block there (else a free end)
  const Shape& sh = shape(c, n, left, right);
  const double uL = left ? s.u[r.lo - 1] : 0.0, uR = right ? s.u[r.hi] : 0.0;
  for (int k = 0; k < n; ++k) {
    B_[r.lo + k] = sh.B[k];
    A_[r.lo + k] = sh.a0[k] + uL * sh.gL[k] + uR * sh.gR[k];
  }
}

bool ActiveSet::settled_now(const State& s, BlockRange r) const {
  if (!settle_grooves_) return false;
  for (int i = r.lo; i < r.hi; ++i) {
    if (std::fabs(s.u[i] - (A_[i] + B_[i] * s.t)) > eps_u_) return false;
    if (std::fabs(s.v[i] - B_[i]) > eps_v_) return false;
  }
  return true;
}

void ActiveSet::rebuild(const Chain& c, const State& s, const std::uint8_t* touched) {
  // A grooves-only run is always a whole groove segment; it keeps its A, B while it stays
  // grooves-only, because its stuck boundary blocks have not moved since they were computed.
  // kind_ still holds the previous classification until it is refilled below.
  runs_.clear();
  const std::uint8_t* contact = c.contact.data();
  const std::int8_t* dir = s.dir.data();
  for (int i = 0; i < N_;) {
    // Eight stuck contact blocks in a row: nothing starts here.
    if (i + 8 <= N_ && load8(contact + i) == kOnes && load8(dir + i) == 0) {
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
    if (K_int_ > 0)
      while (j + 1 < N_) {
        if (j + 9 <= N_ && load8(contact + j + 1) == 0) {  // eight groove blocks: all mobile
          j += 8;
          continue;
        }
        if (contact[j + 1] && dir[j + 1] == 0) break;
        ++j;
        grooves = grooves && !contact[j];
      }
    runs_.push_back(Run{{i, j + 1}, kStepped, grooves});
    i = j + 1;
  }
  auto switched = [&](int i) {
    return i >= 0 && i < N_ && (s.dir[i] != dir_prev_[i] || (touched != nullptr && touched[i]));
  };
  auto untouched = [&](BlockRange sp) {
    for (int i = sp.lo - 1; i <= sp.hi; ++i)
      if (switched(i)) return false;
    return true;
  };
  for (Run& r : runs_) {
    if (r.grooves) {
      const std::uint8_t was = kind_[r.span.lo];
      if (was == kSettled) {
        r.kind = kSettled;
        continue;
      }
      // A modal groove run that nothing in or beside it switched is kept, and was not brought
      // to s.t (materialise_near): whether its transient is gone comes from its modes' envelope.
      // Its A, B still hold: its stuck ends have not moved since they were computed.
      if (was == kModal && untouched(r.span) && modal_.same_run(r.span.lo, r.span.hi)) {
        r.kind = s.t >= modal_.quiet_after(r.span.lo) ? kSettled : kModal;
        continue;
      }
      // Was stepped, or modal and touched (ringing, or part of an active run), or never
      // classified: new A, B.
      particular(c, s, r.span);
      if (settled_now(s, r.span)) {
        r.kind = kSettled;
        continue;
      }
    }
    if (r.span.hi - r.span.lo <= (r.grooves ? modal_max_groove_ : modal_max_)) r.kind = kModal;
  }
  kind_prev_.swap(kind_);
  std::fill(kind_.begin(), kind_.end(), kStuck);
  for (const Run& r : runs_) std::fill(kind_.begin() + r.span.lo, kind_.begin() + r.span.hi, r.kind);
  list_stepped(s);

  // Modal runs: a run none of whose blocks or stuck neighbours switched keeps its coordinates
  // and its blocks' stop times; the others are projected afresh at s.t.
  std::fill(fresh_.begin(), fresh_.end(), 0);
  if (any_modal()) {
    modal_.begin(s);
    for (const Run& r : runs_) {
      if (r.kind != kModal) continue;
      bool keep = kind_prev_[r.span.lo] == kModal;
      for (int i = r.span.lo - 1; keep && i <= r.span.hi; ++i) keep = !switched(i);
      if (modal_.add(c, s, r.span.lo, r.span.hi, keep, r.grooves))
        for (int i = r.span.lo; i < r.span.hi; ++i) fresh_[i] = 1;
    }
    modal_.end();
  }
  // Events. Closed-form crossings and the kept modal events first, then the fresh modal
  // searches (finish_events).
  // Only blocks that switched, changed kind or were projected afresh, and their neighbours, can
  // have a new event time (the rules below do nothing for any other block), so only they are
  // visited, in index order as a full pass would.
  pending_.clear();
  cand_.clear();
  if (first_) {
    for (int i = 0; i < N_; ++i) cand_.push_back(i);
  } else {
    int last = -1;
    for (int i = 0; i < N_; ++i) {
      if (i + 8 <= N_ && load8(dir + i) == load8(dir_prev_.data() + i) &&
          load8(kind_.data() + i) == load8(kind_prev_.data() + i) && load8(fresh_.data() + i) == 0 &&
          (touched == nullptr || load8(touched + i) == 0)) {
        i += 7;  // none of the eight changed; the loop's ++i moves past them
        continue;
      }
      if (s.dir[i] == dir_prev_[i] && kind_[i] == kind_prev_[i] && !fresh_[i] && (touched == nullptr || !touched[i]))
        continue;
      for (int j = std::max(i - 1, last + 1); j <= std::min(i + 1, N_ - 1); ++j) cand_.push_back(j), last = j;
    }
  }
  for (int i : cand_) {
    if (!c.contact[i] || (s.dir[i] != 0 && kind_[i] != kModal)) {
      set_cross(i, kInf, false);
    } else if (s.dir[i] != 0) {
      if (fresh_[i]) set_cross(i, kInf, false), pending_.push_back(i);
    } else {
      // A stuck block keeps its event time unless something next to it changed: it does not
      // move, nor do its stuck neighbours, and a settled or kept modal neighbour follows the
      // same path as when the time was found.
      bool changed = first_ || switched(i) || switched(i - 1) || switched(i + 1) || kind_prev_[i] != kStuck;
      for (int j : {i - 1, i + 1})
        if (j >= 0 && j < N_) changed = changed || kind_[j] != kind_prev_[j] || fresh_[j];
      if (changed && !refresh_stuck(c, s, i)) pending_.push_back(i);
    }
  }
  std::copy(s.dir.begin(), s.dir.end(), dir_prev_.begin());
  first_ = false;
  finish_events(c, s);
}

bool ActiveSet::beside_modal(int i) const {
  return K_int_ > 0 && ((i > 0 && kind_[i - 1] == kModal) || (i + 1 < N_ && kind_[i + 1] == kModal));
}

bool ActiveSet::refresh_stuck(const Chain& c, const State& s, int i) {
  if (K_int_ > 0)
    for (int j : {i - 1, i + 1})
      if (j >= 0 && j < N_ && kind_[j] == kStepped) {
        set_cross(i, kInf, false);  // watched: the step's dense output finds its crossing
        return true;
      }
  if (beside_modal(i)) {
    set_cross(i, kInf, false);  // searched by finish_events
    return false;
  }
  update_crossing(c, s, i);
  return true;
}

void ActiveSet::search_modal(const Chain& c, const State& s, int i, double limit) {
  ModalRuns::Found f;
  if (s.dir[i] != 0) {
    f = modal_.stop_time(c, s, i, fresh_[i] != 0, limit);
  } else {
    double base[2] = {0, 0}, nb_B[2] = {0, 0};
    for (int side = 0; side < 2; ++side) {
      const int j = side == 0 ? i - 1 : i + 1;
      if (j < 0 || j >= N_) continue;
      if (kind_[j] == kSettled) base[side] = settled_u(j, s.t), nb_B[side] = B_[j];
      else base[side] = s.u[j];
    }
    f = modal_.crossing_time(c, s, i, base, nb_B, limit);
  }
  // Cut off at the limit: search again from there if it ever becomes the next event.
  set_cross(i, std::isfinite(f.t) ? f.t : f.limited ? limit : kInf, !std::isfinite(f.t) && f.limited);
}

void ActiveSet::finish_events(const Chain& c, const State& s) {
  // Each fresh modal search goes only as far as the earliest event known so far: most of them
  // never become the next event, and one cut off is searched again when it does (recheck()).
  refresh_next();
  for (int i : pending_) {
    // Limited by the earliest real event (not a recheck), so a recheck always makes progress.
    search_modal(c, s, i, std::min(next_event_t_, t_end_));
    const bool rc = recheck_[i] != 0;
    if (t_cross_[i] < next_.t || (t_cross_[i] == next_.t && (next_.recheck ? !rc || i < next_.block : !rc && i < next_.block)))
      next_ = {t_cross_[i], i, rc};
    if (!rc && t_cross_[i] < next_event_t_) next_event_t_ = t_cross_[i];
  }
  pending_.clear();
}

void ActiveSet::recheck(const Chain& c, const State& s) {
  const int i = next_.block;
  set_cross(i, kInf, false);
  fresh_[i] = 0;
  pending_.assign(1, i);
  finish_events(c, s);
}

void ActiveSet::list_stepped(const State& s) {
  stepped_.clear();
  watched_.clear();
  ringing_.clear();
  for (std::size_t k = 0; k < runs_.size(); ++k) {
    const Run& r = runs_[k];
    if (r.kind != kStepped) continue;
    if (r.grooves) ringing_.push_back(static_cast<int>(k));
    stepped_.push_back(r.span);
    // In block order; a stuck block between two stepped runs is listed once.
    if (K_int_ > 0 && r.span.lo > 0 && (watched_.empty() || watched_.back() != r.span.lo - 1))
      watched_.push_back(r.span.lo - 1);
    for (int i = r.span.lo; i < r.span.hi; ++i)
      if (s.dir[i] != 0) watched_.push_back(i);
    if (K_int_ > 0 && r.span.hi < N_) watched_.push_back(r.span.hi);
  }
}

void ActiveSet::update_crossing(const Chain& c, const State& s, int i) {
  double a = c.K_s * (c.v_slider * s.t - s.u[i]), b = c.K_s * c.v_slider;
  if (K_int_ > 0) {
    for (int j : {i - 1, i + 1}) {
      if (j < 0 || j >= N_) continue;
      if (kind_[j] == kStepped) {  // watched instead: its force is not affine
        set_cross(i, kInf, false);
        return;
      }
      if (kind_[j] == kSettled) {
        a += K_int_ * (settled_u(j, s.t) - s.u[i]);
        b += K_int_ * B_[j];
      } else {
        a += K_int_ * (s.u[j] - s.u[i]);
      }
    }
  }
  // First time a + b tau reaches +-f_static. b = 0 (nothing loads it) never crosses.
  const double f = c.f_static[i];
  if (b == 0.0) {
    set_cross(i, kInf, false);
    return;
  }
  const double tau = ((b > 0 ? f : -f) - a) / b;
  set_cross(i, s.t + std::max(tau, 0.0), false);
}

void ActiveSet::set_cross(int i, double t, bool recheck) {
  if (t_cross_[i] == t && (recheck_[i] != 0) == recheck) return;
  t_cross_[i] = t;
  recheck_[i] = recheck;
  if (!dirty_[i]) dirty_[i] = 1, dirty_list_.push_back(i);
}

bool ActiveSet::earlier(int a, int b) const {
  // The order a full scan in block order would give: earliest t; on a tie a real event before
  // a recheck (which then searches on from there); then the lower block.
  if (a < 0) return false;
  if (b < 0) return true;
  if (t_cross_[a] != t_cross_[b]) return t_cross_[a] < t_cross_[b];
  if (recheck_[a] != recheck_[b]) return recheck_[a] < recheck_[b];
  return a < b;
}

bool ActiveSet::earlier_real(int a, int b) const {
  auto t = [&](int i) { return i < 0 || recheck_[i] ? kInf : t_cross_[i]; };
  if (t(a) != t(b)) return t(a) < t(b);
  return a >= 0 && (b < 0 || a < b);
}

void ActiveSet::refresh_next() {
  // Two tournament trees over the blocks (earliest event; earliest real event), brought up to
  // date for the blocks whose time changed since the last call: O(changed log N), not O(N).
  for (int i : dirty_list_) {
    dirty_[i] = 0;
    for (int n = (P_ + i) >> 1; n >= 1; n >>= 1) {
      const int l = 2 * n, r = 2 * n + 1;
      tree_[n] = earlier(tree_[r], tree_[l]) ? tree_[r] : tree_[l];
      tree_real_[n] = earlier_real(tree_real_[r], tree_real_[l]) ? tree_real_[r] : tree_real_[l];
    }
  }
  dirty_list_.clear();
  const int b = tree_[1], e = tree_real_[1];
  next_ = (b >= 0 && t_cross_[b] < kInf) ? Next{t_cross_[b], b, recheck_[b] != 0} : Next{kInf, -1, false};
  next_event_t_ = (e >= 0 && !recheck_[e]) ? t_cross_[e] : kInf;
}

bool ActiveSet::retire_settled(const Chain& c, const State& s) {
  if (!settle_grooves_) return false;
  bool changed = false;
  for (int k : ringing_) {
    Run& r = runs_[k];
    if (!settled_now(s, r.span)) continue;
    r.kind = kSettled;
    for (int i = r.span.lo; i < r.span.hi; ++i) kind_[i] = kSettled;
    changed = true;
  }
  if (!changed) return false;
  list_stepped(s);
  // The stuck blocks beside a newly settled run may now have an affine force.
  for (const Run& r : runs_) {
    if (r.kind != kSettled) continue;
    for (int i : {r.span.lo - 1, r.span.hi})
      if (i >= 0 && i < N_ && c.contact[i] && s.dir[i] == 0 && t_cross_[i] == kInf && !refresh_stuck(c, s, i))
        pending_.push_back(i);
  }
  finish_events(c, s);
  return true;
}

void ActiveSet::materialise(double t, double* u, double* v, bool at_sample, bool ends_only) {
  for (const Run& r : runs_) {
    if (r.kind != kSettled) continue;
    for (int i = r.span.lo; i < r.span.hi; ++i) {
      u[i] = A_[i] + B_[i] * t;
      v[i] = B_[i];
    }
  }
  if (any_modal()) modal_.materialise(t, u, v, at_sample, ends_only);
}

void ActiveSet::materialise_near(double t, double* u, double* v, const std::vector<int>& blocks) {
  done_.clear();
  for (int b : blocks)
    for (int j = b - 1; j <= b + 1; ++j) {
      if (j < 0 || j >= N_) continue;
      if (kind_[j] == kSettled) {
        // The whole run: it may merge into a new run that is stepped or projected from s.u.
        if (u[j] == A_[j] + B_[j] * t && v[j] == B_[j]) continue;  // written already
        int lo = j, hi = j + 1;
        while (lo > 0 && kind_[lo - 1] == kSettled) --lo;
        while (hi < N_ && kind_[hi] == kSettled) ++hi;
        for (int i = lo; i < hi; ++i) {
          u[i] = A_[i] + B_[i] * t;
          v[i] = B_[i];
        }
      } else if (kind_[j] == kModal) {
        const int lo = modal_.run_start(j);
        if (std::find(done_.begin(), done_.end(), lo) != done_.end()) continue;  // a few runs at most
        modal_.materialise_run(j, t, u, v);
        done_.push_back(lo);
      }
    }
}

}  // namespace sb::event_detail
