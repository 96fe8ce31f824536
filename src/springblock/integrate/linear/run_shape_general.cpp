// The shape of one run of a chain whose blocks differ in slider spring, mass or internal springs:
// the same pieces as a uniform chain's (run_shape.cpp), from the run's own blocks.
#include <algorithm>
#include <utility>
#include <vector>

#include "springblock/integrate/linear/general_modes.hpp"
#include "springblock/integrate/linear/run_shape.hpp"

namespace sb::event_detail {

const RunShape& RunShapes::general(BlockRange r, std::uint8_t parts) {
  auto it = ranged_.find({r.lo, r.hi});
  if (it == ranged_.end()) {
    std::vector<double> key = general_key(r);
    auto shape = by_content_.find(key);
    if (shape == by_content_.end()) shape = by_content_.emplace(std::move(key), make_general(r)).first;
    it = ranged_.emplace(std::make_pair(r.lo, r.hi), &shape->second).first;
  }
  RunShape& sh = *it->second;
  if ((sh.steps.parts & parts) != parts) add_parts(sh, parts);
  return sh;
}

// Every value make_general reads, so that runs with equal keys have equal shapes to the last bit
// (the chain's v, gamma and m are common to all): each block's slider spring and mass, the springs
// inside the run, and the holding spring at each end (-1 at a free chain end, never a spring).
std::vector<double> RunShapes::general_key(BlockRange r) const {
  const Chain& c = c_;
  std::vector<double> key;
  key.reserve(3 * static_cast<std::size_t>(r.size()) + 1);
  for (int i = r.lo; i < r.hi; ++i) key.push_back(c.k_s(i)), key.push_back(c.mass(i));
  for (int i = r.lo; i + 1 < r.hi; ++i) key.push_back(c.spring(i));
  key.push_back(r.lo > 0 ? c.spring(r.lo - 1) : -1.0);
  key.push_back(r.hi < c.N ? c.spring(r.hi - 1) : -1.0);
  return key;
}

// K: each block's slider spring plus the springs to the neighbours that exist (inside the run,
// or the stuck block holding an end), minus those springs beside the diagonal. The path: K B =
// (K_s,i v), a0 = K^-1 (-m_i gamma B_i), gL and gR = K^-1 of the holding springs at the ends.
RunShape RunShapes::make_general(BlockRange r) const {
  const Chain& c = c_;
  const int n = r.size(), lo = r.lo;
  const bool left = r.lo > 0, right = r.hi < c.N;
  RunShape sh;
  sh.n = n, sh.path.left = left, sh.path.right = right;
  Factors& K = sh.K;
  for (int k = 0; k < n; ++k) {
    const int i = lo + k;
    K.diag.push_back(c.k_s(i) + ((k > 0 || left) ? c.spring(i - 1) : 0.0) + ((k + 1 < n || right) ? c.spring(i) : 0.0));
    if (k + 1 < n) K.off.push_back(-c.spring(i));
  }
  K.factor();
  AffinePieces& path = sh.path;
  path.B.resize(n);
  for (int k = 0; k < n; ++k) path.B[k] = c.k_s(lo + k) * c.v_slider;
  K.solve(path.B.data(), path.B.data());
  path.a0.resize(n), path.gL.assign(n, 0.0), path.gR.assign(n, 0.0);
  for (int k = 0; k < n; ++k) path.a0[k] = -c.mass(lo + k) * c.gamma * path.B[k];
  K.solve(path.a0.data(), path.a0.data());
  if (left) path.gL[0] = c.spring(lo - 1), K.solve(path.gL.data(), path.gL.data());
  if (right) path.gR[n - 1] = c.spring(r.hi - 1), K.solve(path.gR.data(), path.gR.data());
  sh.weight.resize(n);
  for (int k = 0; k < n; ++k) sh.weight[k] = c.mass(lo + k) / c.m;
  cached_general_modes(K, sh.weight, sh.Q, sh.spectrum.lambda);
  finish_modes(sh, c.m, c.gamma);
  return sh;
}

}  // namespace sb::event_detail
