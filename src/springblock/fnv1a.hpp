#pragma once
// FNV-1a, 64 bits (offset basis 14695981039346656037, prime 1099511628211): the one content hash
// the outputs record (a mask's blocks, the per-block materials' values) and the sweep checkpoint's
// fingerprint. A few lines, and the same value on every platform and build, which std::hash is
// not.
#include <cstdint>
#include <cstdio>
#include <string>
#include <string_view>

namespace sb {

class Fnv1a64 {
 public:
  void add(unsigned char byte) { h_ = (h_ ^ byte) * 1099511628211ull; }
  void add(std::string_view bytes) {
    for (unsigned char c : bytes) add(c);
  }
  std::uint64_t value() const { return h_; }
  // 16 lower-case hex digits.
  std::string hex() const {
    char text[24];
    std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(h_));
    return text;
  }

 private:
  std::uint64_t h_ = 14695981039346656037ull;
};

}  // namespace sb
