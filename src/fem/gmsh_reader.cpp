#include "rccm/fem/gmsh_reader.hpp"

#include "rccm/base/errors.hpp"
#include "rccm/base/memory.hpp"
#include "rccm/base/suggest.hpp"
#include "rccm/fem/mesh_bytes.hpp"

#include <Eigen/Geometry>
#include <gmsh.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <map>
#include <set>
#include <sstream>
#include <sys/resource.h>
#include <unistd.h>

namespace rccm {

namespace {

/// gmsh for one read, in rccm-gmsh: initialized without the user's gmshrc, silent, its
/// messages collected; never finalized (the process ends: freeing a large model would only
/// delay the answer).
void start_gmsh() {
  gmsh::initialize(0, nullptr, false);
  gmsh::option::setNumber("General.Terminal", 0);
  gmsh::logger::start();
}


/// The format version a .msh file's header states ("$MeshFormat" then "4.1 0 8"), "" if none.
std::string msh_version(const std::string& file) {
  std::ifstream in(file);
  std::string line, version;
  while (std::getline(in, line) && line.rfind("$MeshFormat", 0) != 0) {
    if (!line.empty() && line != "\r") return {};  // no header first
  }
  in >> version;
  return version;
}

/// After gmsh's message about a file it could not read: where it is a .msh whose header states
/// a format rccm does not read (a header edited by hand, a file of another program), that format.
std::string format_note(const std::string& file) {
  if (std::filesystem::path(file).extension() != ".msh") return {};
  const std::string version = msh_version(file);
  if (version == "4.1" || version.rfind("2.", 0) == 0) return {};
  return " (its header states " + (version.empty() ? std::string("no $MeshFormat") : "MSH " + version) +
         "; rccm reads MSH 2.2 and 4.1: gmsh writes 4.1 with `-format msh41`, e.g. `gmsh OLD.msh -save -format msh41 -o NEW.msh` for a file it reads)";
}

/// gmsh's last error message, or the exception's text, about `file`, with format_note(file).
std::string last_gmsh_error(const std::string& fallback, const std::string& file) {
  std::string e;
  gmsh::logger::getLastError(e);
  return (e.empty() ? fallback : e) + format_note(file);
}

/// The process's address space limited to what it has and what the machine can give: a mesh
/// larger than the memory ends in bad_alloc at once, not in minutes of swapping.
void limit_memory() {
  long pages = 0;
  if (std::FILE* statm = std::fopen("/proc/self/statm", "r")) {
    if (std::fscanf(statm, "%ld", &pages) != 1) pages = 0;
    std::fclose(statm);
  }
  const double bytes = double(pages) * double(::sysconf(_SC_PAGESIZE)) + available_memory();
  if (bytes < 1e18) {
    const rlimit limit{rlim_t(bytes), rlim_t(bytes)};
    ::setrlimit(RLIMIT_AS, &limit);
  }
}

const char* group_kind(int dim) { return dim == 0 ? "point" : dim == 1 ? "curve" : dim == 2 ? "surface" : "volume"; }

/// "Physical Point", "Physical Curve", ... as a .geo file writes it.
std::string physical(int dim) {
  std::string k = group_kind(dim);
  k[0] = static_cast<char>(std::toupper(k[0]));
  return "Physical " + k;
}

const char* const no_physical_volume =
    "the file has volumes but no Physical Volume: name each body, e.g. Physical Volume(\"plate\") = {1}; "
    "(a 2D mesh lies in the plane z = 0, its bodies Physical Surfaces)";

/// 3 when the open model has a Physical Volume (a solid), 2 when it has no volume at all, 0
/// when it has volumes but none is a Physical Volume (no_physical_volume).
int top_dimension() {
  gmsh::vectorpair groups, volumes;
  gmsh::model::getPhysicalGroups(groups, 3);
  if (!groups.empty()) return 3;
  gmsh::model::getEntities(volumes, 3);
  return volumes.empty() ? 2 : 0;
}

/// Opens `p.file` with the .geo's parameters set (throws gmsh's errors).
void open_with_parameters(const MeshParams& p) {
  for (const auto& [name, value] : p.parameters) gmsh::onelab::setNumber(name, {value});
  gmsh::open(p.file);
}

/// The name of a physical group; an unnamed group is "<kind> <tag>".
std::string group_name(int dim, int tag) {
  std::string name;
  gmsh::model::getPhysicalName(dim, tag, name);
  return name.empty() ? std::string(group_kind(dim)) + " " + std::to_string(tag) : name;
}

class Reader {
 public:
  Reader(const MeshParams& p, const std::string& where) : p_(p), where_(where + ": " + p.file + ": ") {}

