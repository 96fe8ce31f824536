#pragma once
// The exact state of every run whose motion is known in closed form, in one place.
//
// Between two switches a run (run_shape.hpp) moves as its affine path A + B t plus its modes,
// each a damped oscillator started from (q0, p0) at the run's origin t0:
//   u = A + B t + Q q(t - t0),   v = B + Q q'(t - t0).
// A record holds exactly that: the run's blocks, its shape, A and B per block, q0 and p0 per
// mode (mode k of the run starting at block lo sits in slot lo + k, so the slots of disjoint
// runs never meet and any per-slot array of a user lines up with the store's), and t0. Every
// exact treatment of a run is a user of its record: a settled groove run is a record without
// modes; a modal run, a run of the exact stepper and a groove segment of a quiet phase are
// records with modes plus what each user keeps on its own (a sample cursor, the stepper's
// current coordinates, event searches). The mathematics every user needs is written here once:
// the projection of a state onto a run (one application of K^-1, one change to modal
// coordinates), the closed form at any time, a block's u, v and acceleration from a run's
// coordinates, the write-back into the chain's state, the bounds that hold for all later times,
// and a row's Taylor polynomial.
//
// Each record has an owner (the user that made it); a projection over blocks another record
// holds drops that record, and an owner drops its records when it lets the runs go, so what the
// store holds is always current. Records carry the serial number of their projection, so a
// user that keeps a run across switches can tell whether it is still the one it projected.
#include <algorithm>
#include <cstdint>
#include <vector>

#include "springblock/integrate/block_range.hpp"
#include "springblock/integrate/linear/coords.hpp"
#include "springblock/integrate/linear/envelope.hpp"
#include "springblock/integrate/linear/run_shape.hpp"
#include "springblock/model.hpp"

namespace sb::event_detail {

class RunStore {
 public:
  enum Owner : std::uint8_t { kNone, kSettled, kModal, kSpan, kQuiet };
  struct Run {
    int lo = 0, hi = 0;
    const RunShape* shape = nullptr;
    double t0 = 0;       // origin of q0, p0
    bool modes = false;  // false: on its affine path (q0 = p0 = 0, nothing to evaluate)
    Owner owner = kNone;
    std::int64_t id = 0;  // serial number of the projection that made it
    int n() const { return hi - lo; }
  };

  explicit RunStore(const Chain& c);
  // The shapes of its runs (run_shape.hpp).
  RunShapes& shapes() { return shapes_; }

  // Run r projected from the state at time t (u, v; its sliding blocks' kinetic friction from
  // dir, nullptr when nothing in it slides): its affine path, and the modal coordinates of u's
  // and v's deviation from it (with_modes = false: on its path, the deviation taken as zero).
  // Bounds are taken for the rows its owner reads (bound()).
  const Run& project(const Chain& c, BlockRange r, double t, const double* u, const double* v,
                     const std::int8_t* dir, Owner owner, bool with_modes = true);
  // The run starting at block lo with its coordinates moved to origin t (the closed form).
  void rebase(int lo, double t);
  void drop(int lo) { records_.drop(lo); }

  const Run& run(int i) const { return records_.run(i); }
  Owner owner(int i) const { return records_.holds(i) ? records_.run(i).owner : kNone; }
  // The record spanning exactly r, or nullptr.
  const Run* exact(BlockRange r) const { return records_.exact(r); }

  double A(int i) const { return A_[i]; }
  double B(int i) const { return B_[i]; }
  double path_u(int i, double t) const { return A_[i] + B_[i] * t; }
  const double* q0() const { return modes_.q.data(); }
  const double* p0() const { return modes_.p.data(); }

  // The modes of run r at t into slots r.lo .. of q, p.
  void coords(const Run& r, double t, double* q, double* p) const;
  // u of block i at t from its run's record (direct evaluation).
  double u(int i, double t) const;
  // Block i's u at t, v and acceleration from its run's coordinates q, p (slots) at that time.
  double row_u(int i, double t, const double* q) const { return path_u(i, t) + row_dot(i, q); }
  double row_v(int i, const double* p) const { return B_[i] + row_dot(i, p); }
  double row_a(int i, const double* q, const double* p) const;
  // u, v of run r's blocks at t from its coordinates (ends_only: its first and last rows only),
  // plus per-block offsets du, dv where given.
  void write(const Run& r, double t, const double* q, const double* p, double* u, double* v, bool ends_only = false,
             const double* du = nullptr, const double* dv = nullptr);
  // On its path (no modes): every row, or (ends_only) its first and last rows only.
  void write_path(const Run& r, double t, double* u, double* v, bool ends_only = false) const;
  // u, v of run r's blocks at t by the closed form from its record.
  void write_at(const Run& r, double t, double* u, double* v);
  // Bounds that hold at every time after the projection, from each mode's energy at it (which
  // never grows): order 0, |u - path| of block i; orders 2 to 5, |u^(order)|. Taken where a
  // run's owner reads them: order 0 at a modal run's end rows (its stuck neighbours' forces),
  // orders 2 to 5 at the exact stepper's end rows and sliding blocks (its screen).
  double bound(int i, int order) const { return bound_[order == 0 ? 0 : order - 1][i]; }
  TransientEnvelope envelope(const Run& r) const { return transient_envelope(*r.shape, q0() + r.lo, p0() + r.lo); }
  // u of block i about t as a polynomial in tau, c[j] = u^(j)(t) / j!, j = 0 .. deg, from its
  // run's coordinates q, p at t.
  void taylor(int i, double t, const double* q, const double* p, int deg, double* c) const;

 private:
  // Which runs exist: the records by first block, and each block's run.
  class Records {
   public:
    explicit Records(int N) : runs_(N), first_(N, -1) {}
    // A new record for r (dropping any record that holds one of its blocks).
    Run& claim(BlockRange r, const RunShape* shape, double t0, bool modes, Owner owner);
    void drop(int lo) { std::fill(first_.begin() + runs_[lo].lo, first_.begin() + runs_[lo].hi, -1); }
    bool holds(int i) const { return first_[i] >= 0; }
    const Run& run(int i) const { return runs_[first_[i]]; }
    Run& at(int lo) { return runs_[lo]; }
    const Run* exact(BlockRange r) const {
      return first_[r.lo] == r.lo && runs_[r.lo].hi == r.hi ? &runs_[r.lo] : nullptr;
    }

   private:
    std::vector<Run> runs_;   // by first block
    std::vector<int> first_;  // per block: first block of the run holding it (-1: none)
    std::int64_t serial_ = 0;
  };

  double row_dot(int i, const double* x) const {
    const Run& r = records_.run(i);
    const int n = r.n();
    const double* row = r.shape->row(i - r.lo);
    const double* xs = x + r.lo;
    double d = 0;
    for (int k = 0; k < n; ++k) d += row[k] * xs[k];
    return d;
  }
  void set_path(const Chain& c, Run& run, const double* u, const std::int8_t* dir);
  void set_bounds(const Run& run, const std::int8_t* dir);

  double gamma_;
  RunShapes shapes_;
  Records records_;
  std::vector<double> A_, B_;      // per block: the affine path
  Coords modes_;                   // per slot: q0, p0
  std::vector<double> bound_[5];   // per block: bound() of orders 0, 2, 3, 4, 5
  // Work arrays: a projection's deviation (u and v) and then its modes' sqrt energies
  // (set_bounds), or the modes at a time (write_at); a write's Q q and Q p.
  Coords dev_, sums_;
};

}  // namespace sb::event_detail
