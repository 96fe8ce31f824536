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
#include "sweep_run.hpp"

namespace sb::app {

// The results file: --out, or the sweep file with .results.jsonl.
std::string out_path(const SweepOptions& o);

// The checkpoint, after every output path is claimed; the records of a resumed one go to
// `results` as they are read. Throws InputError for a refused path or checkpoint.
std::unique_ptr<sweep::Checkpoint> open_checkpoint(const SweepOptions& o, const std::vector<sweep::SweepScene>& scenes,
                                                   const std::vector<sweep::Unit>& units,
                                                   sweep::StreamedResults& results);

// The partial results' header: what the sweep is, before any of its numbers.
nlohmann::json partial_header(const SweepOptions& o, const std::vector<sweep::SweepScene>& scenes,
                              const std::vector<sweep::Unit>& units, const std::string& command_line);

// UNITS.partial: the records of the units already done (a resumed sweep's, in unit order), then
// each unit's as it finishes; renamed to UNITS when the sweep completes.
std::unique_ptr<sweep::LineFile> start_unit_records(const std::string& path, const sweep::Checkpoint& cp);

}  // namespace sb::app
