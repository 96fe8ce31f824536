#include "springblock/sweep/streamed_results.hpp"

#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <stdexcept>

namespace sb::sweep {

std::string partial_path(const std::string& out) { return out + ".partial"; }

StreamedResults::StreamedResults(const std::vector<SweepScene>& scenes, std::string out)
    : scenes_(scenes),
      out_(std::move(out)),
      partial_path_(partial_path(out_)),
      in_(scenes.size(), 0),
      line_at_(scenes.size(), -1),
      rows_(scenes.size()) {}

void StreamedResults::add(int scene, int rep, const nlohmann::json& record_numbers) {
  take_numbers(open_[scene], rep, record_numbers);
  if (++in_.at(scene) < scenes_[scene].scene.reps) return;
  const auto line = scene_statistics(scenes_, scene, open_.at(scene));
  open_.erase(scene);
  rows_[scene] = summary_row(line);
  ++complete_;
  if (partial_) {
    line_at_[scene] = partial_->append(line.dump());
  } else {
    waiting_.push_back(line);
  }
}

void StreamedResults::start(nlohmann::json header) {
  header["partial"] = true;
  // The header is in before the file takes its name: a reader never finds it empty.
  auto file = std::make_unique<LineFile>(partial_path_ + ".tmp." + std::to_string(::getpid()));
  file->append(header.dump());
  for (const auto& line : waiting_) line_at_[line.at("scene").get<int>()] = file->append(line.dump());
  waiting_.clear();
  file->rename_to(partial_path_);
  partial_ = std::move(file);
}

void StreamedResults::complete(const nlohmann::json& header, const Checkpoint& checkpoint) {
  const std::string tmp = out_ + ".tmp." + std::to_string(::getpid());
  try {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    out << header.dump() << '\n';
    int first = 0;
    for (int k = 0; k < static_cast<int>(scenes_.size()); ++k) {
      if (line_at_[k] < 0) throw std::logic_error("results: scene " + std::to_string(k) + " is not complete");
      const auto statistics = nlohmann::json::parse(partial_->line_at(line_at_[k]));
      write_scene_line(out, statistics, scenes_[k].scene.reps,
                       [&](int rep) { return checkpoint.record_text(first + rep); });
      first += scenes_[k].scene.reps;
    }
    out.close();
    if (!out) throw std::runtime_error("cannot write '" + tmp + "'");
    if (std::rename(tmp.c_str(), out_.c_str()) != 0) throw std::runtime_error("cannot rename '" + tmp + "'");
  } catch (...) {
    std::remove(tmp.c_str());
    throw;
  }
  partial_->remove();
}

std::string StreamedResults::summary() const {
  std::string out = summary_heading();
  for (const auto& row : rows_) out += row;
  return out;
}

}  // namespace sb::sweep
