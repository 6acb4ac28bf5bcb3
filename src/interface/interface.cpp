#include "rccm/interface/interface.hpp"

#include "rccm/base/errors.hpp"
#include "rccm/la/bisection_order.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <set>
#include <sstream>

namespace rccm {

namespace {

RccmLaw law_of(const InterfaceParams& p) { return {p.Cn, p.Ct, p.w, p.alpha, p.mu}; }

/// A flat foundation's normal this far from a face's inward normal is noted (Interface::notes):
/// a face bonded to a plane lies on it, to the mesh's facets' round-off.
constexpr double max_tilt_degrees = 5.0;

/// The contact pairs of one config interface, built node by node of its boundary set.
class PairBuilder {
 public:
  PairBuilder(const Mesh& mesh, const Config& cfg, const InterfaceParams& p, int law)
      : mesh_(mesh), cfg_(cfg), p_(p), law_(law) {}

  std::vector<ContactPair> build() {
    nodes_ = node_set(p_.boundary, ".boundary");
    facets_ = mesh_.facets_of(p_.boundary);
    const std::vector<double> a = mesh_.tributary_measures(nodes_, facets_), length = mesh_.tributary_lengths(nodes_, facets_);
    outward_ = mesh_.outward_normals(nodes_, facets_);
    const std::vector<char> precrack = precracked();
    if (p_.facing == Facing::Body) match_opposite();
    std::vector<ContactPair> pairs;
    for (std::size_t k = 0; k < nodes_.size(); ++k) {
      if (length[k] <= 0)
        fail(".boundary", "node set '" + p_.boundary + "' must be a chain of the mesh's boundary " +
                              (mesh_.dim == 3 ? "faces" : "edges") + ": node " + std::to_string(nodes_[k]) + " at " +
                              point(mesh_.nodes[nodes_[k]], mesh_.dim) + " is on none of the set's own " +
                              (mesh_.dim == 3 ? "faces" : "edges") + " (" + why_not_on_boundary(nodes_[k]) + ")");
      ContactPair c;
      c.node = nodes_[k];
      c.measure = a[k];
      c.length = length[k];
      c.beta0 = precrack[c.node] ? 0.0 : per_node("beta0", p_.beta0, k);
      c.law = law_;
      face(c, k);
      pairs.push_back(c);
    }
    note_tilt(pairs);
    note_bonded_gap(pairs);
    return pairs;
  }

  /// What the pairs' geometry makes doubtful without being wrong (Interface::notes).
  const std::vector<std::string>& notes() const { return notes_; }
  /// The boundary facets the interface bonds (Mesh::facets_of its boundary).
  const std::vector<std::vector<int>>& facets() const { return facets_; }

 private:
  [[noreturn]] void fail(const std::string& setting, const std::string& what) const {
    throw InputError(cfg_.where(p_.path + setting) + ": " + what);
  }

  const std::vector<int>& node_set(const std::string& name, const char* setting) const {
    const std::vector<int>* set = nullptr;
    try {
      set = &mesh_.node_set(name);
    } catch (const InputError& e) {
      fail(setting, e.what());
    }
    if (set->empty()) fail(setting, "node set '" + name + "' has no nodes");
    return *set;
  }

  /// Per mesh node, whether it starts unbonded: every interface edge at it lies in the
  /// precrack node set (so a precrack curve's end at the crack tip, whose other edge is
  /// bonded, stays bonded).
  std::vector<char> precracked() const {
    std::vector<char> out(mesh_.num_nodes(), 0);
    if (p_.precrack.empty()) return out;
    node_set(p_.precrack, ".precrack");  // refused if unknown or empty
    const std::vector<std::vector<int>> precrack = mesh_.facets_of(p_.precrack);  // as mesh.facets lists them
    const std::set<std::vector<int>> crack(precrack.begin(), precrack.end());
    std::vector<int> edges(mesh_.num_nodes(), 0), cracked(mesh_.num_nodes(), 0);  // facets (2D: edges) at each node
    for (const std::vector<int>& f : facets_)
      for (int n : f) {
        ++edges[n];
        cracked[n] += crack.count(f) > 0;
      }
    bool any = false;
    for (int n : nodes_) {
      out[n] = edges[n] > 0 && cracked[n] == edges[n];
      any = any || out[n];
    }
    if (!any) fail(".precrack", "node set '" + p_.precrack + "' holds no " + (mesh_.dim == 3 ? "face" : "edge") + " of '" +
                                p_.boundary + "'");
    return out;
  }

