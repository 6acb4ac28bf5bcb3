// PLACEHOLDER (issue 17): replaced by its implementation.
#pragma once

#include "rccm/contact/bipotential_solver.hpp"

namespace rccm {

class NewtonSolver final : public ContactSolver {
 public:
  explicit NewtonSolver(const SolverParams& params) : fallback_(params) {}
  ContactSolution solve(const ContactProblem& pb, const Eigen::VectorXd& Rbar_start,
                        const Eigen::VectorXd& u_start) override {
    return fallback_.solve(pb, Rbar_start, u_start);
  }
  std::string failure_advice() const override { return fallback_.failure_advice(); }

 private:
  BipotentialSolver fallback_;
};

}  // namespace rccm
