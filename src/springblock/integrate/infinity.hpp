#pragma once
// "Never" for event times and bounds (no crossing, no stop, no limit), defined once for the
// integrators: each source used to define its own in an anonymous namespace, and two such
// sources could not share a unity-build translation unit (SPRINGBLOCK_UNITY_BUILD).
#include <limits>

namespace sb {

inline constexpr double kInf = std::numeric_limits<double>::infinity();

}  // namespace sb