  Mesh read() {
    open();
    require_fits(double(node_count()), "the mesh");
    for (int k = 0; k < p_.refine; ++k) gmsh::model::mesh::refine();
    m_.source = p_.file;
    read_bodies();
    read_node_sets();
    find_facets();
    return std::move(m_);
  }

 private:
  [[noreturn]] void fail(const std::string& what) const { throw InputError(where_ + what); }

  void open() {
    const std::string ext = std::filesystem::path(p_.file).extension().string();
    if (ext != ".msh" && ext != ".geo") fail("a mesh file is a gmsh .msh or .geo file");
    if (!std::ifstream(p_.file)) fail("cannot read the file (does it exist?)");
    if (ext == ".msh" && !p_.parameters.empty()) fail("mesh.parameters set the DefineConstant values of a .geo file, not of a .msh");
    try {
      if (!p_.parameters.empty()) check_parameters();
      open_with_parameters(p_);
      m_.dim = top_dimension();
      if (m_.dim == 0) fail(no_physical_volume);
      std::vector<int> types;
      gmsh::model::mesh::getElementTypes(types, m_.dim);
      if (types.empty()) {
        // Sizes checked and the curves meshed first: gmsh throws a bad size from its threads
        // (where it cannot be caught), and a tiny one would fill the memory for minutes.
        check_sizes();
        gmsh::model::mesh::generate(1);
        require_fits(nodes_from_curves(), "meshing it");
        gmsh::model::mesh::generate(m_.dim);
      }
    } catch (const std::string& e) {
      fail(last_gmsh_error(e, p_.file));
    } catch (const InputError&) {
      throw;  // ours, already placed
    } catch (const std::exception& e) {
      fail(last_gmsh_error(e.what(), p_.file));
    }
  }

  /// gmsh's global mesh sizes, as the file set them (a parameter of 0 or below there).
  void check_sizes() const {
    for (const char* name : {"Mesh.MeshSizeMax", "Mesh.MeshSizeFactor", "Mesh.MeshSizeMin"}) {
      double v = 0;
      gmsh::option::getNumber(name, v);
      const bool at_least_zero = std::string(name) == "Mesh.MeshSizeMin";
      if (!std::isfinite(v) || v < 0 || (v == 0 && !at_least_zero)) {
        std::ostringstream m;
        m << name << " = " << v << ": a mesh size must be " << (at_least_zero ? ">= 0" : "> 0")
          << " (check the value of the file's parameters)";
        fail(m.str());
      }
    }
  }

