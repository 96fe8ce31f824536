#include "springblock/integrate/linear/quiet_phase.hpp"
#include "springblock/integrate/linear/run_stiffness.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace sb::event_detail {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// First tau >= 0 at which an affine force a + b tau reaches +-f (|a| <= f assumed).
double affine_crossing(double a, double b, double f) {
  if (b == 0.0) return kInf;
  const double tau = ((b > 0 ? f : -f) - a) / b;
  return std::max(tau, 0.0);
}

}  // namespace

QuietPhase::QuietPhase(const Chain& c) : K_int_(c.K_int) {
  const int N = c.N;
  int offset = 0;
  for (int i = 0; i < N;) {
    if (c.contact[i]) {
      ++i;
      continue;
    }
    int j = i;
    while (j + 1 < N && !c.contact[j + 1]) ++j;
    Segment s{i, j - i + 1, 0, offset, i > 0, j + 1 < N};
    const auto key = std::make_tuple(s.n, int(s.left_stuck), int(s.right_stuck));
    auto it = cache_.find(key);
    if (it == cache_.end()) {
      Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(run_stiffness(c.K_s, c.K_int, s.n, s.left_stuck, s.right_stuck));
      Decomp d{es.eigenvectors(), es.eigenvalues(), {}, {}, {}, {}, {}, {}, {}};
      for (int k = 0; k < s.n; ++k) d.modes.push_back({0.5 * c.gamma, d.lambda[k] / c.m});
      for (int k = 0; k < s.n; ++k) d.first_row.push_back(d.Q(0, k)), d.last_row.push_back(d.Q(s.n - 1, k));
      decomps_.push_back(std::move(d));
      it = cache_.emplace(key, static_cast<int>(decomps_.size()) - 1).first;
    }
    s.decomp = it->second;
    segs_.push_back(s);
    offset += s.n;
    i = j + 1;
  }
  A_.resize(offset);
  B_.resize(offset);
  q0_.resize(offset);
  p0_.resize(offset);
  rhs_.resize(offset);
  work_.resize(offset);

  // Groove index -> segment, to find the segments each contact block borders.
  std::vector<int> seg_of(N, -1);
  for (int k = 0; k < static_cast<int>(segs_.size()); ++k)
    for (int r = 0; r < segs_[k].n; ++r) seg_of[segs_[k].first + r] = k;
  for (int j = 0; j < N; ++j) {
    if (!c.contact[j]) continue;
    Edge e;
    e.block = j;
    if (K_int_ > 0) {
      if (j > 0 && !c.contact[j - 1]) {
        e.seg[e.nseg] = seg_of[j - 1];
        e.row[e.nseg++] = segs_[seg_of[j - 1]].n - 1;
      }
      if (j + 1 < N && !c.contact[j + 1]) {
        e.seg[e.nseg] = seg_of[j + 1];
        e.row[e.nseg++] = 0;
      }
    }
    if (e.nseg) {
      for (int n = 0; n < e.nseg; ++n) {
        const Segment& s = segs_[e.seg[n]];
        const Decomp& d = decomps_[s.decomp];
        for (int k = 0; k < s.n; ++k) e.march.add_mode(K_int_ * d.Q(e.row[n], k), d.modes[k], s.offset + k);
      }
      e.march.finish();
      edges_.push_back(std::move(e));
    } else {
      affine_blocks_.push_back(j);
    }
  }
  affine_a_.resize(affine_blocks_.size());
  qs_.resize(offset);
  qds_.resize(offset);
  order_.resize(edges_.size());
}

