#pragma once
// The first tau >= 0 at which an affine force a + b tau reaches the threshold +-f it is heading
// for (|a| <= f assumed), in closed form; never (kInf) when nothing loads it (b = 0). A stuck
// block's crossing wherever its force is affine: the active set's stuck blocks, the quiet phase's
// blocks beside no ringing groove, an edge whose modes have died out, the uncoupled solver's stuck
// blocks.
#include <algorithm>

#include "springblock/infinity.hpp"

namespace sb {

inline double affine_crossing(double a, double b, double f) {
  if (b == 0.0) return kInf;
  return std::max(((b > 0 ? f : -f) - a) / b, 0.0);
}

}  // namespace sb
