#include "rccm/contact/contact_solver.hpp"

#include "rccm/contact/bipotential_solver.hpp"
#include "rccm/contact/newton_solver.hpp"
#include "rccm/contact/rccm_solver.hpp"

namespace rccm {

std::unique_ptr<ContactSolver> make_contact_solver(const SolverParams& params) {
  switch (params.method) {
    case ContactMethod::Rccm: return std::make_unique<RccmSolver>(params);
    case ContactMethod::Newton: return std::make_unique<NewtonSolver>(params);
    case ContactMethod::Bipotential: break;
  }
  return std::make_unique<BipotentialSolver>(params);
}

const char* contact_method_name(ContactMethod m) {
  switch (m) {
    case ContactMethod::Rccm: return "rccm";
    case ContactMethod::Newton: return "newton";
    case ContactMethod::Bipotential: break;
  }
  return "bipotential";
}

}  // namespace rccm
