#pragma once
// The reference bench/naive_rk4 is checked against (test_naive_rk4.cpp): the same RK4 scheme
// and switching rules written with an array of structs and a right-hand side that allocates the
// derivative of the whole state y = (u, v) at every stage. The benchmarks' baseline must give
// the same doubles as this one, step for step: its engineering may change, its arithmetic not.
// Header-only and test-only; nothing times it.
#include <cmath>
#include <cstdint>
#include <vector>

#include "springblock/model.hpp"
#include "springblock/state.hpp"

namespace sbtest {

class AllocatingRk4 {
 public:
  explicit AllocatingRk4(double h) : h_(h) {}

  // Advances `s` to t_end with every step taken; updates s.steps, s.rhs_evals and s.switches.
  void run(const sb::Chain& c, sb::State& s, double t_end) const {
    const int N = c.N;
    std::vector<Block> blocks(N);
    for (int i = 0; i < N; ++i)
      blocks[i] = {s.u[i], s.v[i], s.dir[i], c.contact[i] != 0, c.f_static[i], c.f_kinetic[i]};
    auto pack = [&] {
      std::vector<double> y(2 * N);
      for (int i = 0; i < N; ++i) y[i] = blocks[i].u, y[N + i] = blocks[i].v;
      return y;
    };
    const double h = h_;
    const std::int64_t n_end = std::llround(t_end / h);
    std::int64_t n = std::llround(s.t / h);
    switches(c, blocks, n * h, s);
    while (n < n_end) {
      const double t = n * h;
      const std::vector<double> y = pack();
      const std::vector<double> k1 = rhs(c, blocks, y, t);
      const std::vector<double> k2 = rhs(c, blocks, axpy(y, h / 2, k1), t + h / 2);
      const std::vector<double> k3 = rhs(c, blocks, axpy(y, h / 2, k2), t + h / 2);
      const std::vector<double> k4 = rhs(c, blocks, axpy(y, h, k3), t + h);
      for (int i = 0; i < N; ++i) {
        blocks[i].u += h / 6 * (k1[i] + 2 * k2[i] + 2 * k3[i] + k4[i]);
        blocks[i].v += h / 6 * (k1[N + i] + 2 * k2[N + i] + 2 * k3[N + i] + k4[N + i]);
      }
      ++n;
      ++s.steps;
      s.rhs_evals += 4;
      switches(c, blocks, n * h, s);
    }
    for (int i = 0; i < N; ++i) s.u[i] = blocks[i].u, s.v[i] = blocks[i].v, s.dir[i] = blocks[i].dir;
    s.t = n * h;
  }

 private:
  struct Block {
    double u = 0, v = 0;
    std::int8_t dir = 0;  // 0 = stuck or free, +1/-1 = sliding direction
    bool contact = true;
    double f_static = 0, f_kinetic = 0;
  };

  // Net non-friction force on block i for the state vector y = (u_0..u_{N-1}, v_0..v_{N-1}).
  static double net_force(const sb::Chain& c, const std::vector<double>& y, int i, double t) {
    const int N = c.N;
    double f = c.K_s * (c.v_slider * t - y[i]) - c.m * c.gamma * y[N + i];
    if (i > 0) f += c.K_int * (y[i - 1] - y[i]);
    if (i + 1 < N) f += c.K_int * (y[i + 1] - y[i]);
    return f;
  }

  // dy/dt = (v, a) with the phases of `blocks` frozen, freshly allocated.
  static std::vector<double> rhs(const sb::Chain& c, const std::vector<Block>& blocks,
                                 const std::vector<double>& y, double t) {
    const int N = c.N;
    std::vector<double> dy(2 * N, 0.0);
    for (int i = 0; i < N; ++i) {
      const Block& b = blocks[i];
      if (b.contact && b.dir == 0) {
        dy[i] = 0.0;
        dy[N + i] = 0.0;
      } else if (!b.contact) {
        dy[i] = y[N + i];
        dy[N + i] = net_force(c, y, i, t) / c.m;
      } else {
        dy[i] = y[N + i];
        dy[N + i] = (net_force(c, y, i, t) - b.dir * b.f_kinetic) / c.m;
      }
    }
    return dy;
  }

  // y + a * k, freshly allocated.
  static std::vector<double> axpy(const std::vector<double>& y, double a, const std::vector<double>& k) {
    std::vector<double> out(y.size());
    for (std::size_t j = 0; j < y.size(); ++j) out[j] = y[j] + a * k[j];
    return out;
  }

  // The same force read from the blocks themselves, for the switching decisions.
  static double net_force(const sb::Chain& c, const std::vector<Block>& blocks, int i, double t) {
    double f = c.K_s * (c.v_slider * t - blocks[i].u) - c.m * c.gamma * blocks[i].v;
    if (i > 0) f += c.K_int * (blocks[i - 1].u - blocks[i].u);
    if (i + 1 < c.N) f += c.K_int * (blocks[i + 1].u - blocks[i].u);
    return f;
  }

  // At a step end: a sliding block whose velocity reached or crossed zero stops; a stuck block
  // slips when |net non-friction force| > f_static.
  static void switches(const sb::Chain& c, std::vector<Block>& blocks, double t, sb::State& s) {
    for (int i = 0; i < c.N; ++i) {
      Block& b = blocks[i];
      if (!b.contact) continue;
      if (b.dir != 0 && b.v * b.dir <= 0.0) {
        b.v = 0.0;
        b.dir = 0;
        ++s.switches;
      }
      if (b.dir == 0) {
        const double F = net_force(c, blocks, i, t);
        if (std::fabs(F) > b.f_static) {
          b.dir = F > 0 ? 1 : -1;
          ++s.switches;
        }
      }
    }
  }

  double h_;
};

}  // namespace sbtest
