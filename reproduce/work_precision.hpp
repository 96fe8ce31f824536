#pragma once
// The work-precision study shared by accuracy_cost (part of every reproduction) and the optional
// rk4_refinement study: which integrator settings to run, on which two scenes, and the error of
// each against the converged event reference. The two targets differ only in their settings.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "common.hpp"

namespace repro {

struct WorkPrecisionSetting {
  std::string name;  // e.g. "rk4 h=1e-07s", "dopri5 tol=1e-08", "exact tol=1e-08"
  sb::Method method;
  double dt_s = 1e-7, tol = 1e-9;
  bool reference = false, reference_check = false;
  sb::Stepper stepper = sb::Stepper::Dopri5;  // the event method's
};

// RK4 at each step (in seconds), the event method's Dormand-Prince stepper at each tolerance
// and its exact stepper at each tolerance (which there only sets when a ringing groove counts as
// settled, and the tolerance of the Dormand-Prince steps of runs longer than exact_max_run);
// with_check adds the reference check (Dormand-Prince at tol 1e-11). The reference
// (Dormand-Prince at tol 1e-12, a method independent of the exact stepper) is always included:
// the errors are measured against it.
std::vector<WorkPrecisionSetting> work_precision_settings(const std::vector<double>& rk4_steps_s,
                                                          const std::vector<double>& dopri5_tols,
                                                          const std::vector<double>& exact_tols, bool with_check);

// Scenes: (A) first macroscopic peak, N = 360, L_x = 7.2 cm, periodic:10,10, 3 seeds, each
// stopped at its first slip, mu(t) every 1e-6 s; (B) full runs of fig1's smooth N = 200 chain.
// Every setting sees the same draws. A setting that cannot run is listed in the document's
// "failed" block by work_precision_finish.
std::vector<LabelledScene> work_precision_plan(const Context& ctx, const std::vector<WorkPrecisionSetting>& settings);

// The document's "work_precision" table (error of each setting against the reference, cost) and
// "failed" block.
void work_precision_finish(const Context& ctx, nlohmann::json& doc);

}  // namespace repro
