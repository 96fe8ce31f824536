#include "springblock/trajectory_spec.hpp"

#include <functional>
#include <string>
#include <tuple>

#include "springblock/scene.hpp"

namespace sb {

std::optional<TrajectorySpec> trajectory_spec(const Scene& s) {
  if (s.run.stop_after_mu_s) return std::nullopt;
  TrajectorySpec t;
  t.material = s.material;
  t.geometry = s.geometry;
  t.k_int_scale = s.k_int_scale;
  t.friction = s.friction;
  t.materials_hash = materials_hash(resolve_materials(s));
  t.pattern = s.pattern;
  t.seed = s.seed;
  t.reps = s.reps;
  t.method = s.run.method;
  t.dt_s = s.run.dt_s;
  t.tol = s.run.tol;
  t.modal_max_run = s.run.modal_max_run;
  t.modal_max_groove = s.run.modal_max_groove;
  t.stepper = s.run.stepper;
  t.exact_max_run = s.run.exact_max_run;
  t.sample_dt_s = s.run.sample_dt_s;
  return t;
}

namespace {

// A parametric surface by its canonical text (kind and sizes); a mask by its blocks alone (the
// mask member, compared in place: no copy of a long mask per comparison), never its file's name,
// so a file and an inline mask of the same blocks are one surface and an edited file another.
std::string surface_text(const PatternSpec& p) { return p.kind == SurfaceKind::Mask ? "mask" : p.text(); }

// Every member once, in one order, for both comparisons. The surface enters as above, with its
// layout: members of PatternSpec its kind does not use play no part.
auto members(const TrajectorySpec& t) {
  const auto& m = t.material;
  const auto& f = t.friction;
  return std::make_tuple(m.G_Pa, m.E_Pa, m.rho_kg_per_m3, m.P_Pa, m.gamma_per_s, m.v_m_per_s, m.l_y_m,
                         m.l_z_m, t.geometry.N, t.geometry.L_x_m, t.k_int_scale, f.mu_s_mean, f.mu_s_sd,
                         f.mu_d_mean, f.mu_d_sd, f.pair_policy, t.materials_hash, surface_text(t.pattern),
                         std::cref(t.pattern.mask), t.pattern.layout, t.seed, t.reps, t.method, t.dt_s, t.tol,
                         t.modal_max_run, t.modal_max_groove, t.stepper, t.exact_max_run, t.sample_dt_s);
}

}  // namespace

bool operator==(const TrajectorySpec& a, const TrajectorySpec& b) { return members(a) == members(b); }
bool operator!=(const TrajectorySpec& a, const TrajectorySpec& b) { return !(a == b); }
bool operator<(const TrajectorySpec& a, const TrajectorySpec& b) { return members(a) < members(b); }

}  // namespace sb
