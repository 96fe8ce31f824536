#include "springblock/io.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <fmt/format.h>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <thread>

#include "springblock/errors.hpp"

#ifndef SPRINGBLOCK_VERSION
#define SPRINGBLOCK_VERSION "0"
#endif

namespace sb {

// The commit this library was built from (generated at build time, src/CMakeLists.txt).
const char* build_commit();

void write_file_atomic(const std::string& path, const std::string& content) {
  const std::string tmp = path + ".tmp." + std::to_string(::getpid());
  int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  if (fd < 0) throw std::runtime_error("cannot create " + tmp);
  std::size_t done = 0;
  while (done < content.size()) {
    ssize_t n = ::write(fd, content.data() + done, content.size() - done);
    if (n <= 0) {
      ::close(fd);
      ::unlink(tmp.c_str());
      throw std::runtime_error("cannot write " + tmp);
    }
    done += static_cast<std::size_t>(n);
  }
  ::fsync(fd);
  ::close(fd);
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    ::unlink(tmp.c_str());
    throw std::runtime_error("cannot rename " + tmp + " to " + path);
  }
}

void check_writable(const std::string& path, const std::string& field) {
  if (path.empty()) throw InputError(field, "empty path; give a file name");
  struct stat st{};
  if (::stat(path.c_str(), &st) == 0 && S_ISDIR(st.st_mode))
    throw InputError(field, "'" + path + "' is a directory; give a file name");
  const std::string tmp = path + ".tmp." + std::to_string(::getpid());
  const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL, 0644);
  if (fd < 0) {
    const auto slash = path.rfind('/');
    const std::string dir = slash == std::string::npos ? "." : slash == 0 ? "/" : path.substr(0, slash);
    throw InputError(field, "cannot write '" + path + "' (directory '" + dir + "': " + std::strerror(errno) +
                                "); give a file in an existing, writable directory");
  }
  ::close(fd);
  ::unlink(tmp.c_str());
}

std::string not_measured(const Scene& scene, const EnsembleResult& r, const std::string& quantity) {
  const Statistic& st = quantity == "mu_s" ? r.mu_s : r.mu_d;
  if (st.n > 0) return {};
  if (quantity != "mu_s" && scene.run.stop_after_mu_s) return "stop_after_mu_s";
  if (r.mu_s.n == 0) return "no repetition ended its loading phase before the end of the run (duration)";
  return "no repetition had a sample in its mu_d window (mu_d_skip, duration)";
}

nlohmann::json provenance(const std::string& command_line) {
  std::time_t now = std::time(nullptr);
  char stamp[32];
  std::strftime(stamp, sizeof stamp, "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&now));
  return {{"program", "springblock"},
          {"version", SPRINGBLOCK_VERSION},
          {"commit", build_commit()},
          {"command", command_line},
          {"utc", stamp},
          {"hardware_threads", std::thread::hardware_concurrency()}};
}

namespace {

// Repetition 0's stress snapshots, one entry per time asked for, in time order.
nlohmann::json stress_json(const std::vector<StressSnapshot>& snapshots) {
  auto numbers = [](const std::vector<double>& xs) {
    nlohmann::json a = nlohmann::json::array();
    for (double x : xs) a.push_back(json_number(x));
    return a;
  };
  nlohmann::json out = nlohmann::json::array();
  for (const auto& s : snapshots)
    out.push_back({{"t_s", json_number(s.t)}, {"f_over_Fn", numbers(s.f_over_Fn)}, {"sigma_over_P", numbers(s.sigma_over_P)}});
  return out;
}

// An observable's statistic; one over no repetitions has null mean, std and sem, and says why.
nlohmann::json statistic_json(const Scene& scene, const EnsembleResult& r, const Observable& o) {
  nlohmann::json j = r.*o.statistic;
  if (const auto why = not_measured(scene, r, o); !why.empty()) j["not_measured"] = why;
  return j;
}

}  // namespace

std::string not_measured(const Scene& scene, const EnsembleResult& r, const Observable& o) {
  if (o.summary == Summary::Loading) return not_measured(scene, r, "mu_s");
  if (o.summary == Summary::Window) return not_measured(scene, r, "mu_d");
  return "";
}

nlohmann::json ensemble_json(const Scene& scene, const EnsembleResult& r, const std::string& command_line) {
  nlohmann::json runs = nlohmann::json::array();
  for (const auto& run : r.runs) runs.push_back(run);
  std::int64_t steps = 0, rhs = 0;
  int slipped = 0;
  for (const auto& run : r.runs) steps += run.steps, rhs += run.rhs_evals, slipped += run.slipped;
  const nlohmann::json scene_json = scene;
  nlohmann::json j = {{"reps_slipped", slipped},
                      {"contact_fraction", r.contact_fraction},
                      {"wall_seconds", r.wall_s},
                      {"threads", r.threads},
                      {"steps_total", steps},
                      {"rhs_evals_total", rhs},
                      {"scene", scene_json},
                      {"runs", runs},
                      {"provenance", provenance(command_line)}};
  for (const auto& o : observables())
    if (o.summary != Summary::None) j[o.name] = statistic_json(scene, r, o);
  if (auto slips = slip_event_summary(r); !slips.is_null()) j["slip_events"] = std::move(slips);
  if (!r.runs.empty() && !r.runs.front().stress.empty()) j["stress"] = stress_json(r.runs.front().stress);
  j.update(schema_entries(scene_json));
  return j;
}

std::string series_tsv(const Scene& scene, const EnsembleResult& r, const std::string& command_line) {
  nlohmann::json meta = {{"scene", scene}, {"provenance", provenance(command_line)},
                         {"wall_seconds", r.wall_s}};
  std::string out = "# springblock mu(t) series of repetition 0\n# " + meta.dump() + "\n";
  out += "t_s\tmu\tmu_signed\tn_sliding\n";
  if (!r.runs.empty())
    for (const auto& s : r.runs[0].series)
      out += fmt::format("{:.9g}\t{:.9g}\t{:.9g}\t{}\n", s.t, s.mu, s.mu_signed, s.n_sliding);
  return out;
}

}  // namespace sb
