#include "springblock/sweep/outputs.hpp"

#include <unistd.h>

#include <filesystem>

#include "springblock/errors.hpp"
#include "springblock/io.hpp"

namespace sb::sweep {

std::string out_path(const OutputOptions& o) {
  if (!o.out.empty()) return o.out;
  const auto dot = o.file.rfind('.');
  return (dot == std::string::npos ? o.file : o.file.substr(0, dot)) + ".results.jsonl";
}

std::unique_ptr<Checkpoint> open_checkpoint(const OutputOptions& o, const std::vector<SweepScene>& scenes,
                                            const std::vector<Unit>& units, StreamedResults& results) {
  check_writable(out_path(o), "out");
  check_writable(partial_path(out_path(o)), "out");
  if (!o.units.empty()) {
    const std::string out = out_path(o);
    for (const auto& taken : {out, partial_path(out), out + ".checkpoint"})
      if (std::filesystem::absolute(o.units).lexically_normal() == std::filesystem::absolute(taken).lexically_normal())
        throw InputError("units", "'" + o.units + "' is the sweep's own file " + taken + "; give another file");
    check_writable(o.units, "units");
    check_writable(partial_path(o.units), "units");
  }
  auto resumed = [&](const nlohmann::json& record) {
    const auto& u = units.at(record.at("unit").get<int>());
    results.add(u.scene, u.rep, record_numbers(record));
  };
  return std::make_unique<Checkpoint>(out_path(o) + ".checkpoint", fingerprint(scenes),
                                      static_cast<int>(units.size()), o.resume, resumed);
}

nlohmann::json partial_header(const OutputOptions& o, const std::vector<SweepScene>& scenes,
                              const std::vector<Unit>& units, const std::string& command_line) {
  return {{"kind", "sweep"},
          {"file", o.file},
          {"scenes", scenes.size()},
          {"units", units.size()},
          {"fingerprint", fingerprint(scenes)},
          {"provenance", provenance(command_line)}};
}

std::unique_ptr<LineFile> start_unit_records(const std::string& path, const Checkpoint& cp) {
  auto file = std::make_unique<LineFile>(partial_path(path) + ".tmp." + std::to_string(::getpid()));
  for (int id = 0; cp.done_count() > 0 && id < cp.units(); ++id)
    if (cp.done(id)) file->append(cp.record_text(id));
  file->rename_to(partial_path(path));
  return file;
}

}  // namespace sb::sweep
