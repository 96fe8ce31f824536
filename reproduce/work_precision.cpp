#include "work_precision.hpp"

#include <cmath>
#include <cstdio>

#include "springblock/errors.hpp"

namespace repro {
namespace {

// Settings refused by validation (e.g. an RK4 step beyond the stability limit) are reported,
// not dropped: one list per process, filled by the plan and emptied into the document.
nlohmann::json& failed_list() {
  static nlohmann::json failed = nlohmann::json::array();
  return failed;
}

const nlohmann::json* find_reference(const nlohmann::json& scenes, const std::string& study) {
  for (const auto& s : scenes)
    if (s["x"]["study"] == study && s["x"]["reference"].get<bool>()) return &s;
  return nullptr;
}

double num(const nlohmann::json& j) { return j.is_number() ? j.get<double>() : std::nan(""); }

// The name a work-precision row gives its method: one line per method in the figure.
std::string method_label(const WorkPrecisionSetting& st) {
  if (st.method == sb::Method::RK4) return "rk4";
  return "event " + sb::stepper_name(st.stepper);
}

}  // namespace

std::vector<WorkPrecisionSetting> work_precision_settings(const std::vector<double>& rk4_steps_s,
                                                          const std::vector<double>& dopri5_tols,
                                                          const std::vector<double>& exact_tols, bool with_check) {
  std::vector<WorkPrecisionSetting> s;
  char name[64];
  for (double h : rk4_steps_s) {
    std::snprintf(name, sizeof name, "rk4 h=%.3gs", h);
    s.push_back({name, sb::Method::RK4, h, 1e-9});  // tol unused by RK4, kept valid
  }
  for (double tol : dopri5_tols) {
    std::snprintf(name, sizeof name, "dopri5 tol=%.0e", tol);
    s.push_back({name, sb::Method::Event, 1e-7, tol});
  }
  for (double tol : exact_tols) {
    std::snprintf(name, sizeof name, "exact tol=%.0e", tol);
    s.push_back({name, sb::Method::Event, 1e-7, tol, false, false, sb::Stepper::Exact});
  }
  if (with_check) s.push_back({"dopri5 tol=1e-11 (reference check)", sb::Method::Event, 1e-7, 1e-11, false, true});
  s.push_back({"dopri5 tol=1e-12 (reference)", sb::Method::Event, 1e-7, 1e-12, true, false});
  return s;
}


std::vector<LabelledScene> work_precision_plan(const Context& ctx, const std::vector<WorkPrecisionSetting>& settings) {
  std::vector<LabelledScene> out;
  for (const auto& st : settings) {
    for (const char* study : {"first_peak", "mu_d"}) {
      const bool peak = std::string(study) == "first_peak";
      LabelledScene ls;
      ls.scene = peak ? ctx.chain(360, "7.2cm", "periodic:10,10") : ctx.chain(200, "4cm");
      ls.scene.run.method = st.method;
      ls.scene.run.dt_s = st.dt_s;
      ls.scene.run.tol = st.tol;
      ls.scene.run.stepper = st.stepper;
      if (peak) {
        // Three seeds suffice: the per-seed error is deterministic, not a statistic.
        ls.scene.reps = std::min(ls.scene.reps, 3);
        ls.scene.run.stop_after_mu_s = true;
        ls.scene.run.sample_dt_s = 1e-6;
      }
      ls.shared_seed = true;  // identical draws for every setting: differences are numerical
      ls.id = std::string(study) + ":" + st.name;
      ls.label = st.name;
      ls.x = {{"study", study},          {"setting", st.name},
              {"method", method_label(st)}, {"dt_s", st.dt_s},
              {"tol", st.tol},           {"reference", st.reference},
              {"reference_check", st.reference_check}};
      try {
        sb::validate(ls.scene);
        out.push_back(std::move(ls));
      } catch (const sb::InputError& e) {
        failed_list().push_back({{"study", study}, {"setting", st.name}, {"reason", e.what()}});
      }
    }
  }
  return out;
}

// Per setting and study: cost (wall seconds, rhs evaluations) and error against the reference.
// The scenes share one pool of threads (repro::run_target), so a setting's wall seconds are its
// repetitions' wall times summed and divided by the thread count: what it costs on this
// machine, without the idle tail of a scene whose 3 seeds do not split over 2 threads.
// First peak: max over seeds of |mu_s - ref| and |t_slip - ref|. mu_d: |mean - ref|, also
// divided by the reference's standard error.
void work_precision_finish(const Context&, nlohmann::json& doc) {
  nlohmann::json table = nlohmann::json::array();
  for (const char* study : {"first_peak", "mu_d"}) {
    const auto* ref = find_reference(doc["scenes"], study);
    if (!ref) continue;
    const auto& ref_runs = (*ref)["result"]["runs"];
    for (const auto& s : doc["scenes"]) {
      if (s["x"]["study"] != study) continue;
      const auto& r = s["result"];
      nlohmann::json row = {{"study", study},
                            {"setting", s["x"]["setting"]},
                            {"method", s["x"]["method"]},
                            {"dt_s", s["x"]["dt_s"]},
                            {"tol", s["x"]["tol"]},
                            {"reference", s["x"]["reference"]},
                            {"reference_check", s["x"]["reference_check"]},
                            {"wall_seconds", r["wall_seconds"]},
                            {"rhs_evals_total", r["rhs_evals_total"]}};
      if (std::string(study) == "first_peak") {
        double e_mu = 0, e_t = 0;
        for (std::size_t k = 0; k < r["runs"].size() && k < ref_runs.size(); ++k) {
          e_mu = std::max(e_mu, std::fabs(num(r["runs"][k]["mu_s"]) - num(ref_runs[k]["mu_s"])));
          e_t = std::max(e_t, std::fabs(num(r["runs"][k]["t_slip_s"]) - num(ref_runs[k]["t_slip_s"])));
        }
        row["error_mu_s"] = e_mu;
        row["error_t_slip_s"] = e_t;
        row["error"] = e_mu;  // the headline metric plotted by figures/accuracy_cost.py
      } else {
        const double ref_mean = num((*ref)["result"]["mu_d"]["mean"]);
        const double ref_sem = num((*ref)["result"]["mu_d"]["sem"]);
        const double diff = std::fabs(num(r["mu_d"]["mean"]) - ref_mean);
        row["error_mu_d"] = diff;
        row["error_mu_d_over_sem"] = ref_sem > 0 ? diff / ref_sem : std::nan("");
        row["error"] = diff;
      }
      table.push_back(row);
    }
  }
  doc["work_precision"] = table;
  doc["failed"] = failed_list();
}

}  // namespace repro
