// The rows of the exact stepper's runs (span_modes.hpp): a block's Taylor polynomial over a step,
// and the rows written into the chain's state.
#include "springblock/integrate/linear/span_modes.hpp"

#include <algorithm>
#include <limits>

namespace sb::event_detail {

void SpanModes::row_taylor(int i, double* c) const {
  store_.taylor(i, now_.t, now_.x.q.data(), now_.x.p.data(), kDegree + 1, c);
  c[0] += du_[i];
  c[1] += dv_[i];
}

void SpanModes::write(double* u, double* v, bool ends_only) {
  for (const Span& sp : spans_)
    if (mine(sp) != nullptr) write_rows(sp, u, v, ends_only);
}

// Every row of a run, or its end rows (RunStore::write), with their offsets.
void SpanModes::write_rows(const Span& sp, double* u, double* v, bool ends_only) {
  store_.write(store_.run(sp.lo), now_.t, now_.x.q.data(), now_.x.p.data(), u, v, ends_only, du_.data(), dv_.data());
}

void SpanModes::write_near(const std::vector<int>& blocks, double* u, double* v) {
  for (const Span& sp : spans_) {
    bool near = sp.grooves;
    for (std::size_t k = 0; k < blocks.size() && !near; ++k) near = blocks[k] >= sp.lo - 1 && blocks[k] <= sp.hi;
    if (near && mine(sp) != nullptr) write_rows(sp, u, v);
  }
}

void SpanModes::write_untouched(const std::int64_t* switched_at, std::int64_t since, double* u, double* v) {
  for (const Span& sp : spans_) {
    bool touched = false;
    const int N = static_cast<int>(span_of_.size());
    for (int i = std::max(sp.lo - 1, 0); i < std::min(sp.hi + 1, N) && !touched; ++i) touched = switched_at[i] > since;
    if (!touched && mine(sp) != nullptr) write_rows(sp, u, v);
  }
}

double SpanModes::settled_after(int k, double eps_u, double eps_v) const {
  if (!spans_[k].grooves) return std::numeric_limits<double>::infinity();
  const RunStore::Run& rec = store_.run(spans_[k].lo);
  return rec.t0 + store_.envelope(rec).time_below(eps_u, eps_v);
}

}  // namespace sb::event_detail
