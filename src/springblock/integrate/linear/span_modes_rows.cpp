// The rows of the exact stepper's runs (span_modes.hpp): a block's Taylor polynomial over a step,
// and the rows written into the chain's state.
#include "springblock/integrate/linear/span_modes.hpp"

#include <limits>

namespace sb::event_detail {

void SpanModes::row_taylor(int i, double* c) const {
  const Span& sp = spans_[span_of_[i]];
  store_.taylor(i, sp.t0, at(sp, false).q.data(), at(sp, false).p.data(), kDegree + 1, c);
  c[0] += du_[i];
  c[1] += dv_[i];
}

void SpanModes::write(double t, double* u, double* v, bool ends_only) {
  for (const Span& sp : spans_)
    if (mine(sp)) write_rows(sp, t, u, v, ends_only);
}

// Every row of a run, or its end rows (RunStore::write), with their offsets.
void SpanModes::write_rows(const Span& sp, double t, double* u, double* v, bool ends_only) {
  const RunStore::Run& rec = store_.run(sp.lo);
  const Coords* x = &at(sp, false);
  if (t != sp.t0) {
    rec.shape->evolve(x->q.data() + sp.lo, x->p.data() + sp.lo, t - sp.t0, scratch_.q.data() + sp.lo,
                      scratch_.p.data() + sp.lo);
    x = &scratch_;
  }
  store_.write(rec, t, x->q.data(), x->p.data(), u, v, ends_only, du_.data(), dv_.data());
}

void SpanModes::write_near(double t, const std::vector<int>& blocks, double* u, double* v) {
  for (const Span& sp : spans_) {
    bool near = sp.grooves;
    for (std::size_t k = 0; k < blocks.size() && !near; ++k) near = blocks[k] >= sp.lo - 1 && blocks[k] <= sp.hi;
    if (near && mine(sp)) write_rows(sp, t, u, v);
  }
}

void SpanModes::write_untouched(double t, const std::int64_t* switched_at, std::int64_t since, double* u, double* v) {
  for (const Span& sp : spans_)
    if (untouched(sp, switched_at, since) && mine(sp)) write_rows(sp, t, u, v);
}

double SpanModes::settled_after(int k, double eps_u, double eps_v) const {
  if (!spans_[k].grooves) return std::numeric_limits<double>::infinity();
  const RunStore::Run& rec = store_.run(spans_[k].lo);
  return rec.t0 + store_.envelope(rec).time_below(eps_u, eps_v);
}

}  // namespace sb::event_detail
