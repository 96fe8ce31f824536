#include "springblock/integrate/methods/event_driven.hpp"
#include "springblock/integrate/integrator.hpp"
#include "springblock/integrate/methods/rk4.hpp"
#include "springblock/errors.hpp"

namespace sb {

std::unique_ptr<Integrator> make_integrator(const RunControl& rc) {
  switch (rc.method) {
    case Method::RK4:
      return std::make_unique<Rk4>(rc.dt_s);
    case Method::Event:
    {
      auto e = std::make_unique<EventDriven>(rc.tol);
      e->set_modal_max_run(rc.modal_max_run);
      e->set_modal_max_groove(rc.modal_max_groove);
      e->set_exact_stepper(rc.stepper == Stepper::Exact, rc.exact_max_run);
      return e;
    }
  }
  throw InputError("method", "unknown integration method");
}

}  // namespace sb
