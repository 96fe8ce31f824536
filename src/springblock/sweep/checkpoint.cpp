#include "springblock/sweep/checkpoint.hpp"

#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>

#include "springblock/errors.hpp"
#include "springblock/io.hpp"

namespace sb::sweep {
namespace {

nlohmann::json checkpoint_header(const std::string& fingerprint, int units) {
  return {{"checkpoint", "springblock sweep"}, {"fingerprint", fingerprint}, {"units", units}};
}

double steady_s() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

}  // namespace

Checkpoint::Checkpoint(std::string path, const std::string& fingerprint, int units, bool resume,
                       const ResumedRecord& resumed)
    : path_(std::move(path)), offset_(units, -1) {
  const bool exists = std::filesystem::exists(path_);
  if (exists && !resume)
    throw InputError("resume", "checkpoint '" + path_ +
                                   "' exists from an unfinished run of this sweep: add --resume to finish it, "
                                   "or delete it to start over");
  check_writable(path_, "checkpoint");
  // Written beside the old file and renamed over it once whole: a failure leaves the old one.
  auto clean = std::make_unique<LineFile>(path_ + ".tmp." + std::to_string(::getpid()));
  try {
    clean->append(checkpoint_header(fingerprint, units).dump());
    if (exists) load(fingerprint, units, *clean, resumed);
    clean->rename_to(path_);
  } catch (...) {
    clean->remove();
    throw;
  }
  file_ = std::move(clean);
}

void Checkpoint::load(const std::string& fingerprint, int units, LineFile& clean, const ResumedRecord& resumed) {
  std::ifstream in(path_);
  std::vector<int> handed_to(units, -1);  // unit -> rank it was last handed to
  std::string line, next;
  bool more = static_cast<bool>(std::getline(in, line));
  for (int i = 0; more; ++i, line.swap(next)) {
    more = static_cast<bool>(std::getline(in, next));
    nlohmann::json j;
    try {
      j = nlohmann::json::parse(line);
    } catch (const nlohmann::json::exception&) {
      if (!more) break;  // cut short by a kill while it was written: that unit reruns
      throw InputError("resume", "checkpoint '" + path_ + "' line " + std::to_string(i + 1) + " is corrupt");
    }
    if (i == 0) {
      if (j != checkpoint_header(fingerprint, units))
        throw InputError("resume", "checkpoint '" + path_ + "' belongs to another sweep (other scenes or "
                                   "repetitions); delete it to start this one over");
    } else if (j.contains("assigned")) {
      const auto& ids = j.at("assigned");
      for (const auto& id : ids.is_array() ? ids : nlohmann::json::array({ids}))
        handed_to.at(id.get<int>()) = j.at("rank").get<int>();
    } else {
      const int unit = j.at("unit").get<int>();
      if (offset_.at(unit) >= 0) continue;
      offset_[unit] = clean.append(line);
      ++done_count_;
      if (resumed) resumed(j);
    }
  }
  for (int unit = 0; unit < units; ++unit)
    if (handed_to[unit] >= 0 && !done(unit)) lost_.push_back({unit, handed_to[unit]});
}

std::string Checkpoint::record_text(int unit) const { return file_->line_at(offset_.at(unit)); }

void Checkpoint::sync() {
  if (file_) file_->sync();
  last_sync_s_ = steady_s();
  unsynced_ = false;
}

void Checkpoint::flush() {
  if (!file_) return;
  const double now = steady_s();
  if (file_->held_bytes() >= kWriteBytes || now - last_write_s_ >= kWriteEvery) {
    file_->flush();
    last_write_s_ = now;
  }
  if (unsynced_ && now - last_sync_s_ >= kSyncEvery) sync();
}

void Checkpoint::assigned(const std::vector<int>& units, int rank) {
  // A single unit as a number, a batch as a list; load() reads both.
  const nlohmann::json ids = units.size() == 1 ? nlohmann::json(units[0]) : nlohmann::json(units);
  file_->hold(nlohmann::json{{"assigned", ids}, {"rank", rank}}.dump());
  unsynced_ = true;
}

void Checkpoint::finished(int unit, const std::string& record_text) {
  const std::int64_t at = file_->hold(record_text);
  unsynced_ = true;
  if (offset_.at(unit) < 0) ++done_count_;
  offset_[unit] = at;
}

void Checkpoint::remove() {
  if (file_) file_->remove();
  file_.reset();
}

}  // namespace sb::sweep
