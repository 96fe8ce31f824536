#pragma once
// The checkpoint of a sweep: a JSON-lines file beside the results, one line appended per
// finished unit with one write() as soon as the unit is in, so a sweep killed at any moment
// (Ctrl-C, a dead rank, a killed job) loses at most the units in flight. fsync (which only a
// crash of the machine itself needs) is grouped: at most every 0.1 s, since one per unit cost
// rank 0 about 4 ms a unit on this machine and capped a sweep at ~250 units/s (README). Units handed to a rank are logged too (not synced): on
// resume, those handed out but never finished are reported as lost with the rank that had them.
// Only the coordinator (rank 0) touches the file.
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace sb::sweep {

struct LostUnit {
  int unit = 0;
  int rank = 0;
};

class Checkpoint {
 public:
  // A fresh checkpoint refuses an existing file (the user meant --resume, or should delete it);
  // a resumed one reads it (a truncated last line, from a kill mid-write, is dropped), checks it
  // belongs to this sweep (`fingerprint`), and rewrites it clean before appending.
  // Throws InputError("resume", ...) naming the file.
  Checkpoint(std::string path, const std::string& fingerprint, int units, bool resume);
  ~Checkpoint();
  Checkpoint(const Checkpoint&) = delete;
  Checkpoint& operator=(const Checkpoint&) = delete;

  const std::map<int, nlohmann::json>& finished() const { return finished_; }
  const std::vector<LostUnit>& lost() const { return lost_; }  // from the run being resumed
  const std::string& path() const { return path_; }

  void assigned(int unit, int rank);             // logged, not synced
  void finished(const nlohmann::json& record);   // logged; fsynced if the last fsync is 0.1 s old
  void sync();                                   // fsync now (the run stops)
  void remove();                                 // the sweep is complete: its results hold it all

 private:
  void append(const std::string& line, bool sync);
  void load(const std::string& fingerprint, int units);

  std::string path_;
  int fd_ = -1;
  double last_sync_s_ = 0;  // steady-clock seconds of the last fsync
  std::map<int, nlohmann::json> finished_;
  std::vector<LostUnit> lost_;
};

}  // namespace sb::sweep