  /// Nodes of the mesh to come, from its meshed curves. 2D: per surface, its bounding box
  /// filled with cells as long as its curves' median cell, or, for a surface of four curves
  /// whose opposite curves have as many cells (as a Transfinite Surface's), the grid they make
  /// when it has fewer: graded structured meshes (fine along an interface, coarse across) are
  /// not taken for uniformly fine ones. 3D: the model's box, from all curves' median cell.
  double nodes_from_curves() const {
    if (m_.dim == 3) return fill(-1, -1, cell_lengths(-1));
    gmsh::vectorpair surfaces;
    gmsh::model::getEntities(surfaces, 2);
    double nodes = 0;
    for (const auto& [dim, tag] : surfaces) {
      gmsh::vectorpair curves;
      gmsh::model::getBoundary({{dim, tag}}, curves, false, false, false);
      std::vector<double> lengths;
      std::vector<double> counts;
      for (const auto& curve : curves) {
        const std::vector<double> cells = cell_lengths(curve.second);
        lengths.insert(lengths.end(), cells.begin(), cells.end());
        counts.push_back(double(cells.size()));
      }
      const double filled = fill(dim, tag, lengths);
      const bool grid = counts.size() == 4 && counts[0] == counts[2] && counts[1] == counts[3];
      nodes += grid ? std::min(filled, (counts[0] + 1) * (counts[1] + 1)) : filled;  // (Transfinite) grid
    }
    return nodes;
  }

  /// The lengths of the cells (2-node lines) of meshed curve `tag` (-1: of every curve).
  std::vector<double> cell_lengths(int tag) const {
    std::vector<double> lengths;
    std::vector<int> types;
    std::vector<std::vector<std::size_t>> cells, nodes;
    gmsh::model::mesh::getElements(types, cells, nodes, 1, tag);
    for (std::size_t t = 0; t < types.size(); ++t) {
      if (types[t] != 1) continue;  // 2-node lines
      for (std::size_t c = 0; c < cells[t].size(); ++c) {
        std::vector<double> a, b, param;
        gmsh::model::mesh::getNode(nodes[t][2 * c], a, param);
        gmsh::model::mesh::getNode(nodes[t][2 * c + 1], b, param);
        lengths.push_back(std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]));
      }
    }
    return lengths;
  }

  /// Nodes of entity (`dim`, `tag`)'s bounding box (-1, -1: the model's) meshed uniformly
  /// with cells of the median of `lengths`: about 1.15 / h^2 per unit area (triangles),
  /// 1.4 / h^3 per unit volume (tetrahedra).
  double fill(int dim, int tag, std::vector<double> lengths) const {
    if (lengths.empty()) return 0;
    std::nth_element(lengths.begin(), lengths.begin() + lengths.size() / 2, lengths.end());
    const double h = std::max(lengths[lengths.size() / 2], 1e-300);
    double x0, y0, z0, x1, y1, z1;
    gmsh::model::getBoundingBox(dim, tag, x0, y0, z0, x1, y1, z1);
    const double extent[3] = {std::max(x1 - x0, h), std::max(y1 - y0, h), std::max(z1 - z0, h)};
    return m_.dim == 2 ? 1.15 * extent[0] * extent[1] / (h * h) : 1.4 * extent[0] * extent[1] * extent[2] / (h * h * h);
  }

  double node_count() const {
    std::vector<std::size_t> tags;
    std::vector<double> x, param;
    gmsh::model::mesh::getNodes(tags, x, param, -1, -1, false, false);
    return double(tags.size());
  }

  /// Refuses `what` (`nodes` before refinement) when the body's assembly would not fit in
  /// the memory: each of mesh.refine's splits multiplies the nodes by 4 (2D) or 8 (3D).
  void require_fits(double nodes, const std::string& what) const {
    const double unknowns = m_.dim * nodes * std::pow(m_.dim == 2 ? 4.0 : 8.0, p_.refine);
    std::ostringstream m;
    m << what << (p_.refine ? " with mesh.refine = " + std::to_string(p_.refine) : std::string()) << " (about "
      << std::setprecision(3) << unknowns << " unknowns)";
    const std::string shortfall = memory_shortfall(assembly_bytes(unknowns), m.str());
    if (!shortfall.empty()) fail(shortfall + "; use coarser mesh sizes (the file's parameters) or fewer refinements");
  }