void QuietPhase::begin(const Chain& c, double t0, const double* u, const double* v) {
  t0_ = t0;
  sample_valid_ = false;
  const double mg = c.m * c.gamma;
  for (Segment& s : segs_) {
    const Decomp& d = decomps_[s.decomp];
    double* A = A_.data() + s.offset;
    double* B = B_.data() + s.offset;
    double* q0 = q0_.data() + s.offset;
    double* p0 = p0_.data() + s.offset;
    double* w = work_.data() + s.offset;
    // K_seg^{-1} x = Q diag(1/lambda) Q^T x; B from the slider load, then A from the stuck
    // neighbours' springs minus the damping force of the drift velocity B.
    auto solve = [&](const double* x, double* out) {
      for (int k = 0; k < s.n; ++k) {
        double dot = 0;
        for (int r = 0; r < s.n; ++r) dot += d.Q(r, k) * x[r];
        w[k] = dot / d.lambda[k];
      }
      for (int r = 0; r < s.n; ++r) {
        double sum = 0;
        for (int k = 0; k < s.n; ++k) sum += d.Q(r, k) * w[k];
        out[r] = sum;
      }
    };
    double* x = rhs_.data() + s.offset;
    for (int r = 0; r < s.n; ++r) x[r] = c.K_s * c.v_slider;
    solve(x, B);
    for (int r = 0; r < s.n; ++r) x[r] = -mg * B[r];
    if (s.left_stuck) x[0] += c.K_int * u[s.first - 1];
    if (s.right_stuck) x[s.n - 1] += c.K_int * u[s.first + s.n];
    solve(x, A);
    // Modal coordinates of the deviation from the particular solution.
    for (int k = 0; k < s.n; ++k) {
      double qk = 0, pk = 0;
      for (int r = 0; r < s.n; ++r) {
        const int i = s.first + r;
        qk += d.Q(r, k) * (u[i] - A[r] - B[r] * t0);
        pk += d.Q(r, k) * (v[i] - B[r]);
      }
      q0[k] = qk;
      p0[k] = pk;
    }
    // Underdamped modes shrink at least like e^{-alpha tau} (amplitude and velocity amplitude);
    // once below 1e-17 of the segment's u and v scales they no longer change a double.
    double amp = 0, vamp = 0, uscale = 0, vscale = 0, alpha = 0.5 * c.gamma;
    bool decays = alpha > 0;
    for (int k = 0; k < s.n; ++k) {
      const double s2 = d.modes[k].omega2 - alpha * alpha;
      if (s2 <= 0) decays = false;
      const double wd = std::sqrt(std::max(s2, 0.0));
      const double a_k = decays ? std::hypot(q0[k], (p0[k] + alpha * q0[k]) / wd) : 0.0;
      amp += a_k;
      vamp += a_k * std::sqrt(d.modes[k].omega2);
    }
    for (int r = 0; r < s.n; ++r) {
      uscale = std::max(uscale, std::fabs(A[r] + B[r] * t0));
      vscale = std::max(vscale, std::fabs(B[r]));
    }
    s.dead_tau = std::numeric_limits<double>::infinity();
    if (decays && uscale > 0 && vscale > 0)
      s.dead_tau = std::max({0.0, std::log(amp / (1e-17 * uscale)) / alpha, std::log(vamp / (1e-17 * vscale)) / alpha});
    // For samples only: the modes are dropped once below the settle scales (the bound on every
    // row is amp e^{-alpha tau}, on every velocity vamp e^{-alpha tau}).
    s.sample_dead_tau = s.dead_tau;
    if (decays && sample_eps_u_ > 0 && sample_eps_v_ > 0)
      s.sample_dead_tau = std::min(s.dead_tau, std::max({0.0, std::log(amp / sample_eps_u_) / alpha,
                                                         std::log(vamp / sample_eps_v_) / alpha}));
  }
  for (std::size_t k = 0; k < affine_blocks_.size(); ++k)
    affine_a_[k] = c.driving_force(affine_blocks_[k], u, v, t0);
  for (Edge& e : edges_) {
    double a = c.driving_force(e.block, u, v, t0), b = c.K_s * c.v_slider;
    for (int n = 0; n < e.nseg; ++n) {
      const Segment& s = segs_[e.seg[n]];
      const Decomp& d = decomps_[s.decomp];
      b += c.K_int * B_[s.offset + e.row[n]];
      for (int k = 0; k < s.n; ++k) a -= c.K_int * d.Q(e.row[n], k) * q0_[s.offset + k];
    }
    e.march.set_affine(a, b);
  }
}