  /// Value k of a config list of one value or one per contact node.
  double per_node(const char* setting, const std::vector<double>& v, std::size_t k) const {
    if (v.size() != 1 && v.size() != nodes_.size())
      fail(std::string(".") + setting, "give one value or one per contact node (" + std::to_string(nodes_.size()) +
                                           "), got " + std::to_string(v.size()));
    return v.size() == 1 ? v[0] : v[k];
  }

  /// A flat foundation's unit normal (interface.normal).
  Eigen::Vector3d flat_normal() const { return Eigen::Vector3d(p_.normal[0], p_.normal[1], p_.normal[2]).normalized(); }

  /// The frame and gap of node k against what it faces.
  void face(ContactPair& c, std::size_t k) const {
    const Eigen::Vector3d& x = mesh_.nodes[c.node];
    if (p_.facing == Facing::Line) {
      const FlatFoundation line{flat_normal()};
      c.frame = line.frame_at(x);
      c.g0 = per_node("g0", p_.g0, k);
      require_facing(c.frame.n, k, ".normal", "the foundation normal", "give the normal from the foundation into the body");
    } else if (p_.facing == Facing::Circle) {
      const CircleFoundation circle{Eigen::Vector3d(p_.centre[0], p_.centre[1], p_.centre[2]), p_.radius, p_.inside,
                                    Eigen::Vector3d(p_.axis[0], p_.axis[1], p_.axis[2])};
      if (circle.radial(x).norm() < 1e-12 * p_.radius)
        fail(".circle", "contact node " + std::to_string(k) + " lies at the centre" + (circle.axis.isZero() ? "" : " (on the axis)"));
      c.frame = circle.frame_at(x);
      c.g0 = circle.gap_at(x);
      if (c.g0 < -1e-6 * p_.radius) {
        std::ostringstream m;
        m << "contact node " << k << " at " << point(x, mesh_.dim) << " lies " << -c.g0 << " mm inside the rigid part (the circle's "
          << (p_.inside ? "outside" : "inside") << "); the boundary must lie on the " << (p_.inside ? "inner" : "outer")
          << " side of the circle";
        fail(".circle", m.str());
      }
      c.g0 = std::max(c.g0, 0.0);  // a node on the circle to round-off
      require_facing(c.frame.n, k, ".circle.side", "the circle's normal",
                     "the circle does not face the boundary there: check interface.circle.side (\"inside\": the body "
                     "fills a circular hole; \"outside\": the body lies outside the circle), or, where the boundary "
                     "reaches beyond what the circle faces (a flat face under a cylinder), give interface.boundary as "
                     "the node set of the part the circle can touch");
    } else {
      c.opposite = opposite_[k];
      // The averaged normal: B's outward and A's inward, from B into A.
      const Eigen::Vector3d n = outward_opposite_[k] - outward_[k];
      if (n.norm() < 1e-6 || outward_opposite_[k].dot(outward_[k]) > -0.5)
        fail(".opposite", "at contact node " + std::to_string(k) + " " + point(x, mesh_.dim) + " the boundaries of '" + p_.boundary +
                              "' and '" + p_.opposite + "' do not face each other (their outward normals are not opposite)");
      c.frame = plane_frame(n.normalized());
      c.g0 = c.frame.n.dot(x - mesh_.nodes[c.opposite]);
      if (c.g0 < -apart_) {  // the bodies overlap there: contact would push them apart at once
        std::ostringstream m;
        m << "at contact node " << k << " " << point(x, mesh_.dim) << " the bodies overlap by " << -c.g0 << " mm ('"
          << p_.boundary << "' lies inside '" << p_.opposite << "'), which " << p_.path
          << ".tolerance let through: the matched nodes of two bodies lie at the same place; correct the geometry";
        fail(".opposite", m.str());
      }
    }
  }

