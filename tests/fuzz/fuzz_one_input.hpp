#pragma once
// One fuzz input through the parsers: the body shared by the libFuzzer harness
// (fuzz_parsers.cpp) and the bounded random-input GoogleTest (tests/unit/test_fuzz_parsers.cpp).
//
// The first byte picks the parser, the rest is its text:
//   0: parse_pattern, then build_contact_mask on a small chain
//   1: parse_quantity for the dimension picked by the second byte
//   2: a JSON scene file: apply_scene_json, then validate
//   3: set_scene_field for the key picked by the second byte, then validate
//   4: a materials TSV file: parse_materials_tsv, then validate on a chain of 1 to 4 blocks
// The contract under test: user text is either accepted or refused with sb::InputError. Any
// other exception escapes to the caller (the harness turns it into a crash report).
#include <cstddef>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>

#include "springblock/scene.hpp"
#include "springblock/scene_fields.hpp"
#include "springblock/surface.hpp"
#include "springblock/units.hpp"

namespace sbfuzz {

// Returns true if the input was accepted, false if refused with InputError.
inline bool parse_one(const std::uint8_t* data, std::size_t size) {
  if (size < 2) return false;
  const int which = data[0] % 5;
  const std::uint8_t pick = data[1];
  const std::string text(reinterpret_cast<const char*>(data + 2), size - 2);
  try {
    switch (which) {
      case 0: {
        const auto spec = sb::parse_pattern(text);
        (void)sb::build_contact_mask(spec, 1 + pick, pick);
        return true;
      }
      case 1: {
        const auto dim = static_cast<sb::Dimension>(pick % 7);
        (void)sb::parse_quantity(text, dim, "fuzz");
        return true;
      }
      case 2: {
        // Malformed JSON is refused by the CLI before apply_scene_json; mirror that.
        const auto j = nlohmann::json::parse(text, nullptr, /*allow_exceptions=*/false);
        if (j.is_discarded()) return false;
        sb::Scene s;
        sb::apply_scene_json(s, j);
        sb::validate(s);
        return true;
      }
      case 4: {
        sb::Scene s;
        s.geometry.N = 1 + pick % 4;
        s.run.method = pick & 4 ? sb::Method::RK4 : sb::Method::Event;
        s.materials = sb::parse_materials_tsv(text, "fuzz.tsv");
        sb::validate(s);
        (void)sb::build_chain(s, 0);
        return true;
      }
      default: {
        const auto& fields = sb::scene_fields();
        sb::Scene s;
        sb::set_scene_field(s, fields[pick % fields.size()].key, text);
        sb::validate(s);
        return true;
      }
    }
  } catch (const sb::InputError&) {
    return false;
  }
}

}  // namespace sbfuzz
