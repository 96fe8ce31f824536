#include "springblock/sweep/line_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <stdexcept>

namespace sb::sweep {
namespace {

[[noreturn]] void line_file_error(const std::string& what, const std::string& path) {
  throw std::runtime_error("cannot " + what + " '" + path + "': " + std::strerror(errno));
}

}  // namespace

LineFile::LineFile(std::string path) : path_(std::move(path)) {
  fd_ = ::open(path_.c_str(), O_RDWR | O_CREAT | O_TRUNC | O_APPEND | O_CLOEXEC, 0644);
  if (fd_ < 0) line_file_error("create", path_);
}

LineFile::~LineFile() {
  if (fd_ >= 0) ::close(fd_);
}

std::int64_t LineFile::append(const std::string& line) {
  const std::string text = line + "\n";
  if (::write(fd_, text.data(), text.size()) != static_cast<ssize_t>(text.size())) line_file_error("append to", path_);
  const std::int64_t at = size_;
  size_ += static_cast<std::int64_t>(text.size());
  return at;
}

std::string LineFile::line_at(std::int64_t offset) const {
  std::string out;
  char buf[4096];
  for (;;) {
    const ssize_t n = ::pread(fd_, buf, sizeof buf, offset + static_cast<std::int64_t>(out.size()));
    if (n < 0) line_file_error("read", path_);
    const auto* end = static_cast<const char*>(std::memchr(buf, '\n', static_cast<std::size_t>(n)));
    if (end) return out.append(buf, static_cast<std::size_t>(end - buf));
    if (n == 0) throw std::runtime_error("'" + path_ + "' ends inside a line it wrote");
    out.append(buf, static_cast<std::size_t>(n));
  }
}

void LineFile::sync() {
  if (fd_ >= 0 && ::fsync(fd_) != 0) line_file_error("sync", path_);
}

void LineFile::rename_to(const std::string& path) {
  if (std::rename(path_.c_str(), path.c_str()) != 0) line_file_error("rename", path_);
  path_ = path;
}

void LineFile::remove() {
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
  std::remove(path_.c_str());
}

}  // namespace sb::sweep
