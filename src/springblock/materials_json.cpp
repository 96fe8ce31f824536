// Per-block fields in scene and sweep files: the list of segments and ramps, a member of one of
// them named as "segments.K.member" (so a sweep axis can vary a contrast or a slope), and what a
// results file records of them.
#include <cmath>
#include <nlohmann/json.hpp>

#include "springblock/errors.hpp"
#include "springblock/materials_json.hpp"
#include "springblock/scene.hpp"

namespace sb {
namespace {

const char* const kSegmentHelp =
    "a segment is {field, from, to, value} and a ramp {field, from, to, start, end}: blocks from..to, "
    "0-based and inclusive, a negative index counting from the end";

double number_of(const nlohmann::json& v, const std::string& where) {
  if (!v.is_number()) throw InputError("segments", where + " must be a number");
  return v.get<double>();
}

long index_of_block(const nlohmann::json& v, const std::string& where) {
  const double x = number_of(v, where);
  if (x != std::floor(x) || std::fabs(x) > 1e7) throw InputError("segments", where + " must be a whole block index");
  return static_cast<long>(x);
}

// Member `key` of segment g from `v`.
void set_member(MaterialSegment& g, const std::string& key, const nlohmann::json& v, const std::string& at) {
  const std::string where = at + "." + key;
  if (key == "field") {
    if (!v.is_string()) throw InputError("segments", where + " must name a per-block field");
    g.field = block_field(v.get<std::string>(), where);
  } else if (key == "from") g.from = index_of_block(v, where);
  else if (key == "to") g.to = index_of_block(v, where);
  else if (key == "value") g.value = number_of(v, where), g.ramp = false;
  else if (key == "start") g.start = number_of(v, where), g.ramp = true;
  else if (key == "end") g.end = number_of(v, where), g.ramp = true;
  else throw InputError("segments", where + ": unknown entry; " + kSegmentHelp);
}

MaterialSegment segment_of(const nlohmann::json& j, const std::string& at) {
  if (!j.is_object()) throw InputError("segments", at + " must be a table; " + kSegmentHelp);
  for (const char* need : {"field", "from", "to"})
    if (!j.contains(need)) throw InputError("segments", at + " has no '" + need + "'; " + kSegmentHelp);
  const bool value = j.contains("value"), ramp = j.contains("start") || j.contains("end");
  if (value == ramp || (ramp && !(j.contains("start") && j.contains("end"))))
    throw InputError("segments", at + " needs either a value or both start and end; " + kSegmentHelp);
  MaterialSegment g;
  for (auto& [key, v] : j.items()) set_member(g, key, v, at);
  return g;
}

}  // namespace

bool apply_materials_json(Scene& s, const std::string& key, const nlohmann::json& value) {
  if (key == "segments") {
    if (!value.is_array()) throw InputError("segments", std::string("must be a list; ") + kSegmentHelp);
    std::vector<MaterialSegment> list;
    for (std::size_t k = 0; k < value.size(); ++k) list.push_back(segment_of(value[k], "segments." + std::to_string(k)));
    s.materials.segments = std::move(list);
    return true;
  }
  if (key.rfind("segments.", 0) != 0) return false;
  // "segments.K.member": one member of a segment already listed.
  const auto dot = key.find('.', 9);
  const std::string index = key.substr(9, dot == std::string::npos ? std::string::npos : dot - 9);
  std::size_t k = 0;
  try {
    std::size_t used = 0;
    k = std::stoul(index, &used);
    if (used != index.size() || dot == std::string::npos) throw std::invalid_argument(key);
  } catch (const std::exception&) {
    throw InputError("segments", "'" + key + "' must be segments.K.MEMBER, K the segment's 0-based place in the list");
  }
  if (k >= s.materials.segments.size())
    throw InputError("segments", "'" + key + "' names segment " + std::to_string(k) + " but the scene lists " +
                                     std::to_string(s.materials.segments.size()) + " (give the list first)");
  set_member(s.materials.segments[k], key.substr(dot + 1), value, "segments." + std::to_string(k));
  return true;
}

nlohmann::json materials_json(const Scene& s) {
  const ResolvedMaterials r = resolve_materials(s);
  nlohmann::json j = {{"source", r.source}, {"hash", materials_hash(r)}};
  nlohmann::json given = nlohmann::json::array();
  for (int f = 0; f < kBlockFields; ++f)
    if (r.has(static_cast<BlockField>(f))) given.push_back(block_field_names()[f]);
  j["fields"] = given;
  if (!s.materials.segments.empty()) {
    nlohmann::json list = nlohmann::json::array();
    for (const auto& g : s.materials.segments) {
      nlohmann::json e = {{"field", block_field_names()[index_of(g.field)]}, {"from", g.from}, {"to", g.to}};
      if (g.ramp) e["start"] = g.start, e["end"] = g.end;
      else e["value"] = g.value;
      list.push_back(e);
    }
    j["segments"] = list;
  }
  return j;
}

}  // namespace sb
