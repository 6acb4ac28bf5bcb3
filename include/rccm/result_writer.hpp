// The result files of a run, in output.directory (README "Result files"):
//   interface_t<time>.csv  interface fields at each output time
//   history.csv            watched points and solver work at every accepted step
//   curves.csv             each load's value and resultant force, and the energy terms
//   mesh_<k>.vtu, results.pvd   ParaView
// Every file is complete (flushed) after each accepted step or output time.
#pragma once

#include "rccm/beta_ode.hpp"
#include "rccm/body_state.hpp"
#include "rccm/energy_balance.hpp"
#include "rccm/model.hpp"
#include "rccm/vtk_writer.hpp"

#include <fstream>
#include <string>

namespace rccm {

class ResultWriter {
 public:
  /// Creates the directory (InputError if it cannot) and writes the CSV headers.
  ResultWriter(const Model& model, const std::string& directory);

  void step(const AcceptedStep& a, const BodyState& b, const EnergyTerms& e);
  void output(const InterfaceState& s, const BodyState& b);
  const std::string& directory() const { return directory_; }

 private:
  const Model& model_;
  std::string directory_;
  std::ofstream history_, curves_;
  VtkWriter vtk_;
};

}  // namespace rccm
