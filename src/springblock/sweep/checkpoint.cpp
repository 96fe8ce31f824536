#include "springblock/sweep/checkpoint.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "springblock/errors.hpp"
#include "springblock/io.hpp"

namespace sb::sweep {
namespace {

nlohmann::json header(const std::string& fingerprint, int units) {
  return {{"checkpoint", "springblock sweep"}, {"fingerprint", fingerprint}, {"units", units}};
}

double steady_s() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

std::vector<std::string> read_lines(const std::string& path) {
  std::ifstream in(path);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

}  // namespace

Checkpoint::Checkpoint(std::string path, const std::string& fingerprint, int units, bool resume)
    : path_(std::move(path)) {
  const bool exists = std::filesystem::exists(path_);
  if (exists && !resume)
    throw InputError("resume", "checkpoint '" + path_ +
                                   "' exists from an unfinished run of this sweep: add --resume to finish it, "
                                   "or delete it to start over");
  if (exists) load(fingerprint, units);
  std::string text = header(fingerprint, units).dump() + "\n";
  for (auto& [unit, record] : finished_) text += record.dump() + "\n";
  check_writable(path_, "checkpoint");
  write_file_atomic(path_, text);
  fd_ = ::open(path_.c_str(), O_WRONLY | O_APPEND | O_CLOEXEC);
  if (fd_ < 0) throw std::runtime_error("cannot open checkpoint '" + path_ + "': " + std::strerror(errno));
}

Checkpoint::~Checkpoint() {
  if (fd_ >= 0) ::close(fd_);
}

void Checkpoint::load(const std::string& fingerprint, int units) {
  const auto lines = read_lines(path_);
  std::map<int, int> handed_to;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    nlohmann::json j;
    try {
      j = nlohmann::json::parse(lines[i]);
    } catch (const nlohmann::json::exception&) {
      if (i + 1 == lines.size()) break;  // cut short by a kill while it was written: that unit reruns
      throw InputError("resume", "checkpoint '" + path_ + "' line " + std::to_string(i + 1) + " is corrupt");
    }
    if (i == 0) {
      if (j != header(fingerprint, units))
        throw InputError("resume", "checkpoint '" + path_ + "' belongs to another sweep (other scenes or "
                                   "repetitions); delete it to start this one over");
    } else if (j.contains("assigned")) {
      handed_to[j.at("assigned").get<int>()] = j.at("rank").get<int>();
    } else {
      finished_[j.at("unit").get<int>()] = j;
    }
  }
  for (auto& [unit, rank] : handed_to)
    if (!finished_.count(unit)) lost_.push_back({unit, rank});
}

void Checkpoint::append(const std::string& line, bool sync_due) {
  const std::string text = line + "\n";
  // One write per line, O_APPEND: a kill leaves at most the last line cut short.
  if (::write(fd_, text.data(), text.size()) != static_cast<ssize_t>(text.size()))
    throw std::runtime_error("cannot append to checkpoint '" + path_ + "': " + std::strerror(errno));
  if (sync_due && steady_s() - last_sync_s_ >= 0.1) sync();
}

void Checkpoint::sync() {
  if (fd_ >= 0 && ::fsync(fd_) != 0)
    throw std::runtime_error("cannot sync checkpoint '" + path_ + "': " + std::strerror(errno));
  last_sync_s_ = steady_s();
}

void Checkpoint::assigned(int unit, int rank) {
  append(nlohmann::json{{"assigned", unit}, {"rank", rank}}.dump(), false);
}

void Checkpoint::finished(const nlohmann::json& record) {
  append(record.dump(), true);
  finished_[record.at("unit").get<int>()] = record;
}

void Checkpoint::remove() {
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
  std::filesystem::remove(path_);
}

}  // namespace sb::sweep
