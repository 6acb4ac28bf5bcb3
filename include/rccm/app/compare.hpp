// `rccm compare`: the same problem run with several integrators and contact solvers, side
// by side, with the paper's Tables 1-2 layout per case.
#pragma once

#include "rccm/base/config.hpp"
#include "rccm/app/simulation.hpp"
#include "rccm/io/run_record.hpp"

#include <iosfwd>
#include <string>
#include <vector>

namespace rccm {

struct CompareCase {
  std::string label;  // "integrator" or "integrator/solver" as given on the command line
  Config config;
  RunResult result;
  std::string failure;  // why its run failed (the message of `rccm run`); empty: complete
};

/// Runs `cfg` once per integrator name ("arkode", "euler", "rate-independent", "contact-only")
/// and contact solver name ("bipotential", "rccm", "newton"; empty: the config's), Euler with
/// `euler_steps` fixed steps (0: time.steps); alpha = 0 on every interface runs the
/// rate-independent limit once per solver in place of the viscous integrators (contact-only
/// stays). Throws InputError for an unknown name; a
/// case whose run fails keeps its message (`failure`) and the others run.
std::vector<CompareCase> run_comparison(const Config& cfg, const std::vector<std::string>& integrators,
                                        const std::vector<std::string>& solvers, int euler_steps);

/// Prints beta at the watched points at the output times, the largest difference of beta
/// along the interface against the first case, the work of each case, and per integrator
/// the paper's Tables 1-2 (beta and contact iterations and CPU per step, total CPU) of each
/// solver with the ratio of total CPU to the first solver's: of the complete cases, after a
/// line for each failed one.
void print_comparison(std::ostream& out, const std::vector<CompareCase>& cases);

}  // namespace rccm