  /// Every parameter is a DefineConstant of the .geo (a misspelt one would be ignored).
  void check_parameters() {
    gmsh::open(p_.file);
    std::vector<std::string> names;
    gmsh::onelab::getNames(names);
    // The file's parameters: gmsh's own ONELAB entries ("Gmsh/Model dimension", "ONELAB/Button") are none.
    const auto gmsh_own = [](const std::string& n) { return n.rfind("Gmsh/", 0) == 0 || n.rfind("ONELAB/", 0) == 0; };
    names.erase(std::remove_if(names.begin(), names.end(), gmsh_own), names.end());
    for (const auto& [name, value] : p_.parameters)
      if (std::find(names.begin(), names.end(), name) == names.end())
        fail("mesh.parameters." + name + ": the file defines no such parameter (DefineConstant[ " + name +
             " = {value, Name \"" + name + "\"} ])" + suggestion(name, names));
    gmsh::clear();
  }

  /// Index of gmsh node `tag` in m_.nodes, added on first use.
  int node(std::size_t tag) {
    const auto it = index_.find(tag);
    if (it != index_.end()) return it->second;
    std::vector<double> x, param;
    gmsh::model::mesh::getNode(tag, x, param);
    if (!(std::abs(x[0]) < mesh_reach && std::abs(x[1]) < mesh_reach && std::abs(x[2]) < mesh_reach)) {  // NaN too
      std::ostringstream m;
      m << "node " << tag << " lies at (" << x[0] << ", " << x[1] << ", " << x[2]
        << "): the mesh must lie within 1e15 mm of 0";
      fail(m.str());
    }
    if (m_.dim == 2 && std::abs(x[2]) > 1e-12 * (1 + std::abs(x[0]) + std::abs(x[1]))) {
      std::ostringstream m;
      m << "node " << tag << " lies at z = " << x[2] << ": a 2D mesh lies in the plane z = 0";
      fail(m.str());
    }
    m_.nodes.emplace_back(x[0], x[1], m_.dim == 3 ? x[2] : 0.0);
    return index_[tag] = m_.num_nodes() - 1;
  }

  /// Each Physical Surface (2D) or Physical Volume (3D) is a body.
  void read_bodies() {
    const std::string kind = physical(m_.dim);
    gmsh::vectorpair groups;
    gmsh::model::getPhysicalGroups(groups, m_.dim);
    if (groups.empty()) fail("no Physical Surface: name each body, e.g. Physical Surface(\"arm\") = {1};");
    std::map<int, std::string> owner;  // entity -> its body
    for (const auto& [dim, tag] : groups) {
      const std::string name = group_name(dim, tag);
      const int body = static_cast<int>(m_.body_names.size());
      m_.body_names.push_back(name);
      std::vector<int> entities;
      gmsh::model::getEntitiesForPhysicalGroup(dim, tag, entities);
      std::set<int> nodes_of_body;
      for (int e : entities) {
        if (owner.count(e))
          fail(std::string(group_kind(dim)) + " " + std::to_string(e) + " is in two " + kind + "s, '" + owner[e] + "' and '" +
               name + "': a cell belongs to one body");
        owner[e] = name;
        std::vector<int> types;
        std::vector<std::vector<std::size_t>> cells, nodes;
        gmsh::model::mesh::getElements(types, cells, nodes, dim, e);
        for (std::size_t t = 0; t < types.size(); ++t) {
          const int k = element_nodes(types[t], name);
          for (std::size_t c = 0; c < cells[t].size(); ++c) {
            std::vector<int> cell;
            for (int a = 0; a < k; ++a) cell.push_back(node(nodes[t][k * c + a]));
            orient(cell, name);
            for (int n : cell) nodes_of_body.insert(n);
            m_.cells.push_back(cell);
            m_.cell_body.push_back(body);
          }
        }
      }
      if (nodes_of_body.empty()) fail(kind + " '" + name + "' has no cells (is it meshed?)");
      m_.node_sets[name].assign(nodes_of_body.begin(), nodes_of_body.end());
    }
    gmsh::vectorpair entities;
    gmsh::model::getEntities(entities, m_.dim);
    for (const auto& [dim, tag] : entities) {
      std::vector<int> types;
      gmsh::model::mesh::getElementTypes(types, dim, tag);
      if (!types.empty() && !owner.count(tag))
        fail(std::string(group_kind(dim)) + " " + std::to_string(tag) + " is meshed but in no " + kind +
             ": add it to a body, or its cells would be left out");
    }
    for (const auto& [e, body] : owner) check_every_node_in_a_cell(e, body);
  }

