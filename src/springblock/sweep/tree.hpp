#pragma once
// A sweep file as a JSON tree with the line of every entry: what the TOML and JSON readers both
// produce, so the sections are checked once (build_spec) whatever the format.
#include <map>
#include <nlohmann/json.hpp>
#include <string>

#include "springblock/sweep/spec.hpp"

namespace sb::sweep {

struct Tree {
  nlohmann::ordered_json root;        // file order kept: axes multiply in the order written
  std::map<std::string, int> lines;   // JSON pointer ("/axes/N") -> 1-based line
  int line(const std::string& pointer) const {
    auto it = lines.find(pointer);
    return it == lines.end() ? 0 : it->second;
  }
};

// The sections base, scenes and axes of `tree`. Throws InputError naming the field and line.
Spec build_spec(const Tree& tree, const std::string& path);

}  // namespace sb::sweep
