#include "sweep_files.hpp"

#include <unistd.h>

#include <filesystem>

#include "shell/output.hpp"
#include "springblock/errors.hpp"
#include "springblock/io.hpp"

namespace sb::app {

std::string out_path(const SweepOptions& o) {
  if (!o.out.empty()) return o.out;
  const auto dot = o.file.rfind('.');
  return (dot == std::string::npos ? o.file : o.file.substr(0, dot)) + ".results.jsonl";
}

std::unique_ptr<sweep::Checkpoint> open_checkpoint(const SweepOptions& o, const std::vector<sweep::SweepScene>& scenes,
                                                   const std::vector<sweep::Unit>& units,
                                                   sweep::StreamedResults& results) {
  shell::claim_output(out_path(o), "out");
  shell::claim_output(sweep::partial_path(out_path(o)), "out");
  if (!o.units.empty()) {
    const std::string out = out_path(o);
    for (const auto& taken : {out, sweep::partial_path(out), out + ".checkpoint"})
      if (std::filesystem::absolute(o.units).lexically_normal() == std::filesystem::absolute(taken).lexically_normal())
        throw InputError("units", "'" + o.units + "' is the sweep's own file " + taken + "; give another file");
    shell::claim_output(o.units, "units");
    shell::claim_output(sweep::partial_path(o.units), "units");
  }
  auto resumed = [&](const nlohmann::json& record) {
    const auto& u = units.at(record.at("unit").get<int>());
    results.add(u.scene, u.rep, sweep::record_numbers(record));
  };
  return std::make_unique<sweep::Checkpoint>(out_path(o) + ".checkpoint", sweep::fingerprint(scenes),
                                             static_cast<int>(units.size()), o.resume, resumed);
}

nlohmann::json partial_header(const SweepOptions& o, const std::vector<sweep::SweepScene>& scenes,
                              const std::vector<sweep::Unit>& units, const std::string& command_line) {
  return {{"kind", "sweep"},
          {"file", o.file},
          {"scenes", scenes.size()},
          {"units", units.size()},
          {"fingerprint", sweep::fingerprint(scenes)},
          {"provenance", provenance(command_line)}};
}

std::unique_ptr<sweep::LineFile> start_unit_records(const std::string& path, const sweep::Checkpoint& cp) {
  auto file = std::make_unique<sweep::LineFile>(sweep::partial_path(path) + ".tmp." + std::to_string(::getpid()));
  for (int id = 0; cp.done_count() > 0 && id < cp.units(); ++id)
    if (cp.done(id)) file->append(cp.record_text(id));
  file->rename_to(sweep::partial_path(path));
  return file;
}

}  // namespace sb::app