  /// Every node inside entity `e` of `body` is a node of a cell of some body. gmsh keeps one
  /// type of each kind of cell (triangles, quadrangles, ...) per entity and drops the others
  /// silently: a file mixing T3 and T6 in one surface lost its T6 (their own nodes left in
  /// no cell), and the run went on without them.
  void check_every_node_in_a_cell(int e, const std::string& body) {
    std::vector<std::size_t> inside;
    std::vector<double> x, param;
    gmsh::model::mesh::getNodes(inside, x, param, m_.dim, e, false, false);
    std::size_t orphans = 0, first = 0;
    for (std::size_t k = 0; k < inside.size(); ++k)
      if (!index_.count(inside[k]) && orphans++ == 0) first = k;
    if (orphans == 0) return;
    std::ostringstream m;
    m << group_kind(m_.dim) << " " << e << " of " << physical(m_.dim) << " '" << body << "' holds " << orphans
      << " node(s) that no cell uses (node " << inside[first] << " at (" << x[3 * first] << ", " << x[3 * first + 1];
    if (m_.dim == 3) m << ", " << x[3 * first + 2];
    m << ")): gmsh may have dropped cells it read, as it does where a file mixes linear and quadratic cells of one "
      << "kind in one entity (e.g. T3 and T6; rccm reads linear cells only: Mesh.ElementOrder = 1), or the file "
      << "lists nodes of no cell: remove them";
    fail(m.str());
  }

  /// Nodes per cell of a gmsh element type: linear triangles and quadrangles (2D),
  /// tetrahedra and hexahedra (3D).
  int element_nodes(int type, const std::string& group) const {
    if (m_.dim == 2 && (type == 2 || type == 3)) return type == 2 ? 3 : 4;
    if (m_.dim == 3 && (type == 4 || type == 5)) return type == 4 ? 4 : 8;
    std::string name;
    int dim = 0, order = 0, count = 0, primary = 0;
    std::vector<double> local;
    gmsh::model::mesh::getElementProperties(type, name, dim, order, count, local, primary);
    fail(physical(m_.dim) + " '" + group + "' has " + name + " cells: rccm reads " +
         (m_.dim == 2 ? "linear triangles (T3) and quadrangles (Q4)" : "linear tetrahedra (T4) and hexahedra (H8)") +
         (order > 1 ? "; mesh with Mesh.ElementOrder = 1" : ""));
  }

  /// 2D: counter-clockwise node order (gmsh orients a cell by its surface's normal); 3D: a
  /// positive volume (a mirrored cell's node order reversed face by face).
  void orient(std::vector<int>& cell, const std::string& group) {
    const double volume = signed_measure(cell);
    if (volume < 0 && m_.dim == 2) std::reverse(cell.begin() + 1, cell.end());
    if (volume < 0 && cell.size() == 4 && m_.dim == 3) std::swap(cell[1], cell[2]);
    if (volume < 0 && cell.size() == 8) std::swap(cell[1], cell[3]), std::swap(cell[5], cell[7]);
    if (volume == 0 || signed_measure(cell) <= 0) {
      fail(physical(m_.dim) + " '" + group + "' has a cell of zero " + (m_.dim == 2 ? "area" : "volume") + " at " +
           point(m_.nodes[cell[0]], m_.dim));
    }
    const int corner = folded_corner(cell);
    if (corner >= 0)
      fail(physical(m_.dim) + " '" + group + "' has a " + (m_.dim == 2 ? "quadrangle" : "hexahedron") +
           " that folds at its corner " + point(m_.nodes[cell[corner]], m_.dim) + " (" +
           (m_.dim == 2 ? "concave there" : "twisted or concave there") +
           ": its Jacobian is negative, no finite element can be built on it); remesh that region or correct "
           "the cell's node order in the file");
  }

