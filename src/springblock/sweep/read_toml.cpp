// TOML sweep files through toml++ (Debian's libtomlplusplus-dev): the document becomes the same
// JSON tree as a JSON sweep file, with each entry's line taken from toml++'s source regions.
#include <algorithm>
#include <toml++/toml.h>

#include "springblock/errors.hpp"
#include "springblock/sweep/tree.hpp"

namespace sb::sweep {
namespace {

int line_of(const toml::source_region& r) { return static_cast<int>(r.begin.line); }

nlohmann::ordered_json convert(const toml::node& node, const std::string& pointer, Tree& t, const std::string& path);

nlohmann::ordered_json convert_table(const toml::table& table, const std::string& pointer, Tree& t,
                                     const std::string& path) {
  // toml++ keeps keys sorted; the file's order is the order of their lines.
  std::vector<std::pair<const toml::key*, const toml::node*>> entries;
  for (auto&& [k, v] : table) entries.emplace_back(&k, &v);
  std::stable_sort(entries.begin(), entries.end(), [](auto& a, auto& b) {
    return line_of(a.first->source()) < line_of(b.first->source());
  });
  nlohmann::ordered_json out = nlohmann::ordered_json::object();
  for (auto& [k, v] : entries) {
    const std::string p = pointer + "/" + std::string(k->str());
    t.lines[p] = line_of(k->source()) > 0 ? line_of(k->source()) : line_of(v->source());
    out[std::string(k->str())] = convert(*v, p, t, path);
  }
  return out;
}

nlohmann::ordered_json convert(const toml::node& node, const std::string& pointer, Tree& t, const std::string& path) {
  if (auto* table = node.as_table()) return convert_table(*table, pointer, t, path);
  if (auto* array = node.as_array()) {
    nlohmann::ordered_json out = nlohmann::ordered_json::array();
    for (std::size_t i = 0; i < array->size(); ++i) {
      const std::string p = pointer + "/" + std::to_string(i);
      t.lines[p] = line_of((*array)[i].source());
      out.push_back(convert((*array)[i], p, t, path));
    }
    return out;
  }
  if (auto* s = node.as_string()) return s->get();
  if (auto* i = node.as_integer()) return i->get();
  if (auto* f = node.as_floating_point()) return f->get();
  if (auto* b = node.as_boolean()) return b->get();
  const auto slash = pointer.rfind('/');
  throw InputError(pointer.substr(slash + 1), "dates and times are not scene values (" +
                                                  where(path, line_of(node.source())) + ")");
}

}  // namespace

Spec parse_toml(const std::string& text, const std::string& path) {
  toml::table doc;
  try {
    doc = toml::parse(text, path);
  } catch (const toml::parse_error& e) {
    throw InputError("sweep", "'" + path + "' is not valid TOML: " + std::string(e.description()) + " (" +
                                  where(path, line_of(e.source())) + ")");
  }
  Tree t;
  t.root = convert_table(doc, "", t, path);
  return build_spec(t, path);
}

}  // namespace sb::sweep
