#pragma once
// The checkpoint of a sweep: a JSON-lines file beside the results, one line per finished unit.
// Lines are written together, with one write(), once kWriteBytes are held or kWriteEvery has
// passed since the last write: a system call per unit would be most of rank 0's time per unit
// when units are short (rank 0's own units arrive one at a time). So a sweep killed at any
// moment (a dead rank, a killed job) loses at most the units in flight and those finished in
// the last kWriteEvery, which a resume runs again; Ctrl-C writes them all (sync). fsync, which
// only a crash of the machine itself needs, is grouped: at most every kSyncEvery. One per unit
// cost rank 0 milliseconds a unit; one every 0.1 s still cost it more than all else per tiny
// unit, since each waits for the disk; a machine crash loses at most kSyncEvery of work. Units
// handed to a rank are logged too (not synced): on resume, those handed out but never finished
// are reported as lost with the rank that had them. Only the coordinator (rank 0) touches the
// file, and it keeps no record in memory: only where each finished unit's line starts, so that
// the results can read the records back scene by scene.
#include <cstdint>
#include <functional>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "springblock/sweep/line_file.hpp"

namespace sb::sweep {

struct LostUnit {
  int unit = 0;
  int rank = 0;
};

// Called with each finished record read from a resumed checkpoint, in the file's order.
using ResumedRecord = std::function<void(const nlohmann::json& record)>;

class Checkpoint {
 public:
  // A fresh checkpoint refuses an existing file (the user meant --resume, or should delete it);
  // a resumed one reads it line by line (a truncated last line, from a kill mid-write, is
  // dropped; a unit finished twice counts once), checks it belongs to this sweep
  // (`fingerprint`), hands each finished record to `resumed`, and rewrites it clean (through a
  // temporary file renamed over it) before appending. Throws InputError("resume", ...) naming
  // the file.
  Checkpoint(std::string path, const std::string& fingerprint, int units, bool resume,
             const ResumedRecord& resumed = {});

  bool done(int unit) const { return offset_[unit] >= 0; }
  int done_count() const { return done_count_; }
  int units() const { return static_cast<int>(offset_.size()); }
  const std::vector<LostUnit>& lost() const { return lost_; }  // from the run being resumed
  const std::string& path() const { return path_; }
  // A finished unit's record as the file holds it (one JSON object: the shortest round-trip text
  // of every double).
  std::string record_text(int unit) const;

  // Units handed out together, as one line; unit `unit`'s record as text (one line). Both are
  // held until flush(), which the coordinator calls once it has taken in what one message (or
  // one of its own threads) brought: one write() per batch, not per unit.
  void assigned(const std::vector<int>& units, int rank);
  void finished(int unit, const std::string& record_text);
  void finished(const nlohmann::json& record) { finished(record.at("unit").get<int>(), record.dump()); }
  // Writes what is held if it is kWriteBytes or kWriteEvery old; fsyncs if the last fsync is
  // kSyncEvery old.
  void flush();
  static constexpr std::size_t kWriteBytes = std::size_t{1} << 16;
  static constexpr double kWriteEvery = 0.02, kSyncEvery = 1.0;  // seconds
  void sync();    // writes what is held and fsyncs now (the run stops)
  void remove();  // the sweep is complete: its results hold it all

 private:
  void load(const std::string& fingerprint, int units, LineFile& clean, const ResumedRecord& resumed);

  std::string path_;
  std::unique_ptr<LineFile> file_;
  double last_sync_s_ = 0;            // steady-clock seconds of the last fsync
  double last_write_s_ = 0;           // and of the last write
  bool unsynced_ = false;             // lines held or written since then
  std::vector<std::int64_t> offset_;  // per unit: where its record starts, -1 until finished
  int done_count_ = 0;
  std::vector<LostUnit> lost_;
};

}  // namespace sb::sweep
