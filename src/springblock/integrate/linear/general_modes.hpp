#pragma once
// The modes of a run whose blocks differ in slider spring, mass or internal springs: the general
// case of run_shape.hpp's closed forms. With W = diag(w) the blocks' masses relative to the
// chain's nominal mass m, the run's deviation from its path obeys m W x'' + gamma m W x' + K x = 0,
// so its modes solve K Q = W Q diag(lambda), normalised Q^T W Q = I, each mode a damped oscillator
// with omega^2 = lambda / m as on a uniform chain (damping proportional to mass keeps the modes
// uncoupled). They come from the symmetric tridiagonal S = W^-1/2 K W^-1/2, S Y = Y diag(lambda),
// Q = W^-1/2 Y; the projection of a deviation x onto them is Q^T W x.
#include <vector>

#include <Eigen/Dense>

#include "springblock/integrate/linear/run_shape.hpp"

namespace sb::event_detail {

// Q (modes by column, eigenvalues rising) and lambda for the stiffness K and the weights w
// (all > 0; all 1 gives K's orthonormal eigenvectors).
void general_modes(const Factors& K, const std::vector<double>& w, Eigen::MatrixXd& Q, std::vector<double>& lambda);
// The same through a per-thread cache (the same doubles).
void cached_general_modes(const Factors& K, const std::vector<double>& w, Eigen::MatrixXd& Q,
                          std::vector<double>& lambda);

}  // namespace sb::event_detail