  /// The first corner of a Q4 or H8 where the cell folds (the Jacobian of its bilinear or
  /// trilinear map negative there: a concave or twisted cell), or -1. A Q4's Jacobian is linear
  /// in the reference coordinates: positive at its corners, positive everywhere.
  int folded_corner(const std::vector<int>& cell) const {
    static const int ref[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                                  {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
    const int k = static_cast<int>(cell.size());
    if (k != (m_.dim == 2 ? 4 : 8)) return -1;  // a simplex: its signed measure decides
    for (int a = 0; a < k; ++a) {
      Eigen::Matrix3d edges = Eigen::Matrix3d::Identity();  // 2D: the third column stays z
      double sign = 1;
      for (int j = 0; j < m_.dim; ++j) {  // the corner across reference coordinate j
        int b = 0;
        while (!(ref[b][j] == -ref[a][j] && ref[b][(j + 1) % 3] == ref[a][(j + 1) % 3] &&
                 ref[b][(j + 2) % 3] == ref[a][(j + 2) % 3]))
          ++b;
        edges.col(j) = m_.nodes[cell[b]] - m_.nodes[cell[a]];
        sign *= -ref[a][j];  // d x / d xi_j at the corner is -ref (x_b - x_a) / 2
      }
      if (sign * edges.determinant() < 0) return a;
    }
    return -1;
  }

  /// Twice the signed area of a 2D cell; 3D: the triple product of the edges from node 0 to
  /// nodes 1, 3 (H8) or 1, 2 (T4) and 4 (H8) or 3 (T4), positive for a right-handed cell.
  double signed_measure(const std::vector<int>& cell) const {
    const auto& x = m_.nodes;
    if (m_.dim == 2) {
      double area2 = 0;
      for (std::size_t a = 0; a < cell.size(); ++a) {
        const Eigen::Vector3d &p = x[cell[a]], &q = x[cell[(a + 1) % cell.size()]];
        area2 += p.x() * q.y() - q.x() * p.y();
      }
      return area2;
    }
    const bool hex = cell.size() == 8;
    const Eigen::Vector3d o = x[cell[0]];
    return (x[cell[1]] - o).cross(x[cell[hex ? 3 : 2]] - o).dot(x[cell[hex ? 4 : 3]] - o);
  }

  /// Physical groups below the bodies' dimension name node sets; a curve's (2D) or surface's
  /// (3D) elements are the facets its set loads or bonds.
  void read_node_sets() {
    for (int dim = m_.dim - 1; dim >= 0; --dim) {
      const std::string kind = physical(dim);
      gmsh::vectorpair groups;
      gmsh::model::getPhysicalGroups(groups, dim);
      for (const auto& [d, tag] : groups) {
        const std::string name = group_name(d, tag);
        if (m_.node_sets.count(name)) fail(kind + " '" + name + "' has the name of another physical group: give each its own name");
        std::vector<int> entities;
        gmsh::model::getEntitiesForPhysicalGroup(d, tag, entities);
        std::vector<int> set;
        std::vector<char> in_set(m_.nodes.size(), 0);  // a node once, in the order the elements list them
        std::vector<std::vector<int>> elements_of_set;  // facets (d = dim - 1): sorted node lists
        for (int e : entities) {
          std::vector<int> types;
          std::vector<std::vector<std::size_t>> elements, nodes;
          gmsh::model::mesh::getElements(types, elements, nodes, d, e);
          for (std::size_t t = 0; t < types.size(); ++t) {
            if (!(types[t] == 15 || types[t] == 1 || types[t] == 2 || types[t] == 3))  // point, line, triangle, quad
              fail(kind + " '" + name + "' has elements of higher order: mesh with Mesh.ElementOrder = 1");
            const std::size_t per_element = types[t] == 15 ? 1 : types[t] == 1 ? 2 : std::size_t(types[t] + 1);
            for (std::size_t k = 0; k < nodes[t].size(); ++k) {
              const auto it = index_.find(nodes[t][k]);
              if (it == index_.end())
                fail(kind + " '" + name + "' has a node on no cell of a body: it must lie on the boundary of a " + physical(m_.dim));
              if (!in_set[it->second]) in_set[it->second] = 1, set.push_back(it->second);
              if (d != m_.dim - 1) continue;
              if (k % per_element == 0) elements_of_set.emplace_back();
              elements_of_set.back().push_back(it->second);
            }
          }
        }
        if (set.empty()) fail(kind + " '" + name + "' has no nodes");
        m_.node_sets[name] = set;
        if (d != m_.dim - 1) continue;
        for (std::vector<int>& element : elements_of_set) std::sort(element.begin(), element.end());
        std::sort(elements_of_set.begin(), elements_of_set.end());
        m_.set_elements[name] = std::move(elements_of_set);
      }
    }
  }

  /// The boundary facets: the cell edges (2D) or faces (3D) of one cell only, as the cell
  /// orders them (2D: counter-clockwise; 3D: counter-clockwise seen from outside).
  void find_facets() {
    std::map<std::vector<int>, std::pair<int, std::vector<int>>> seen;  // sorted nodes -> count, oriented facet
    for (const auto& cell : m_.cells)
      for (const std::vector<int>& local : facets_of(cell.size())) {
        std::vector<int> f;
        for (int a : local) f.push_back(cell[a]);
        std::vector<int> key = f;
        std::sort(key.begin(), key.end());
        auto& e = seen[key];
        ++e.first;
        e.second = f;
      }
    for (const auto& [key, e] : seen)
      if (e.first == 1) m_.facets.push_back(e.second);
  }

  /// The facets of a cell of `k` nodes by local index, ordered counter-clockwise seen from
  /// outside a positively oriented cell.
  std::vector<std::vector<int>> facets_of(std::size_t k) const {
    if (m_.dim == 2 && k == 3) return {{0, 1}, {1, 2}, {2, 0}};
    if (m_.dim == 2) return {{0, 1}, {1, 2}, {2, 3}, {3, 0}};
    if (k == 4) return {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
    return {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
  }

  const MeshParams& p_;
  const std::string where_;
  Mesh m_;
  std::map<std::size_t, int> index_;
};

}  // namespace

std::string gmsh_answer(bool dimension_only, const MeshParams& p, const std::string& where) {
  const std::string place = gmsh_place(dimension_only, p, where);  // of gmsh's own errors
  limit_memory();
  start_gmsh();
  try {
    if (!dimension_only) return "M" + pack_mesh(Reader(p, where).read());
    open_with_parameters(p);
    const int dim = top_dimension();
    if (dim == 0) throw InputError(place + no_physical_volume);
    return "M" + std::to_string(dim);
  } catch (const InputError& e) {
    return "E" + std::string(e.what());
  } catch (const std::string& e) {  // gmsh reports its errors as strings
    return "E" + place + last_gmsh_error(e, p.file);
  } catch (const std::bad_alloc&) {
    std::ostringstream m;
    m << std::setprecision(3) << "meshing it needs more memory than the machine has (" << available_memory() / 1e9
      << " GB available): use coarser mesh sizes (the file's parameters) or fewer refinements";
    return "E" + place + m.str();
  } catch (const std::exception& e) {
    return "E" + place + last_gmsh_error(e.what(), p.file);
  }
}

}  // namespace rccm
