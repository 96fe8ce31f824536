#pragma once
// "Never" for event times and bounds (no crossing, no stop, no limit), defined once for the
// integrators and the observers: a definition per source, in an anonymous namespace, would clash
// when two such sources share a unity-build translation unit (SPRINGBLOCK_UNITY_BUILD).
#include <limits>

namespace sb {

inline constexpr double kInf = std::numeric_limits<double>::infinity();

}  // namespace sb
