#include "rccm/time/contact_only_integrator.hpp"

namespace rccm {

void ContactOnlyIntegrator::step(double t_new) {
  Eigen::VectorXd beta = ode_.committed_beta();
  ode_.accept(t_new, beta);
}

}  // namespace rccm
