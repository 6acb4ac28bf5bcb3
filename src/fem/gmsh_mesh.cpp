#include "rccm/fem/gmsh_mesh.hpp"

#include "rccm/base/errors.hpp"
#include "rccm/base/suggest.hpp"

#include <gmsh.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <mutex>
#include <set>
#include <sstream>

namespace rccm {

namespace {

/// gmsh's library state for one read: initialized without reading the user's gmshrc,
/// silent, its messages collected, no parameter left from an earlier read (gmsh keeps
/// them across finalize); finalized on every way out. gmsh's state is global: one read at
/// a time (a sweep builds its cases' models in parallel threads).
class GmshSession {
 public:
  GmshSession() : lock_(mutex()) {
    gmsh::initialize(0, nullptr, false);
    gmsh::option::setNumber("General.Terminal", 0);
    gmsh::logger::start();
    gmsh::onelab::clear();
  }
  ~GmshSession() { gmsh::finalize(); }
  GmshSession(const GmshSession&) = delete;
  GmshSession& operator=(const GmshSession&) = delete;

  /// gmsh's last error message, or the exception's text.
  static std::string last_error(const std::string& fallback) {
    std::string e;
    gmsh::logger::getLastError(e);
    return e.empty() ? fallback : e;
  }

 private:
  static std::mutex& mutex() {
    static std::mutex m;
    return m;
  }
  std::lock_guard<std::mutex> lock_;
};

const char* group_kind(int dim) { return dim == 0 ? "point" : dim == 1 ? "curve" : "surface"; }

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
      for (const auto& [name, value] : p_.parameters) gmsh::onelab::setNumber(name, {value});
      gmsh::open(p_.file);
      std::vector<int> types;
      gmsh::model::mesh::getElementTypes(types, 2);
      if (types.empty()) gmsh::model::mesh::generate(2);
    } catch (const std::string& e) {
      fail(GmshSession::last_error(e));
    } catch (const std::exception& e) {
      fail(GmshSession::last_error(e.what()));
    }
  }

  /// Every parameter is a DefineConstant of the .geo (a misspelt one would be ignored).
  void check_parameters() {
    gmsh::open(p_.file);
    std::vector<std::string> names;
    gmsh::onelab::getNames(names);
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
    if (std::abs(x[2]) > 1e-12 * (1 + std::abs(x[0]) + std::abs(x[1]))) {
      std::ostringstream m;
      m << "node " << tag << " lies at z = " << x[2] << ": a 2D mesh lies in the plane z = 0";
      fail(m.str());
    }
    m_.nodes.emplace_back(x[0], x[1], 0.0);
    return index_[tag] = m_.num_nodes() - 1;
  }

  void read_bodies() {
    gmsh::vectorpair groups;
    gmsh::model::getPhysicalGroups(groups, 2);
    if (groups.empty()) fail("no Physical Surface: name each body, e.g. Physical Surface(\"arm\") = {1};");
    std::map<int, std::string> owner;  // surface entity -> its body
    for (const auto& [dim, tag] : groups) {
      const std::string name = group_name(dim, tag);
      const int body = static_cast<int>(m_.body_names.size());
      m_.body_names.push_back(name);
      std::vector<int> entities;
      gmsh::model::getEntitiesForPhysicalGroup(dim, tag, entities);
      std::set<int> nodes_of_body;
      for (int e : entities) {
        if (owner.count(e))
          fail("surface " + std::to_string(e) + " is in two Physical Surfaces, '" + owner[e] + "' and '" + name +
               "': a cell belongs to one body");
        owner[e] = name;
        std::vector<int> types;
        std::vector<std::vector<std::size_t>> cells, nodes;
        gmsh::model::mesh::getElements(types, cells, nodes, 2, e);
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
      if (nodes_of_body.empty()) fail("Physical Surface '" + name + "' has no cells (is the surface meshed?)");
      m_.node_sets[name].assign(nodes_of_body.begin(), nodes_of_body.end());
    }
    gmsh::vectorpair surfaces;
    gmsh::model::getEntities(surfaces, 2);
    for (const auto& [dim, tag] : surfaces) {
      std::vector<int> types;
      gmsh::model::mesh::getElementTypes(types, dim, tag);
      if (!types.empty() && !owner.count(tag))
        fail("surface " + std::to_string(tag) + " is meshed but in no Physical Surface: add it to a body, or its "
             "cells would be left out");
    }
  }

  /// Nodes per cell of a gmsh element type: linear triangles and quadrangles only.
  int element_nodes(int type, const std::string& group) const {
    if (type == 2) return 3;
    if (type == 3) return 4;
    std::string name;
    int dim = 0, order = 0, count = 0, primary = 0;
    std::vector<double> local;
    gmsh::model::mesh::getElementProperties(type, name, dim, order, count, local, primary);
    fail("Physical Surface '" + group + "' has " + name + " cells: rccm reads linear triangles (T3) and quadrangles (Q4)" +
         (order > 1 ? "; mesh with Mesh.ElementOrder = 1" : ""));
  }

  /// Counter-clockwise node order (gmsh orients a cell by its surface's normal).
  void orient(std::vector<int>& cell, const std::string& group) {
    double area2 = 0;
    for (std::size_t a = 0; a < cell.size(); ++a) {
      const Eigen::Vector3d &p = m_.nodes[cell[a]], &q = m_.nodes[cell[(a + 1) % cell.size()]];
      area2 += p.x() * q.y() - q.x() * p.y();
    }
    if (area2 < 0) std::reverse(cell.begin() + 1, cell.end());
    if (area2 == 0) {
      const Eigen::Vector3d& x = m_.nodes[cell[0]];
      std::ostringstream m;
      m << "Physical Surface '" << group << "' has a cell of zero area at (" << x.x() << ", " << x.y() << ")";
      fail(m.str());
    }
  }

  void read_node_sets() {
    for (int dim : {1, 0}) {
      gmsh::vectorpair groups;
      gmsh::model::getPhysicalGroups(groups, dim);
      for (const auto& [d, tag] : groups) {
        const std::string name = group_name(d, tag);
        if (m_.node_sets.count(name))
          fail("Physical " + std::string(dim == 1 ? "Curve" : "Point") + " '" + name +
               "' has the name of another physical group: give each its own name");
        std::vector<int> entities;
        gmsh::model::getEntitiesForPhysicalGroup(d, tag, entities);
        std::vector<int> set;
        for (int e : entities) {
          std::vector<int> types;
          std::vector<std::vector<std::size_t>> elements, nodes;
          gmsh::model::mesh::getElements(types, elements, nodes, d, e);
          for (std::size_t t = 0; t < types.size(); ++t) {
            if (types[t] != 1 && types[t] != 15)
              fail("Physical Curve '" + name + "' has elements of higher order: mesh with Mesh.ElementOrder = 1");
            for (std::size_t tag_of_node : nodes[t]) {
              const auto it = index_.find(tag_of_node);
              if (it == index_.end())
                fail("Physical " + std::string(dim == 1 ? "Curve" : "Point") + " '" + name +
                     "' has a node on no cell of a body: it must lie on the boundary of a Physical Surface");
              if (std::find(set.begin(), set.end(), it->second) == set.end()) set.push_back(it->second);
            }
          }
        }
        if (set.empty()) fail("Physical " + std::string(dim == 1 ? "Curve" : "Point") + " '" + name + "' has no nodes");
        m_.node_sets[name] = set;
      }
    }
  }

  /// The boundary facets: the cell edges of one cell only.
  void find_facets() {
    std::map<std::pair<int, int>, std::pair<int, std::vector<int>>> edges;  // sorted nodes -> count, oriented edge
    for (const auto& cell : m_.cells)
      for (std::size_t a = 0; a < cell.size(); ++a) {
        const int i = cell[a], j = cell[(a + 1) % cell.size()];
        auto& e = edges[{std::min(i, j), std::max(i, j)}];
        ++e.first;
        e.second = {i, j};
      }
    for (const auto& [key, e] : edges)
      if (e.first == 1) m_.facets.push_back(e.second);
  }

  const MeshParams& p_;
  const std::string where_;
  Mesh m_;
  std::map<std::size_t, int> index_;
};

}  // namespace

Mesh read_gmsh(const MeshParams& p, const std::string& where) {
  GmshSession session;
  try {
    return Reader(p, where).read();
  } catch (const std::string& e) {  // gmsh reports its errors as strings
    throw InputError(where + ": " + p.file + ": " + GmshSession::last_error(e));
  }
}

}  // namespace rccm
