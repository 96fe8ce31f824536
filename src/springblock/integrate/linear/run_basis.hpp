#pragma once
// The modes of a run: n consecutive mobile blocks between stuck blocks or chain ends, all in the
// same state, move as
//   m u'' + m gamma u' + K u = (load affine in t),
// K the run's stiffness matrix (run_stiffness.hpp). Around an affine particular solution
// (affine_paths.hpp, or the modal one of modal_runs.hpp) the deviation splits into the
// orthonormal eigenvectors of K, each a damped oscillator solved in closed form
// (damped_mode.hpp). K depends only on (n, left held, right held), and with every block alike its
// eigenvectors are sampled sines and cosines (run_basis.cpp), so the modes are made once per shape
// in closed form and shared by every run of that shape (RunBases): the quiet phase's groove
// segments, the active set's modal runs and the exact stepper's runs are all built on it.
#include <array>
#include <map>
#include <tuple>
#include <vector>

#include <Eigen/Dense>

#include "springblock/integrate/linear/damped_mode.hpp"
#include "springblock/model.hpp"

namespace sb::event_detail {

struct RunBasis {
  Eigen::MatrixXd Q;              // columns: orthonormal modes of K
  Eigen::VectorXd lambda;         // eigenvalues of K (stiffnesses of the modes)
  std::vector<DampedMode> modes;  // alpha = gamma / 2, omega^2 = lambda / m
  // Q's first and last rows, contiguous: a contact block's force reads only the row of the
  // groove block beside it, and Q is stored by column (a row is strided by n).
  std::vector<double> first_row, last_row;
  // Per mode: the exact transition over the sample spacing (RunBases::set_sample_dt), so
  // consecutive samples advance the modes without transcendental calls.
  std::vector<Transition> sample;
  // Per mode: the first row of (I - P)^-1, P its sample transition. The sum of q over m
  // consecutive samples from state x is that row times (x - P^m x), the geometric series of
  // the transition in closed form (QuietPhase::window_sums). NaN where I - P is too near
  // singular for it (|det| < 1e-6: an undamped mode that turns by a multiple of 2 pi).
  std::vector<std::array<double, 2>> sample_sum;
  int n() const { return static_cast<int>(modes.size()); }
  // The modes (q, q') one sample spacing on, by their transitions (no transcendental calls).
  void step_sample(double* q, double* qd) const {
    const int m = n();
    for (int k = 0; k < m; ++k) {
      const double a = q[k], b = qd[k];
      const Transition& P = sample[k];
      q[k] = P[0] * a + P[1] * b;
      qd[k] = P[2] * a + P[3] * b;
    }
  }
  // The first and last rows' modal parts, Q's end rows . q, summed mode by mode.
  void end_rows(const double* q, double& first, double& last) const {
    first = last = 0;
    const int m = n();
    for (int k = 0; k < m; ++k) first += first_row[k] * q[k], last += last_row[k] * q[k];
  }
};

class RunBases {
 public:
  explicit RunBases(const Chain& c) : K_s_(c.K_s), K_int_(c.K_int), m_(c.m), gamma_(c.gamma) {}
  // The basis of a run of n blocks, held at its left / right end by a stuck block or not (a
  // free chain end). References stay valid for the life of this object.
  const RunBasis& get(int n, bool left, bool right);
  // Sample transitions of every basis, present and future.
  void set_sample_dt(double dt);
  int size() const { return static_cast<int>(bases_.size()); }

 private:
  static void set_sample_transitions(RunBasis& b, double dt);
  double K_s_, K_int_, m_, gamma_, sample_dt_ = 0;
  std::map<std::tuple<int, bool, bool>, RunBasis> bases_;
};

}  // namespace sb::event_detail
