#include "shell/output.hpp"

#include <filesystem>
#include <system_error>

#include "springblock/errors.hpp"
#include "springblock/io.hpp"

namespace sb::shell {

void claim_output(const std::string& path, const std::string& field) { sb::check_writable(path, field); }

void make_output_directory(const std::string& dir, const std::string& field) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) throw sb::InputError(field, "cannot create directory '" + dir + "': " + ec.message());
}

void write_output(const std::string& path, const std::string& content) { sb::write_file_atomic(path, content); }

}  // namespace sb::shell