  /// A flat foundation tilted against the face it holds bonded: its normal more than
  /// max_tilt_degrees from the boundary's inward normal at a pair with beta0 > 0 (a mesh
  /// turned without its normal, say; a curved body in unbonded contact is no concern).
  void note_tilt(const std::vector<ContactPair>& pairs) {
    if (p_.facing != Facing::Line) return;
    const Eigen::Vector3d n = flat_normal();
    double worst = 0;
    std::size_t at = 0;
    for (std::size_t k = 0; k < nodes_.size(); ++k) {
      if (pairs[k].beta0 <= 0) continue;
      const double degrees = std::acos(std::clamp(-n.dot(outward_[k]), -1.0, 1.0)) * 180 / M_PI;
      if (degrees > worst) worst = degrees, at = k;
    }
    if (worst <= max_tilt_degrees) return;
    std::ostringstream m;
    m << cfg_.where(p_.path + ".normal") << ": " << point(n, mesh_.dim) << " is " << std::setprecision(3) << worst
      << " degrees from the boundary's inward normal at mesh node " << nodes_[at] << " " << point(mesh_.nodes[nodes_[at]], mesh_.dim)
      << ": the foundation is not parallel to the face there (a turned mesh turns its foundation's normal only "
         "when the config does)";
    notes_.push_back(m.str());
  }

  /// Adhesion across an initial gap: a pair bonded (beta0 > 0) with g0 > 0 has its springs act
  /// across the gap (docs/MODEL.md s2: a bonded interface has g0 = 0).
  void note_bonded_gap(const std::vector<ContactPair>& pairs) {
    // Matched nodes of two bodies coincide to round-off: a gap beyond it passed the matching
    // only by its tolerance (interface.tolerance raised, as its message suggests).
    const double tolerance = p_.facing == Facing::Circle ? 1e-6 * p_.radius
                             : p_.facing == Facing::Body ? apart_
                                                         : 0.0;
    std::size_t count = 0, at = 0;
    for (std::size_t k = 0; k < pairs.size(); ++k)
      if (pairs[k].beta0 > 0 && pairs[k].g0 > tolerance) {
        if (count == 0 || pairs[k].g0 > pairs[at].g0) at = k;
        ++count;
      }
    if (count == 0) return;
    std::ostringstream m;
    m << cfg_.where(p_.path) << ": " << count << " contact node(s) start bonded across a gap, up to g0 = " << pairs[at].g0
      << " mm at mesh node " << pairs[at].node << " " << point(mesh_.nodes[pairs[at].node], mesh_.dim) << " (beta0 = " << pairs[at].beta0
      << "): their adhesive springs act across it as if the faces touched; a bonded interface touches "
      << (p_.facing == Facing::Body ? "the other body (its nodes on the other's)" : "its foundation (g0 = 0)")
      << ", an open one starts with beta0 = 0 (precrack)";
    notes_.push_back(m.str());
  }

  /// A foundation's normal points into the body: against the boundary's outward normal
  /// (within 60 degrees), not out of the body nor along the interface. `remedy`: what to change.
  void require_facing(const Eigen::Vector3d& n, std::size_t k, const char* setting, const char* what,
                      const char* remedy) const {
    const double cosine = -n.dot(outward_[k]);
    if (cosine >= 0.5) return;
    std::ostringstream m;
    m << what << " " << point(n, mesh_.dim) << " does not point into the body at contact node " << k << " "
      << point(mesh_.nodes[nodes_[k]], mesh_.dim) << ", where the boundary's inward normal is "
      << point(Eigen::Vector3d::Zero() - outward_[k], mesh_.dim) << " (" << std::setprecision(3)
      << std::acos(std::clamp(cosine, -1.0, 1.0)) * 180 / M_PI << " degrees apart, at most 60); " << remedy;
    fail(setting, m.str());
  }

  /// The bodies whose cells hold `node`, in the order of the cells.
  std::vector<int> bodies_at(int node) const {
    std::vector<int> bodies;
    for (std::size_t c = 0; c < mesh_.cells.size(); ++c)
      if (std::find(mesh_.cells[c].begin(), mesh_.cells[c].end(), node) != mesh_.cells[c].end() &&
          std::find(bodies.begin(), bodies.end(), mesh_.cell_body[c]) == bodies.end())
        bodies.push_back(mesh_.cell_body[c]);
    return bodies;
  }

  /// Why a node of the boundary set lies on none of its facets: the bodies whose cells share it
  /// are fused there, or the set is a point or lies inside a body.
  std::string why_not_on_boundary(int node) const {
    const std::vector<int> bodies = bodies_at(node);
    if (bodies.size() > 1)
      return "bodies '" + mesh_.body_names[bodies[0]] + "' and '" + mesh_.body_names[bodies[1]] +
             "' share this node: their meshes are fused there (gmsh's BooleanFragments, or one surface shared by "
             "both), so the face between them is inside the mesh; an interface between two bodies needs each its "
             "own nodes: leave the solids unfused, give each body its own " +
             (mesh_.dim == 3 ? "surface" : "curve") + " and set interface.opposite";
    return std::string("a lone point, or a ") + (mesh_.dim == 3 ? "surface" : "curve") +
           " inside a body such as gmsh's Line In Surface, makes none: an interface lies on a body's boundary";
  }

