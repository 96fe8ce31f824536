#pragma once
// When an observation is due: the one sample grid every integrator and the fan-out observer use.
//
// Sample k sits at t_k = k dt, computed from the integer k each time, so a long run does not
// accumulate rounding in its sample times, and two runs that share a trajectory (FanOut) agree
// on which sample is which. A method with a fixed step h (RK4) samples every stride = round(dt/h)
// steps instead, at n h; those times round to the same k (index_of), which is how FanOut maps
// both kinds of sample to one index.
#include <algorithm>
#include <cmath>
#include <cstdint>

namespace sb {

class SampleSchedule {
 public:
  // The grid of spacing dt, positioned at the first sample after t0 (the sample at t0 itself is
  // the one every run takes before it starts).
  SampleSchedule(double dt, double t0) : dt_(dt), k_(static_cast<long long>(std::floor(t0 / dt)) + 1) {}

  double dt() const { return dt_; }
  long long index() const { return k_; }
  double time_of(long long k) const { return static_cast<double>(k) * dt_; }
  double next() const { return time_of(k_); }
  // Exactly at the next sample (variable-step methods land on it by shortening a step).
  bool due(double t) const { return t == next(); }
  void advance(long long n = 1) { k_ += n; }

  // The first index k >= index() with k dt >= t: the samples index() .. k - 1 are those before t,
  // counted with the same floating-point products next() uses.
  long long first_at_or_after(double t) const { return first_at_or_after(t, dt_, k_); }
  static long long first_at_or_after(double t, double dt, long long k_min) {
    long long k = static_cast<long long>(std::ceil(t / dt));
    while (k > k_min && static_cast<double>(k - 1) * dt >= t) --k;
    while (static_cast<double>(k) * dt < t) ++k;
    return k;
  }

  // The index of a sample time on this grid, whichever method produced it.
  static long long index_of(double t, double dt) { return std::llround(t / dt); }

  // Fixed-step methods: a sample every stride steps (at least every step).
  static std::int64_t stride(double dt, double h) { return std::max<std::int64_t>(1, std::llround(dt / h)); }

 private:
  double dt_;
  long long k_;
};

}  // namespace sb
