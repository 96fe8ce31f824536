#pragma once
// The scalar observables of a repetition, registered in one place.
//
// Each line below gives one: its name (a RunResult member holding the repetition's value, an
// EnsembleResult member holding the statistic over repetitions, and the key of both in the
// results JSON), its unit ("" for a friction coefficient), the FrictionObserver accessor that
// reads it off mu(t), and whether and how the ensemble reports its statistic. The extraction,
// the statistics and the JSON all iterate this list (ensemble.hpp, observables()), so adding an
// observable is one line here once the observer measures it.
//
// A macro rather than a table of member pointers because the members themselves must be
// declared from the list: code that reads r.mu_s by name keeps working, and no list of members
// can fall out of step with the table.
#define SB_OBSERVABLES(X)                            \
  X(mu_s, "", mu_s, Summary::Loading)                \
  X(mu_s_signed, "", mu_s_signed, Summary::Loading)  \
  X(t_peak_s, "s", t_peak, Summary::Always)          \
  X(t_slip_s, "s", t_slip, Summary::None)            \
  X(max_mu, "", max_mu, Summary::None)               \
  X(mu_d, "", mu_d, Summary::Window)                 \
  X(mu_d_signed, "", mu_d_signed, Summary::Window)

namespace sb {

// Whether the results JSON carries an observable's ensemble statistic, and why it may be empty.
enum class Summary {
  None,     // per repetition only (runs[].name)
  Always,   // every repetition has a value
  Loading,  // undefined for a repetition whose loading phase did not end (not_measured "mu_s")
  Window,   // undefined for a repetition without a sample in its mu_d window (not_measured "mu_d")
};

}  // namespace sb