  /// The shortest edge of the boundary's facets, mm.
  double shortest_edge() const {
    double shortest = std::numeric_limits<double>::infinity();
    for (const std::vector<int>& f : facets_)
      for (std::size_t a = 0; a < f.size(); ++a)
        shortest = std::min(shortest, (mesh_.nodes[f[a]] - mesh_.nodes[f[(a + 1) % f.size()]]).norm());
    return shortest;
  }

  /// Pairs each node of the boundary with the node of the opposite set at the same place
  /// (conforming meshes), both ways one to one.
  void match_opposite() {
    const std::vector<int>& other = node_set(p_.opposite, ".opposite");
    double tolerance = p_.tolerance;
    const double shortest = shortest_edge();
    apart_ = 1e-6 * shortest;
    if (tolerance == 0) tolerance = 1e-3 * shortest;
    std::vector<char> in_other(mesh_.num_nodes(), 0);
    for (int n : other) in_other[n] = 1;
    for (int n : nodes_) {
      if (!in_other[n]) continue;
      const std::vector<int> bodies = bodies_at(n);
      if (bodies.size() == 1)  // two sets of one body that meet (its bottom and its end)
        fail(".opposite", "'" + p_.boundary + "' and '" + p_.opposite + "' are both on body '" +
                              mesh_.body_names[bodies[0]] + "' (they meet at node " + point(mesh_.nodes[n], mesh_.dim) +
                              "): interface.opposite names the set of the other body that faces '" + p_.boundary + "'");
      fail(".opposite", "node " + point(mesh_.nodes[n], mesh_.dim) + " belongs to both '" + p_.boundary + "' and '" +
                              p_.opposite + "': the bodies share their nodes there; give each body its own curve (3D: "
                              "surface) along the interface (its own points), meshed alike");
    }
    // Counted before matching: no tolerance pairs sets of different sizes one to one.
    if (other.size() != nodes_.size())
      fail(".opposite", "the meshes of '" + p_.boundary + "' and '" + p_.opposite + "' do not match: '" + p_.opposite +
                            "' has " + std::to_string(other.size()) + " nodes, '" + p_.boundary + "' " +
                            std::to_string(nodes_.size()) + "; the meshes along the interface must match node for node "
                            "(mesh both curves (surfaces) alike: Transfinite Curve, Transfinite Surface)");
    std::vector<int> taken(mesh_.num_nodes(), -1);
    double worst = 0;
    int worst_k = -1;
    for (std::size_t k = 0; k < nodes_.size(); ++k) {
      const Eigen::Vector3d& x = mesh_.nodes[nodes_[k]];
      int best = -1;
      double d_best = std::numeric_limits<double>::infinity();
      for (int n : other) {
        const double d = (mesh_.nodes[n] - x).norm();
        if (d < d_best) d_best = d, best = n;
      }
      if (d_best > worst) worst = d_best, worst_k = static_cast<int>(k);
      if (taken[best] >= 0 && d_best <= tolerance)
        fail(".opposite", "nodes " + point(x, mesh_.dim) + " and " + point(mesh_.nodes[nodes_[taken[best]]], mesh_.dim) + " of '" + p_.boundary +
                              "' both face node " + point(mesh_.nodes[best], mesh_.dim) + " of '" + p_.opposite + "'");
      taken[best] = static_cast<int>(k);
      opposite_.push_back(best);
    }
    if (worst > tolerance) {
      std::ostringstream m;
      m << "the meshes of '" << p_.boundary << "' and '" << p_.opposite << "' do not match: node "
        << point(mesh_.nodes[nodes_[worst_k]], mesh_.dim) << " of '" << p_.boundary << "' is " << worst << " mm from the nearest node of '"
        << p_.opposite << "' (tolerance " << tolerance << " mm); mesh both curves (surfaces) alike (Transfinite Curve, Transfinite Surface), or raise "
        << p_.path << ".tolerance";
      fail(".opposite", m.str());
    }
    const std::vector<Eigen::Vector3d> outward_b = mesh_.outward_normals(other, mesh_.facets_of(p_.opposite));
    std::vector<Eigen::Vector3d> by_node(mesh_.num_nodes(), Eigen::Vector3d::Zero());
    for (std::size_t j = 0; j < other.size(); ++j) by_node[other[j]] = outward_b[j];
    for (int n : opposite_) outward_opposite_.push_back(by_node[n]);
  }

