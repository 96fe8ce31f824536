#include "springblock/input_file.hpp"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <ios>

#include "springblock/errors.hpp"

namespace sb {

std::string read_input_file(const std::string& path, const std::string& field, const std::string& what) {
  const std::string cannot = "cannot read " + what + " '" + path + "': ";
  std::error_code ec;
  // A directory opens as a stream on Linux; reading it throws from inside the library.
  if (std::filesystem::is_directory(path, ec)) throw InputError(field, cannot + "it is a directory");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(field, cannot + std::strerror(errno));
  // Far above any input of a 10^6-block chain; a device or pipe that never ends is refused.
  constexpr std::size_t kMaxBytes = std::size_t{1} << 30;
  std::string text;
  try {
    char chunk[1 << 16];
    while (in.read(chunk, sizeof chunk) || in.gcount() > 0) {
      text.append(chunk, static_cast<std::size_t>(in.gcount()));
      if (text.size() > kMaxBytes) throw InputError(field, cannot + "it is longer than 1 GiB");
    }
  } catch (const std::ios_base::failure& e) {
    throw InputError(field, cannot + e.what());
  }
  if (in.bad()) throw InputError(field, cannot + "a read failed");
  return text;
}

}  // namespace sb
