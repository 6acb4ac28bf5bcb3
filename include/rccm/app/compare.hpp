// `rccm compare`: the same problem run with several integrators, side by side.
#pragma once

#include "rccm/base/config.hpp"
#include "rccm/app/simulation.hpp"
#include "rccm/io/run_record.hpp"

#include <iosfwd>
#include <string>
#include <vector>

namespace rccm {

struct CompareCase {
  std::string label;  // integrator name as given on the command line
  Config config;
  RunResult result;
};

/// Runs `cfg` once per integrator name ("arkode", "euler", "rate-independent", "contact-only"),
/// Euler with `euler_steps` fixed steps (0: time.steps). Throws InputError for an unknown name.
std::vector<CompareCase> run_comparison(const Config& cfg, const std::vector<std::string>& integrators,
                                        int euler_steps);

/// Prints beta at the watched points at the output times, the largest difference of beta
/// along the interface against the first case, and the work of each case.
void print_comparison(std::ostream& out, const std::vector<CompareCase>& cases);

}  // namespace rccm
