#pragma once
// The stiffness matrix of a run: n consecutive mobile blocks (grooves or sliding blocks) between
// stuck blocks or chain ends. Every exact treatment of a run starts from it: the settled
// grooves' particular solution (active_set), the modes of short runs (modal_runs) and the
// grooves of a quiet phase (quiet_phase). Written once here so the three cannot drift apart.
//
// Row k: the block's slider spring K_s, plus one internal spring K_int per neighbour that exists
// (a block of the run, or the stuck block at the run's left or right end when `left` / `right`),
// and -K_int to each neighbour inside the run. Additions in this order only, so every user sees
// the same bits.
#include <Eigen/Dense>

namespace sb::event_detail {

inline double run_stiffness_diagonal(double K_s, double K_int, int n, int k, bool left, bool right) {
  return K_s + ((k > 0 || left) ? K_int : 0.0) + ((k + 1 < n || right) ? K_int : 0.0);
}

inline Eigen::MatrixXd run_stiffness(double K_s, double K_int, int n, bool left, bool right) {
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(n, n);
  for (int r = 0; r < n; ++r) {
    K(r, r) = run_stiffness_diagonal(K_s, K_int, n, r, left, right);
    if (r + 1 < n) K(r, r + 1) = K(r + 1, r) = -K_int;
  }
  return K;
}

}  // namespace sb::event_detail
