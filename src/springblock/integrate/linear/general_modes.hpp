#pragma once
// The modes of a run whose blocks differ in slider spring, mass or internal springs: the general
// case of run_shape.hpp's closed forms. With W = diag(w) the blocks' masses relative to the
// chain's nominal mass m, the run's deviation from its path obeys m W x'' + gamma m W x' + K x = 0,
// so its modes solve K Q = W Q diag(lambda), normalised Q^T W Q = I, each mode a damped oscillator
// with omega^2 = lambda / m as on a uniform chain (damping proportional to mass keeps the modes
// uncoupled). They come from the symmetric tridiagonal S = W^-1/2 K W^-1/2, S Y = Y diag(lambda),
// Q = W^-1/2 Y; the projection of a deviation x onto them is Q^T W x.
#include <cstddef>
#include <map>
#include <utility>
#include <vector>

#include <Eigen/Dense>

#include "springblock/integrate/linear/run_shape.hpp"

namespace sb::event_detail {

// Q (modes by column, eigenvalues rising) and lambda for the stiffness K and the weights w
// (all > 0; all 1 gives K's orthonormal eigenvectors).
void general_modes(const Factors& K, const std::vector<double>& w, Eigen::MatrixXd& Q, std::vector<double>& lambda);

// A run's modes kept per thread and keyed by every value they are computed from: every
// repetition of a scene asks for the same runs' modes, and so do runs of equal blocks at
// different places. A hit gives what compute(Q, lambda) would, to the last bit, so results do not
// depend on the thread count or on what was cached. Each caller (its compute) has a cache of its
// own, emptied when it holds more than kMaxDoubles.
template <class Key, class Compute>
void cached_modes(Key key, Compute&& compute, Eigen::MatrixXd& Q, std::vector<double>& lambda) {
  constexpr std::size_t kMaxDoubles = std::size_t{1} << 23;  // 64 MB
  struct Modes {
    Eigen::MatrixXd Q;
    std::vector<double> lambda;
  };
  thread_local std::map<Key, Modes> cache;
  thread_local std::size_t held = 0;
  auto it = cache.find(key);
  if (it == cache.end()) {
    Modes m;
    compute(m.Q, m.lambda);
    const std::size_t size = static_cast<std::size_t>(m.Q.size()) + m.lambda.size();
    if (held + size > kMaxDoubles) cache.clear(), held = 0;
    held += size;
    it = cache.emplace(std::move(key), std::move(m)).first;
  }
  Q = it->second.Q;
  lambda = it->second.lambda;
}

}  // namespace sb::event_detail