void QuietPhase::to_physical(const Segment& s, double t, bool live, const double* q, const double* qd,
                             double* u, double* v) const {
  const Decomp& d = decomps_[s.decomp];
  for (int r = 0; r < s.n; ++r) {
    u[s.first + r] = A_[s.offset + r] + B_[s.offset + r] * t;
    v[s.first + r] = B_[s.offset + r];
  }
  if (!live) return;
  // Column-major Q: accumulate mode by mode so the inner loop runs down a contiguous column.
  for (int k = 0; k < s.n; ++k) {
    const double* col = d.Q.data() + static_cast<std::ptrdiff_t>(k) * s.n;
    const double qk = q[k], qdk = qd[k];
    double* uu = u + s.first;
    double* vv = v + s.first;
    for (int r = 0; r < s.n; ++r) {
      uu[r] += col[r] * qk;
      vv[r] += col[r] * qdk;
    }
  }
}

void QuietPhase::row_to_physical(const Segment& s, int r, double t, const double* q, const double* qd,
                                 double* u, double* v) const {
  const Decomp& d = decomps_[s.decomp];
  double du = 0, dv = 0;
  if (q != nullptr) {
    // Row r of Q (stored by column: stride n), or the contiguous copy of an end row; the same
    // products summed in the same order either way.
    const bool end_row = r == 0 || r == s.n - 1;
    const double* row = r == 0 ? d.first_row.data() : r == s.n - 1 ? d.last_row.data() : d.Q.data() + r;
    const int stride = end_row ? 1 : s.n;
    for (int k = 0; k < s.n; ++k) {
      du += row[k * stride] * q[k];
      dv += row[k * stride] * qd[k];
    }
  }
  u[s.first + r] = A_[s.offset + r] + B_[s.offset + r] * t + du;
  v[s.first + r] = B_[s.offset + r] + dv;
}

void QuietPhase::evaluate(double t, double* u, double* v) const {
  const double tau = t - t0_;
  double q[64], qd[64];  // modes evaluated in blocks of 64: no allocation
  for (const Segment& s : segs_) {
    const Decomp& d = decomps_[s.decomp];
    const bool live = tau <= s.dead_tau;
    to_physical(s, t, false, nullptr, nullptr, u, v);
    if (!live) continue;
    for (int k0 = 0; k0 < s.n; k0 += 64) {
      const int k1 = std::min(s.n, k0 + 64);
      for (int k = k0; k < k1; ++k)
        d.modes[k].eval(q0_[s.offset + k], p0_[s.offset + k], tau, q[k - k0], qd[k - k0]);
      for (int k = k0; k < k1; ++k) {
        const double* col = d.Q.data() + static_cast<std::ptrdiff_t>(k) * s.n;
        for (int r = 0; r < s.n; ++r) {
          u[s.first + r] += col[r] * q[k - k0];
          v[s.first + r] += col[r] * qd[k - k0];
        }
      }
    }
  }
}

void QuietPhase::set_sample_dt(double dt) {
  sample_dt_ = dt;
  for (Decomp& d : decomps_) {
    const std::size_t n = d.modes.size();
    d.s00.resize(n), d.s01.resize(n), d.s10.resize(n), d.s11.resize(n);
    for (std::size_t k = 0; k < n; ++k) {
      d.modes[k].eval(1.0, 0.0, dt, d.s00[k], d.s10[k]);
      d.modes[k].eval(0.0, 1.0, dt, d.s01[k], d.s11[k]);
    }
  }
}

