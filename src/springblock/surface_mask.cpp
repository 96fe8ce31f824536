#include "springblock/surface_mask.hpp"

#include <algorithm>
#include <cstdio>
#include <utility>

#include "springblock/errors.hpp"
#include "springblock/fnv1a.hpp"
#include "springblock/input_file.hpp"

namespace sb {
namespace {

// N's own bound (scene_fields.cpp): a longer mask could never match a chain.
constexpr std::size_t kMaxBlocks = 1'000'000;
constexpr const char* kAllowed = "a mask holds only 0 (groove) and 1 (pawl), one character per block";

[[noreturn]] void refuse_mask(const std::string& what) { throw InputError("pattern", what); }

// A character as a message shows it: printable ones quoted, others by their code.
std::string shown_char(char c) {
  const auto u = static_cast<unsigned char>(c);
  if (u >= 0x20 && u < 0x7f) return std::string("'") + c + "'";
  char buf[16];
  std::snprintf(buf, sizeof buf, "byte 0x%02x", u);
  return buf;
}

bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\v' || c == '\f'; }

void check_not_too_long(std::size_t blocks, const std::string& where) {
  if (blocks > kMaxBlocks)
    refuse_mask(where + " has more than 1000000 blocks; a mask has 1 to 1000000 blocks, one per block of the chain");
}

std::vector<std::uint8_t> inline_blocks(std::string_view digits, const std::string& spec) {
  if (digits.empty()) refuse_mask("empty mask in '" + spec + "'; " + kAllowed + ", e.g. mask:0110, or mask:@FILE");
  check_not_too_long(digits.size(), "the mask");
  std::vector<std::uint8_t> mask;
  mask.reserve(digits.size());
  for (std::size_t i = 0; i < digits.size(); ++i) {
    const char c = digits[i];
    if (c != '0' && c != '1')
      refuse_mask("mask character " + std::to_string(i + 1) + " of " + std::to_string(digits.size()) + " is " +
                  shown_char(c) + "; " + kAllowed);
    mask.push_back(c == '1' ? 1 : 0);
  }
  return mask;
}

// Reads character by character, not line by line: a file with no newline (a device, a wrong
// path to a large binary) is refused at its first bad character or past 1000000 blocks instead
// of being held in memory whole.
class MaskFileReader {
 public:
  explicit MaskFileReader(std::string path) : path_(std::move(path)) {}

  void take(char c, std::vector<std::uint8_t>& mask) {
    ++column_;
    if (c == '\n') {
      ++line_, column_ = 0, blank_so_far_ = true, comment_ = false;
      return;
    }
    if (comment_ || is_blank(c)) return;
    if (c == '#' && blank_so_far_) {
      comment_ = true;
      return;
    }
    blank_so_far_ = false;
    if (c != '0' && c != '1')
      refuse_mask("mask file '" + path_ + "' line " + std::to_string(line_) + ", column " + std::to_string(column_) +
                  ": " + shown_char(c) + " is not 0 or 1; " + kAllowed +
                  " (whitespace and lines starting with '#' are ignored)");
    mask.push_back(c == '1' ? 1 : 0);
    if (mask.size() > kMaxBlocks) check_not_too_long(mask.size(), "mask file '" + path_ + "'");
  }

 private:
  std::string path_;
  int line_ = 1, column_ = 0;
  bool blank_so_far_ = true, comment_ = false;
};

}  // namespace

std::vector<std::uint8_t> read_mask_file(const std::string& path) {
  std::vector<std::uint8_t> mask;
  MaskFileReader reader(path);
  // Taken as it is read: a file too long, or not a mask, is refused at once.
  read_input_chunks(path, "pattern", "mask file", [&](std::string_view chunk) {
    for (char c : chunk) reader.take(c, mask);
  });
  if (mask.empty())
    refuse_mask("mask file '" + path + "' holds no 0 or 1 character; " + kAllowed +
                " (whitespace and lines starting with '#' are ignored)");
  return mask;
}

PatternSpec parse_mask_pattern(std::string_view args, const std::string& spec) {
  PatternSpec out;
  out.kind = SurfaceKind::Mask;
  if (!args.empty() && args.front() == '@') {
    out.mask_path = std::string(args.substr(1));
    if (out.mask_path.empty())
      refuse_mask("'" + spec + "' names no file; write mask:@FILE, or the mask inline as mask:0110");
    out.mask = read_mask_file(out.mask_path);
    check_mask_blocks(out.mask, "mask file '" + out.mask_path + "'");
  } else {
    out.mask = inline_blocks(args, spec);
    check_mask_blocks(out.mask);
  }
  return out;
}

void check_mask_blocks(const std::vector<std::uint8_t>& mask, const std::string& what) {
  if (mask.empty()) refuse_mask("empty mask; " + std::string(kAllowed));
  check_not_too_long(mask.size(), what);
  if (std::any_of(mask.begin(), mask.end(), [](std::uint8_t m) { return m > 1; }))
    refuse_mask(what + " has an entry that is neither 0 nor 1; " + kAllowed);
  if (std::find(mask.begin(), mask.end(), std::uint8_t{1}) == mask.end())
    refuse_mask(what + " has no block in contact (no 1 among its " + std::to_string(mask.size()) +
                " blocks); the surface cannot carry the load: a mask needs at least one 1 (pawl)");
}

void check_mask_length(const PatternSpec& spec, int N) {
  const auto blocks = spec.mask.size();
  if (blocks == static_cast<std::size_t>(N)) return;
  const std::string what = spec.mask_path.empty() ? "the mask" : "mask file '" + spec.mask_path + "'";
  refuse_mask(what + " has " + std::to_string(blocks) + " blocks but the chain has N = " + std::to_string(N) +
              "; a mask gives one character per block, so its length must equal N (set N = " +
              std::to_string(blocks) + ", or give a mask of " + std::to_string(N) + " blocks)");
}

std::string mask_digits(const std::vector<std::uint8_t>& mask) {
  std::string s(mask.size(), '0');
  for (std::size_t i = 0; i < mask.size(); ++i)
    if (mask[i]) s[i] = '1';
  return s;
}

std::string mask_hash(const std::vector<std::uint8_t>& mask) {
  Fnv1a64 h;  // of the digits mask_digits writes
  for (auto m : mask) h.add(static_cast<unsigned char>(m ? '1' : '0'));
  return h.hex();
}

std::string pattern_label(const PatternSpec& spec) {
  if (spec.kind != SurfaceKind::Mask || (spec.mask_path.empty() && spec.mask.size() <= 40)) return spec.text();
  const auto pawls = std::count(spec.mask.begin(), spec.mask.end(), std::uint8_t{1});
  const std::string numbers = std::to_string(spec.mask.size()) + " blocks, " + std::to_string(pawls) +
                              " in contact, fnv1a64 " + mask_hash(spec.mask) + ")";
  if (!spec.mask_path.empty()) return spec.text() + " (" + numbers;
  const std::vector<std::uint8_t> head(spec.mask.begin(), spec.mask.begin() + 24);
  return "mask:" + mask_digits(head) + "... (" + numbers;
}

}  // namespace sb
