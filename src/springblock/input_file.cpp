#include "springblock/input_file.hpp"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <ios>

#include "springblock/errors.hpp"

namespace sb {
namespace {

std::string cannot_read(const std::string& path, const std::string& what) {
  return "cannot read " + what + " '" + path + "': ";
}

}  // namespace

void read_input_chunks(const std::string& path, const std::string& field, const std::string& what,
                       const std::function<void(std::string_view)>& take) {
  std::error_code ec;
  // A directory opens as a stream on Linux; reading it throws from inside the library.
  if (std::filesystem::is_directory(path, ec)) throw InputError(field, cannot_read(path, what) + "it is a directory");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(field, cannot_read(path, what) + std::strerror(errno));
  try {
    char chunk[1 << 16];
    while (in.read(chunk, sizeof chunk) || in.gcount() > 0)
      take(std::string_view(chunk, static_cast<std::size_t>(in.gcount())));
  } catch (const std::ios_base::failure& e) {
    throw InputError(field, cannot_read(path, what) + e.what());
  }
  if (in.bad()) throw InputError(field, cannot_read(path, what) + "a read failed");
}

std::string read_input_file(const std::string& path, const std::string& field, const std::string& what) {
  // Far above any input of a 10^6-block chain.
  constexpr std::size_t kMaxBytes = std::size_t{1} << 30;
  std::string text;
  read_input_chunks(path, field, what, [&](std::string_view chunk) {
    text.append(chunk);
    if (text.size() > kMaxBytes) throw InputError(field, cannot_read(path, what) + "it is longer than 1 GiB");
  });
  return text;
}

}  // namespace sb