  const Mesh& mesh_;
  const Config& cfg_;
  const InterfaceParams& p_;
  const int law_;
  std::vector<int> nodes_, opposite_;
  std::vector<std::vector<int>> facets_;
  double apart_ = 0;  // body-body: matched nodes further apart than this (1e-6 of the shortest edge) are not at one place
  std::vector<Eigen::Vector3d> outward_, outward_opposite_;
  std::vector<std::string> notes_;
};

/// A 3D interface's pairs in recursive bisection order of their nodes (la/bisection_order.hpp:
/// the compressed W0 of a surface keeps lower ranks); a line (2D) keeps its order.
std::vector<ContactPair> in_space_order(std::vector<ContactPair> pairs, const Mesh& mesh) {
  if (mesh.dim != 3) return pairs;
  std::vector<Eigen::Vector3d> x;
  for (const ContactPair& c : pairs) x.push_back(mesh.nodes[c.node]);
  std::vector<ContactPair> ordered;
  for (int i : bisection_order(x)) ordered.push_back(pairs[i]);
  return ordered;
}

}  // namespace

Interface make_interface(const Mesh& mesh, const Config& cfg) {
  Interface I;
  I.layout.dim = mesh.dim;
  std::vector<int> owner(mesh.num_nodes(), -1);  // the interface of each contact node
  for (const InterfaceParams& p : cfg.interfaces) {
    const int law = static_cast<int>(I.laws.size());
    PairBuilder builder(mesh, cfg, p, law);
    for (const ContactPair& c : in_space_order(builder.build(), mesh)) {
      for (int node : {c.node, c.opposite})
        if (node >= 0 && owner[node] >= 0)
          throw InputError(cfg.where(p.path + ".boundary") + ": node " + point(mesh.nodes[node], mesh.dim) + " is on " +
                           cfg.interfaces[owner[node]].path + " already: a node belongs to one interface (a precrack "
                           "is a node set of the interface's boundary: " + p.path + ".precrack)");
      for (int node : {c.node, c.opposite})
        if (node >= 0) owner[node] = law;
      I.pairs.push_back(c);
    }
    I.laws.push_back(law_of(p));
    I.facets.insert(I.facets.end(), builder.facets().begin(), builder.facets().end());
    I.notes.insert(I.notes.end(), builder.notes().begin(), builder.notes().end());
  }
  const int dim = I.layout.dim;
  std::vector<Eigen::Triplet<double>> trip;
  for (int i = 0; i < I.size(); ++i) {
    const ContactPair& c = I.pairs[i];
    for (int k = 0; k < dim; ++k)
      for (int x = 0; x < dim; ++x) {
        const double axis = c.frame.axis(k, dim)[x];
        trip.emplace_back(I.layout.offset(i) + k, mesh.dof(c.node, x), axis);
        if (c.opposite >= 0) trip.emplace_back(I.layout.offset(i) + k, mesh.dof(c.opposite, x), -axis);
      }
  }
  I.P.resize(dim * I.size(), mesh.num_dofs());
  I.P.setFromTriplets(trip.begin(), trip.end());
  return I;
}

Eigen::VectorXd Interface::spring_stiffness() const {
  Eigen::VectorXd D(layout.offset(size()));
  for (int i = 0; i < size(); ++i) layout.local(D, i) = law(i).spring(pairs[i].measure, layout.dim);
  return D;
}

SparseMatrix Interface::springs(const Eigen::VectorXd& weight_t, const Eigen::VectorXd& weight_n) const {
  Eigen::VectorXd d(layout.offset(size()));
  for (int i = 0; i < size(); ++i) {
    const double a = pairs[i].measure;
    layout.tangential(d, i).setConstant(a * law(i).Ct * weight_t[i]);
    d[layout.normal(i)] = a * law(i).Cn * weight_n[i];
  }
  return SparseMatrix(P.transpose() * d.asDiagonal() * P);
}

}  // namespace rccm
