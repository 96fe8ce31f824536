#pragma once
// The files a sweep's coordinator writes, opened: the checkpoint (after every output path is
// claimed, so bad input leaves no file), the partial results' header and the per-unit records.
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "springblock/sweep/checkpoint.hpp"
#include "springblock/sweep/streamed_results.hpp"
#include "springblock/sweep/units.hpp"

namespace sb::sweep {

// Where a sweep's outputs go and whether it resumes. `file` is what the results record as the
// sweep file (its path, or a label for a sweep given another way).
struct OutputOptions {
  std::string file, out, units;  // units: the per-unit records file, if asked
  bool resume = false;
};

// The results file: `out`, or the sweep file with .results.jsonl.
std::string out_path(const OutputOptions& o);

// The checkpoint, after every output path is claimed; the records of a resumed one go to
// `results` as they are read. Throws InputError for a refused path or checkpoint.
std::unique_ptr<Checkpoint> open_checkpoint(const OutputOptions& o, const std::vector<SweepScene>& scenes,
                                            const std::vector<Unit>& units, StreamedResults& results);

// The partial results' header: what the sweep is, before any of its numbers.
nlohmann::json partial_header(const OutputOptions& o, const std::vector<SweepScene>& scenes,
                              const std::vector<Unit>& units, const std::string& command_line);

// UNITS.partial: the records of the units already done (a resumed sweep's, in unit order), then
// each unit's as it finishes; renamed to UNITS when the sweep completes.
std::unique_ptr<LineFile> start_unit_records(const std::string& path, const Checkpoint& cp);

}  // namespace sb::sweep