void QuietPhase::sample(double t, double* u, double* v, bool ends_only) {
  const double tau = t - t0_;
  // The recurrence needs the previous sample one spacing back; the clock's times k dt differ
  // from that by round-off only. Restart from the closed form every 64 samples regardless.
  const bool step = sample_valid_ && sample_dt_ > 0 && std::fabs((t - ts_) - sample_dt_) <= 1e-9 * sample_dt_ &&
                    ++since_sync_ < 64;
  if (!step) since_sync_ = 0;
  for (const Segment& s : segs_) {
    // An observer that reads only contact forces (ends_only) takes the modes as gone once they
    // are below the settle scales; one that reads every row gets them to round-off.
    const bool live = tau <= (ends_only ? s.sample_dead_tau : s.dead_tau);
    double* q = qs_.data() + s.offset;
    double* qd = qds_.data() + s.offset;
    if (live) {
      const Decomp& d = decomps_[s.decomp];
      if (step) {
        for (int k = 0; k < s.n; ++k) {
          const double a = q[k], b = qd[k];
          q[k] = d.s00[k] * a + d.s01[k] * b;
          qd[k] = d.s10[k] * a + d.s11[k] * b;
        }
      } else {
        for (int k = 0; k < s.n; ++k) d.modes[k].eval(q0_[s.offset + k], p0_[s.offset + k], tau, q[k], qd[k]);
      }
    }
    if (ends_only) {
      // Interior rows are left as they are: the caller's observer does not read them.
      const double* lq = live ? q : nullptr;  // dead modes: the affine part alone
      if (s.left_stuck) row_to_physical(s, 0, t, lq, qd, u, v);
      if (s.right_stuck) row_to_physical(s, s.n - 1, t, lq, qd, u, v);
    } else {
      to_physical(s, t, live, q, qd, u, v);
    }
  }
  ts_ = t;
  sample_valid_ = true;
}

double QuietPhase::all_dead_after() const {
  double tau = 0;
  for (const Segment& s : segs_) tau = std::max(tau, s.sample_dead_tau);
  return t0_ + tau;
}

void QuietPhase::affine_forces(const Chain& c, const double* u, double* a, double* b) const {
  // A groove neighbour j of a contact block sits at A_j + B_j t; a stuck neighbour at u_j.
  std::vector<double> gA(c.N, 0.0), gB(c.N, 0.0);
  for (const Segment& sg : segs_)
    for (int r = 0; r < sg.n; ++r) gA[sg.first + r] = A_[sg.offset + r], gB[sg.first + r] = B_[sg.offset + r];
  for (int i = 0; i < c.N; ++i) {
    a[i] = b[i] = 0.0;
    if (!c.contact[i]) continue;
    a[i] = -c.K_s * u[i];
    b[i] = c.K_s * c.v_slider;
    if (K_int_ > 0)
      for (int j : {i - 1, i + 1}) {
        if (j < 0 || j >= c.N) continue;
        a[i] += K_int_ * ((c.contact[j] ? u[j] : gA[j]) - u[i]);
        if (!c.contact[j]) b[i] += K_int_ * gB[j];
      }
  }
}

QuietPhase::Next QuietPhase::next_threshold(const Chain& c, double t_limit) {
  double best = t_limit - t0_;
  int block = -1;
  for (std::size_t k = 0; k < affine_blocks_.size(); ++k) {
    const int j = affine_blocks_[k];
    const double tau = affine_crossing(affine_a_[k], c.K_s * c.v_slider, c.f_static[j]);
    if (tau < best) best = tau, block = j;
  }
  // Search the edges likeliest to cross first first: each search stops at the best time so far.
  for (std::size_t k = 0; k < edges_.size(); ++k) {
    Edge& e = edges_[k];
    e.lower = e.march.lower_bound(q0_.data(), p0_.data(), c.f_static[e.block]);
    order_[k] = static_cast<int>(k);
  }
  std::sort(order_.begin(), order_.end(), [&](int x, int y) { return edges_[x].lower < edges_[y].lower; });
  for (int k : order_) {
    Edge& e = edges_[k];
    if (e.lower > best) break;
    const double tau = e.march.first_crossing(q0_.data(), p0_.data(), c.f_static[e.block], best, t0_);
    if (tau < best || (tau == best && block >= 0 && e.block < block)) best = tau, block = e.block;
  }
  return {t0_ + best, block};
}

}  // namespace sb::event_detail
