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
  try {
    if (fd_ >= 0) flush();
  } catch (...) {  // a destructor does not throw: what was held is lost, as in a kill
  }
  if (fd_ >= 0) ::close(fd_);
}

std::int64_t LineFile::hold(const std::string& line) {
  const std::int64_t at = size_;
  held_ += line;
  held_ += '\n';
  size_ += static_cast<std::int64_t>(line.size() + 1);
  return at;
}

void LineFile::flush() {
  if (held_.empty()) return;
  if (::write(fd_, held_.data(), held_.size()) != static_cast<ssize_t>(held_.size())) line_file_error("append to", path_);
  held_.clear();
}

std::int64_t LineFile::append(const std::string& line) {
  const std::int64_t at = hold(line);
  flush();
  return at;
}

std::string LineFile::line_at(std::int64_t offset) const {
  const std::int64_t written = size_ - static_cast<std::int64_t>(held_.size());
  if (offset >= written) {
    const auto from = static_cast<std::size_t>(offset - written);
    return held_.substr(from, held_.find('\n', from) - from);
  }
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
  if (fd_ < 0) return;
  flush();
  if (::fsync(fd_) != 0) line_file_error("sync", path_);
}

void LineFile::rename_to(const std::string& path) {
  if (std::rename(path_.c_str(), path.c_str()) != 0) line_file_error("rename", path_);
  path_ = path;
}

void LineFile::remove() {
  held_.clear();
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
  std::remove(path_.c_str());
}

}  // namespace sb::sweep
