// ParaView output (README "ParaView"): per frame, the bodies as mesh_<k>.vtu (displacement;
// strain and stress as full symmetric tensors, sigma_zz of plane strain included; von Mises)
// and the interface as its own dataset interface_<k>.vtp (its facets as lines; beta, status,
// the local vectors u, Rbar, Radh, r and the pressures p with named components, and the
// global vectors u_xyz, r_xyz for glyphs); results.pvd and interface.pvd tie the frames to
// their times. A frame is written at t = 0, at each output time and every output.every steps.
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

  /// Writes the frame of (s, b) and rewrites both collections (complete after each call); a
  /// second frame at the time of the last one is not written.
  void write(const InterfaceState& s, const BodyState& b);

  /// Takes up the files of an earlier run: keeps the frames of its results.pvd before time t,
  /// and the one at t if `frame_at_t` (not a stopped run's frame of its last state), removes
  /// the others.
  void resume(double t, bool frame_at_t);

 private:
  void write_bodies(const std::string& file, const BodyState& b) const;
  void write_interface(const std::string& file, const InterfaceState& s, const BodyState& b) const;
  void write_collections() const;
  const Model& model_;
  std::string directory_;
  std::vector<std::pair<double, std::string>> frames_;  // time, frame number as text
};

}  // namespace rccm
