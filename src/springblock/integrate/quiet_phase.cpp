#include "springblock/integrate/quiet_phase.hpp"

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
      Eigen::MatrixXd K = Eigen::MatrixXd::Zero(s.n, s.n);
      for (int r = 0; r < s.n; ++r) {
        K(r, r) = c.K_s;
        // One internal spring per neighbour that exists: a groove block or a stuck block.
        if (r > 0 || s.left_stuck) K(r, r) += c.K_int;
        if (r + 1 < s.n || s.right_stuck) K(r, r) += c.K_int;
        if (r + 1 < s.n) K(r, r + 1) = K(r + 1, r) = -c.K_int;
      }
      Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(K);
      Decomp d{es.eigenvectors(), es.eigenvalues(), {}};
      for (int k = 0; k < s.n; ++k) d.modes.push_back({0.5 * c.gamma, d.lambda[k] / c.m});
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
    if (e.nseg) edges_.push_back(e);
    else affine_blocks_.push_back(j);
  }
  affine_a_.resize(affine_blocks_.size());
}

void QuietPhase::begin(const Chain& c, double t0, const double* u, const double* v) {
  t0_ = t0;
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
  }
  for (std::size_t k = 0; k < affine_blocks_.size(); ++k)
    affine_a_[k] = c.driving_force(affine_blocks_[k], u, v, t0);
  for (Edge& e : edges_) {
    e.a = c.driving_force(e.block, u, v, t0);
    e.b = c.K_s * c.v_slider;
    for (int n = 0; n < e.nseg; ++n) {
      const Segment& s = segs_[e.seg[n]];
      const Decomp& d = decomps_[s.decomp];
      e.b += c.K_int * B_[s.offset + e.row[n]];
      for (int k = 0; k < s.n; ++k) e.a -= c.K_int * d.Q(e.row[n], k) * q0_[s.offset + k];
    }
  }
}

void QuietPhase::evaluate(double t, double* u, double* v) const {
  const double tau = t - t0_;
  for (const Segment& s : segs_) {
    const Decomp& d = decomps_[s.decomp];
    double q[64], qd[64];  // modes evaluated in blocks of 64: no allocation
    for (int r = 0; r < s.n; ++r) {
      u[s.first + r] = A_[s.offset + r] + B_[s.offset + r] * t;
      v[s.first + r] = B_[s.offset + r];
    }
    if (tau > s.dead_tau) continue;
    for (int k0 = 0; k0 < s.n; k0 += 64) {
      const int k1 = std::min(s.n, k0 + 64);
      for (int k = k0; k < k1; ++k)
        d.modes[k].eval(q0_[s.offset + k], p0_[s.offset + k], tau, q[k - k0], qd[k - k0]);
      for (int r = 0; r < s.n; ++r) {
        double du = 0, dv = 0;
        for (int k = k0; k < k1; ++k) {
          du += d.Q(r, k) * q[k - k0];
          dv += d.Q(r, k) * qd[k - k0];
        }
        u[s.first + r] += du;
        v[s.first + r] += dv;
      }
    }
  }
}

void QuietPhase::edge_force(const Edge& e, double tau, double& F, double& dF, double& modal_bound,
                            double& slope_bound) {
  F = e.a + e.b * tau;
  dF = e.b;
  modal_bound = 0;
  slope_bound = std::fabs(e.b);
  for (int n = 0; n < e.nseg; ++n) {
    const Segment& s = segs_[e.seg[n]];
    const Decomp& d = decomps_[s.decomp];
    for (int k = 0; k < s.n; ++k) {
      double q, qd;
      d.modes[k].eval(q0_[s.offset + k], p0_[s.offset + k], tau, q, qd);
      const double w = K_int_ * d.Q(e.row[n], k);
      F += w * q;
      dF += w * qd;
      // The mode's energy qd^2 + omega^2 q^2 never grows (damping only removes it), so it
      // bounds |qd| and omega |q| for all later times.
      const double energy = std::sqrt(qd * qd + d.modes[k].omega2 * q * q);
      slope_bound += std::fabs(w) * energy;
      modal_bound += std::fabs(w) * energy / std::sqrt(d.modes[k].omega2);
    }
  }
}

double QuietPhase::march(const Chain& c, const Edge& e, double tau_limit) {
  const double fs = c.f_static[e.block];
  double F, dF, mb, sb;
  auto gap = [&](double tau) {
    edge_force(e, tau, F, dF, mb, sb);
    return fs - std::fabs(F);
  };
  // Bisection on a bracket with gap(lo) > 0 >= gap(hi); returns the crossed end.
  auto refine = [&](double lo, double hi) {
    for (int it = 0; it < 200 && hi - lo > 4e-16 * std::fabs(t0_ + hi); ++it) {
      const double mid = 0.5 * (lo + hi);
      (gap(mid) > 0 ? lo : hi) = mid;
    }
    return hi;
  };
  double tau = 0, prev = 0;
  for (long it = 0; it < 100000000L; ++it) {
    const double g = gap(tau);
    if (g <= 0) return tau == 0 ? 0.0 : refine(prev, tau);
    if (mb <= 1e-16 * fs) {
      // The modes have died out below round-off: the force is affine from here on.
      return tau + affine_crossing(F, e.b, fs);
    }
    if (g <= 1e-15 * fs) return tau;  // touching the threshold: treat as reached
    // Newton probe near the threshold: converges in a few steps where the safe march would
    // creep. A sign change at the probe is a bracket; otherwise the march goes on safely.
    const double rate = F > 0 ? dF : -dF;
    if (g < 1e-3 * fs && rate > 0) {
      const double probe = tau + g / rate;
      if (probe <= tau_limit) {
        if (gap(probe) <= 0) return refine(tau, probe);
        gap(tau);  // restore F, dF and the bounds at tau
      }
    }
    // No crossing is possible before |F| has changed by g, at a rate of at most sb; nor before
    // the affine part alone comes within the modal bound mb of the threshold.
    double step = g / sb;
    const double aff = e.a + e.b * tau;
    if (mb < fs && std::fabs(aff) <= fs - mb) step = std::max(step, affine_crossing(aff, e.b, fs - mb));
    prev = tau;
    tau += step;
    if (tau > tau_limit) return kInf;
  }
  return tau;  // unreachable in practice: the march moved 1e8 guaranteed-safe steps
}

QuietPhase::Next QuietPhase::next_threshold(const Chain& c, double t_limit) {
  double best = t_limit - t0_;
  int block = -1;
  for (std::size_t k = 0; k < affine_blocks_.size(); ++k) {
    const int j = affine_blocks_[k];
    const double tau = affine_crossing(affine_a_[k], c.K_s * c.v_slider, c.f_static[j]);
    if (tau < best) best = tau, block = j;
  }
  for (const Edge& e : edges_) {
    const double tau = march(c, e, best);
    if (tau < best || (tau == best && block >= 0 && e.block < block)) best = tau, block = e.block;
  }
  return {t0_ + best, block};
}

}  // namespace sb::event_detail
