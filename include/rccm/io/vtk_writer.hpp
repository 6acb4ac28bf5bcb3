// ParaView output: one .vtu per output time (deformed-mesh data and interface data on the
// nodes, strain and stress on the cells) and a .pvd that ties them to their times.
#pragma once

#include "rccm/model/body_state.hpp"
#include "rccm/model/interface_state.hpp"
#include "rccm/model/model.hpp"

#include <string>
#include <utility>
#include <vector>

namespace rccm {

class VtkWriter {
 public:
  VtkWriter(const Model& model, std::string directory) : model_(model), directory_(std::move(directory)) {}

  /// Writes mesh_<k>.vtu for this state and rewrites results.pvd (complete after each call).
  void write(const InterfaceState& s, const BodyState& b);

  /// Takes up the files of an earlier run that wrote one .vtu at each of `times`: removes
  /// later .vtu files and rewrites results.pvd with these.
  void resume(const std::vector<double>& times);

 private:
  static std::string file_name(std::size_t k);
  void write_collection() const;
  const Model& model_;
  std::string directory_;
  std::vector<std::pair<double, std::string>> files_;
};

}  // namespace rccm
