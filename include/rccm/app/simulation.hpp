// A whole run: the algorithm of docs/MODEL.md s6 from a config to its results.
#pragma once

#include "rccm/base/config.hpp"
#include "rccm/io/recorder.hpp"
#include "rccm/io/run_record.hpp"

namespace rccm {

class Simulation {
 public:
  Simulation(const Config& cfg, RunOptions options = {}) : cfg_(cfg), options_(std::move(options)) {}

  /// Runs the whole problem; throws InputError (bad model: nothing written), SolveError or
  /// Interrupted (the files then hold every accepted step, the last state, the report and a
  /// checkpoint to restart from).
  RunResult run();

 private:
  Config cfg_;
  RunOptions options_;
};

}  // namespace rccm
