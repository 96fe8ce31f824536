#pragma once
// A directory of this process's own under the system's temporary directory, removed with
// everything in it when the test ends.
#include <unistd.h>

#include <filesystem>
#include <string>

namespace sbtest {

struct TempDir {
  explicit TempDir(const std::string& prefix)
      : path(std::filesystem::temp_directory_path() / (prefix + std::to_string(::getpid()))) {
    std::filesystem::create_directories(path);
  }
  ~TempDir() { std::filesystem::remove_all(path); }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  std::filesystem::path path;
};

}  // namespace sbtest
