#pragma once
// Doubles in JSON that read back to the same bits: a finite double as a JSON number (nlohmann
// writes the shortest text that reads back to it), NaN and the infinities, which JSON lacks, as
// the strings "nan", "inf", "-inf". For states that must round-trip exactly (scene_state.hpp,
// ensemble_state.hpp); the results files write null for them instead (json_number).
#include <cmath>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace sb::exact_json {

inline nlohmann::json num(double x) {
  if (std::isfinite(x)) return x;
  return std::isnan(x) ? "nan" : (x > 0 ? "inf" : "-inf");
}
inline double num(const nlohmann::json& j) {
  if (j.is_number()) return j.get<double>();
  const auto t = j.get<std::string>();
  if (t == "nan") return std::nan("");
  return t == "inf" ? HUGE_VAL : -HUGE_VAL;
}
inline nlohmann::json nums(const std::vector<double>& v) {
  auto a = nlohmann::json::array();
  for (double x : v) a.push_back(num(x));
  return a;
}
inline std::vector<double> nums(const nlohmann::json& j) {
  std::vector<double> v;
  for (const auto& x : j) v.push_back(num(x));
  return v;
}

}  // namespace sb::exact_json
