// JSON sweep files through nlohmann::json. It gives no positions, so the lines of the keys come
// from a scan of the text for keys (a string followed by ':'), which meets them in the same order
// as a depth-first walk of the parsed document in file order (ordered_json).
#include <cctype>

#include "springblock/errors.hpp"
#include "springblock/sweep/tree.hpp"

namespace sb::sweep {
namespace {

// The line of every object key, in the order the keys appear in the text.
std::vector<int> key_lines(const std::string& text) {
  std::vector<int> out;
  int line = 1;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '\n') ++line;
    if (text[i] != '"') continue;
    const int start = line;
    for (++i; i < text.size() && text[i] != '"'; ++i) {
      if (text[i] == '\\') ++i;
      else if (text[i] == '\n') ++line;
    }
    std::size_t j = i + 1;
    while (j < text.size() && std::isspace(static_cast<unsigned char>(text[j]))) {
      if (text[j] == '\n') ++line;
      ++j;
    }
    if (j < text.size() && text[j] == ':') out.push_back(start);
    i = j - 1;
  }
  return out;
}

void record_lines(const nlohmann::ordered_json& v, const std::string& pointer, const std::vector<int>& lines,
                  std::size_t& next, Tree& t) {
  if (v.is_object()) {
    for (auto& [k, child] : v.items()) {
      const std::string p = pointer + "/" + k;
      t.lines[p] = next < lines.size() ? lines[next] : 0;
      ++next;
      record_lines(child, p, lines, next, t);
    }
  } else if (v.is_array()) {
    for (std::size_t i = 0; i < v.size(); ++i) {
      const std::string p = pointer + "/" + std::to_string(i);
      if (v[i].is_object() && !v[i].empty() && next < lines.size()) t.lines[p] = lines[next];
      record_lines(v[i], p, lines, next, t);
    }
  }
}

}  // namespace

Spec parse_json(const std::string& text, const std::string& path) {
  Tree t;
  try {
    t.root = nlohmann::ordered_json::parse(text);
  } catch (const nlohmann::json::exception& e) {
    throw InputError("sweep", "'" + path + "' is not valid JSON: " + e.what());
  }
  std::size_t next = 0;
  record_lines(t.root, "", key_lines(text), next, t);
  return build_spec(t, path);
}

}  // namespace sb::sweep
