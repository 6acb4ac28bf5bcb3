// The interface Gamma_c as a list of contact pairs (docs/MODEL.md s2): a node of a body
// facing a rigid foundation or the matching node of another body, with its local frame,
// initial gap, tributary measure and RCCM law; and the operator P from the global
// displacement to the pairs' local relative displacements.
#pragma once

#include "rccm/base/config.hpp"
#include "rccm/fem/mesh.hpp"
#include "rccm/interface/foundation.hpp"
#include "rccm/interface/layout.hpp"
#include "rccm/interface/rccm_law.hpp"
#include "rccm/la/sparse.hpp"

#include <Eigen/Core>

#include <string>
#include <vector>

namespace rccm {

struct ContactPair {
  int node = -1;       // mesh node of the body the normal points into
  int opposite = -1;   // mesh node it faces on another body, or -1: a rigid foundation
  double measure = 0;  // tributary measure a_i (2D: length, mm; axisymmetric: the ring's area, mm^2)
  double length = 0;   // tributary length in the plane of the mesh, mm
  double g0 = 0;       // initial gap, mm
  double beta0 = 1;    // initial adhesion intensity
  Frame frame;
  int law = 0;         // index in Interface::laws: the config interface it belongs to
};

struct Interface {
  Layout layout;
  std::vector<ContactPair> pairs;
  std::vector<RccmLaw> laws;  // one per config interface
  std::vector<std::vector<int>> facets;  // the boundary facets bonded (mesh nodes; 2D: edges, 3D: triangles and quads)
  SparseMatrix P;             // rows layout.offset(i) + k: axis k of pair i applied to u_node - u_opposite
  std::vector<std::string> notes;  // doubtful geometry, reported as the run's warnings: a flat foundation
                                   // tilted against its face, pairs bonded across a gap

  int size() const { return static_cast<int>(pairs.size()); }
  const RccmLaw& law(int i) const { return laws[pairs[i].law]; }

  /// The adhesive springs at beta = 1 per local component, D1 = a_i (Ct, .., Cn), N/mm (docs/MODEL.md s4).
  Eigen::VectorXd spring_stiffness() const;

  /// P^T diag(a_i Ct weight_t,i, .., a_i Cn weight_n,i) P: the springs as a global matrix with
  /// per-pair weights (beta^2: the adhesive springs at beta; K0's springs: Model::condense).
  SparseMatrix springs(const Eigen::VectorXd& weight_t, const Eigen::VectorXd& weight_n) const;
};

/// The contact pairs of every interface of the config on `mesh`; throws InputError
/// "file:line: interface.boundary: ..." when a node set is unknown, empty or not a chain of
/// boundary edges, a per-node list has the wrong length, a foundation does not face the
/// body, or two node sets of a body-body interface do not match (naming the worst node).
Interface make_interface(const Mesh& mesh, const Config& cfg);

}  // namespace rccm
