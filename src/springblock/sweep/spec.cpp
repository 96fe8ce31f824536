// What the TOML and JSON readers share: dispatch on the extension, the ranges, and the check of
// a section's entries (scene values are scalars; axes are lists or ranges).
#include <cmath>

#include "springblock/errors.hpp"
#include "springblock/input_file.hpp"
#include "springblock/sweep/spec.hpp"

namespace sb::sweep {

std::string where(const std::string& path, int line) {
  return line > 0 ? path + " line " + std::to_string(line) : path;
}

Spec read_spec(const std::string& path) {
  const std::string text = read_input_file(path, "sweep", "sweep file");
  const auto dot = path.rfind('.');
  const std::string ext = dot == std::string::npos ? "" : path.substr(dot);
  if (ext == ".toml") return parse_toml(text, path);
  if (ext == ".json") return parse_json(text, path);
  throw InputError("sweep", "'" + path + "' must end in .toml or .json (its format)");
}

namespace {

double range_number(const std::string& key, const nlohmann::json& range, const char* name,
                    const std::string& path, int line) {
  if (!range.contains(name) || !range.at(name).is_number())
    throw InputError(key, std::string("a range needs a number '") + name + "' (" + where(path, line) + ")");
  return range.at(name).get<double>();
}

}  // namespace

std::vector<nlohmann::json> range_values(const std::string& key, const nlohmann::json& range,
                                         const std::string& path, int line) {
  for (auto& [k, v] : range.items())
    if (k != "from" && k != "to" && k != "steps" && k != "scale")
      throw InputError(key, "unknown range entry '" + k + "'; a range is {from, to, steps, scale} (" +
                                where(path, line) + ")");
  const double from = range_number(key, range, "from", path, line);
  const double to = range_number(key, range, "to", path, line);
  const double steps = range_number(key, range, "steps", path, line);
  if (steps < 1 || steps > 1e6 || steps != std::floor(steps))
    throw InputError(key, "range steps = " + printed(steps) + " must be a whole number in [1, 1000000] (" +
                              where(path, line) + ")");
  const std::string scale = range.value("scale", std::string("linear"));
  const bool log = scale == "log";
  if (!log && scale != "linear")
    throw InputError(key, "range scale '" + scale + "' must be linear or log (" + where(path, line) + ")");
  if (log && !(from > 0 && to > 0))
    throw InputError(key, "a log range needs from > 0 and to > 0 (" + where(path, line) + ")");
  const int n = static_cast<int>(steps);
  const bool integers = !log && range.at("from").is_number_integer() && range.at("to").is_number_integer() &&
                        (n == 1 || static_cast<long long>(to - from) % (n - 1) == 0);
  std::vector<nlohmann::json> out;
  for (int i = 0; i < n; ++i) {
    const double f = n == 1 ? 0.0 : static_cast<double>(i) / (n - 1);
    if (integers)
      out.emplace_back(range.at("from").get<long long>() + static_cast<long long>(to - from) / std::max(1, n - 1) * i);
    else
      out.emplace_back(log ? from * std::pow(to / from, f) : from + (to - from) * f);
  }
  return out;
}

}  // namespace sb::sweep
