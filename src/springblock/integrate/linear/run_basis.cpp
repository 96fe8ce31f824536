#include "springblock/integrate/linear/run_basis.hpp"

#include <cmath>
#include <limits>
#include <map>
#include <tuple>

namespace sb::event_detail {
namespace {

// The modes of a run in closed form. Its stiffness is K_s I + K_int L, L the Laplacian of a path
// of n blocks whose end rows lose their outer spring at a free chain end (run_stiffness.hpp).
// With every block alike, L's eigenvectors are sampled sines and cosines (the discrete sine and
// cosine transforms), j = 0 .. n-1 the row, k = 0 .. n-1 the mode, eigenvalue 2 - 2 cos theta:
//   held at both ends (u_-1 = u_n = 0):     sin(theta (j + 1)),   theta = pi (k + 1) / (n + 1)
//   free left, held right (u_-1 = u_0):     cos(theta (j + 1/2)), theta = pi (2k + 1) / (2n + 1)
//   held left, free right:                  the same, mirrored (j -> n - 1 - j)
//   free at both ends:                      cos(theta (j + 1/2)), theta = pi k / n
// Each column is normalised by its computed norm, and the eigenvalues rise with k, as a
// symmetric eigensolver would order them. O(n^2) per shape, against O(n^3) for the solver, which
// the runs of many lengths of the exact stepper ask for once per repetition each.
void closed_form_modes(double K_s, double K_int, int n, bool left, bool right, Eigen::MatrixXd& Q,
                       Eigen::VectorXd& lambda) {
  const double pi = 3.14159265358979323846;
  Q.resize(n, n);
  lambda.resize(n);
  for (int k = 0; k < n; ++k) {
    double theta;
    if (left && right) theta = pi * (k + 1) / (n + 1);
    else if (left || right) theta = pi * (2 * k + 1) / (2 * n + 1);
    else theta = pi * k / n;
    double norm2 = 0;
    for (int j = 0; j < n; ++j) {
      const int jj = (left && !right) ? n - 1 - j : j;  // the free end at row 0
      const double x = (left && right) ? std::sin(theta * (jj + 1)) : std::cos(theta * (jj + 0.5));
      Q(j, k) = x;
      norm2 += x * x;
    }
    const double inv = 1.0 / std::sqrt(norm2);
    for (int j = 0; j < n; ++j) Q(j, k) *= inv;
    lambda[k] = K_s + K_int * (2.0 - 2.0 * std::cos(theta));
  }
}

// The same, kept per thread: every repetition of a scene asks for the same shapes (their cosines
// are most of a projection's cost on the first call), and the closed form is the same doubles
// whoever computes it, so results do not depend on the thread count.
void cached_modes(double K_s, double K_int, int n, bool left, bool right, Eigen::MatrixXd& Q,
                  Eigen::VectorXd& lambda) {
  struct Modes {
    Eigen::MatrixXd Q;
    Eigen::VectorXd lambda;
  };
  thread_local std::map<std::tuple<double, double, int, bool, bool>, Modes> cache;
  const auto key = std::make_tuple(K_s, K_int, n, left, right);
  auto it = cache.find(key);
  if (it == cache.end()) {
    Modes m;
    closed_form_modes(K_s, K_int, n, left, right, m.Q, m.lambda);
    it = cache.emplace(key, std::move(m)).first;
  }
  Q = it->second.Q;
  lambda = it->second.lambda;
}

}  // namespace

const RunBasis& RunBases::get(int n, bool left, bool right) {
  const auto key = std::make_tuple(n, left, right);
  auto it = bases_.find(key);
  if (it != bases_.end()) return it->second;
  RunBasis b;
  cached_modes(K_s_, K_int_, n, left, right, b.Q, b.lambda);
  for (int k = 0; k < n; ++k) b.modes.push_back({0.5 * gamma_, b.lambda[k] / m_});
  for (int k = 0; k < n; ++k) b.first_row.push_back(b.Q(0, k)), b.last_row.push_back(b.Q(n - 1, k));
  if (sample_dt_ > 0) set_sample_transitions(b, sample_dt_);
  return bases_.emplace(key, std::move(b)).first->second;
}

void RunBases::set_sample_transitions(RunBasis& b, double dt) {
  b.sample.clear();
  b.sample_sum.clear();
  for (const DampedMode& m : b.modes) {
    const Transition P = m.transition(dt);
    b.sample.push_back(P);
    const double det = (1.0 - P[0]) * (1.0 - P[3]) - P[1] * P[2];
    const double nan = std::numeric_limits<double>::quiet_NaN();
    b.sample_sum.push_back(std::fabs(det) < 1e-6 ? std::array<double, 2>{nan, nan}
                                                 : std::array<double, 2>{(1.0 - P[3]) / det, P[1] / det});
  }
}

void RunBases::set_sample_dt(double dt) {
  sample_dt_ = dt;
  for (auto& [key, b] : bases_) set_sample_transitions(b, dt);
}

}  // namespace sb::event_detail
