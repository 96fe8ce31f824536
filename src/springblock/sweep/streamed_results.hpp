#pragma once
// A sweep's results as its units come in, in memory bounded by the scenes in flight rather than
// by the sweep's size. A finished unit leaves only the numbers its scene's statistics need
// (SceneNumbers), held until the scene's last repetition is in; then the scene's line (without
// its runs) is appended to OUT.partial, whose header says "partial": true, and the numbers are
// released. When every unit is in, OUT is written in scene order with each scene's runs read
// back from the checkpoint one record at a time (a temporary file renamed over OUT), and
// OUT.partial is removed. So OUT is only ever complete, and OUT.partial is readable at any time:
// every line whole, one per scene complete so far, in the order they completed.
#include <cstdint>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "springblock/sweep/checkpoint.hpp"
#include "springblock/sweep/expand.hpp"
#include "springblock/sweep/line_file.hpp"
#include "springblock/sweep/results.hpp"

namespace sb::sweep {

// Where the partial results of OUT are kept while the sweep runs.
std::string partial_path(const std::string& out);

class StreamedResults {
 public:
  StreamedResults(const std::vector<SweepScene>& scenes, std::string out);

  // A finished unit's numbers (record_numbers), live or from a resumed checkpoint (each unit once).
  void add(int scene, int rep, const nlohmann::json& record_numbers);
  // Starts OUT.partial afresh: `header` marked partial, then the scenes already complete.
  void start(nlohmann::json header);
  // Every unit is in: writes OUT (`header`, then every scene's line with its runs, records from
  // `checkpoint`) and removes OUT.partial.
  void complete(const nlohmann::json& header, const Checkpoint& checkpoint);

  int scenes_complete() const { return complete_; }
  const std::string& partial() const { return partial_path_; }
  // The summary table's heading and one row per complete scene, in scene order.
  std::string summary() const;

 private:
  const std::vector<SweepScene>& scenes_;
  std::string out_, partial_path_;
  std::unique_ptr<LineFile> partial_;
  std::vector<int> in_;                   // units in, per scene
  std::map<int, SceneNumbers> open_;      // scenes begun and not complete
  std::vector<nlohmann::json> waiting_;   // complete before start(): their lines
  std::vector<std::int64_t> line_at_;     // per scene: its line's offset in OUT.partial, -1 until written
  std::vector<std::string> rows_;         // per scene: its summary row once complete
  int complete_ = 0;
};

}  // namespace sb::sweep
