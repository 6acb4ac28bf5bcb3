// A whole run: the algorithm of docs/MODEL.md s6 from a config to its results.
#pragma once

#include "rccm/base/config.hpp"
#include "rccm/fem/mesh.hpp"
#include "rccm/io/recorder.hpp"
#include "rccm/io/run_record.hpp"

#include <optional>

namespace rccm {

class Simulation {
 public:
  /// `mesh`: the mesh of cfg.mesh when it was made beforehand (a sweep reads its cases'
  /// gmsh files before it runs them, a geometry they share once); else the run makes it.
  Simulation(const Config& cfg, RunOptions options = {}, std::optional<Mesh> mesh = std::nullopt)
      : cfg_(cfg), options_(std::move(options)), mesh_(std::move(mesh)) {}

  /// Runs the whole problem; throws InputError (bad model: nothing written), SolveError or
  /// Interrupted (the files then hold every accepted step, the last state, the report and a
  /// checkpoint to restart from).
  RunResult run();

 private:
  Config cfg_;
  RunOptions options_;
  std::optional<Mesh> mesh_;
};

}  // namespace rccm
