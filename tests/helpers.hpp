// Small helpers shared by the tests.
#pragma once

#include "rccm/base/config.hpp"
#include "rccm/fem/mesh_source.hpp"
#include "rccm/io/config_reader.hpp"
#include "rccm/model/model.hpp"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <unistd.h>
#include <vector>

namespace rccm::test {

/// A config shipped in config/.
inline std::string shipped(const std::string& name) { return std::string(RCCM_SOURCE_DIR) + "/config/" + name; }

/// Writes `text` to a temporary .cfg file and returns its path.
inline std::string write_temp_config(const std::string& text) {
  char name[] = "/tmp/rccm_test_XXXXXX.cfg";
  const int fd = mkstemps(name, 4);
  ::close(fd);
  std::ofstream(name) << text;
  return name;
}

/// Writes `text` to the file `name` in the build tree's tests/tmp (a fixture made by a test:
/// gmsh picks the reader by the extension) and returns its path.
inline std::string write_temp_file(const std::string& name, const std::string& text) {
  std::filesystem::create_directories(RCCM_TEST_TMP);
  const std::string path = std::string(RCCM_TEST_TMP) + "/" + name;
  std::ofstream(path) << text;
  return path;
}

inline Config config_from_text(const std::string& text, const std::vector<std::string>& overrides = {}) {
  struct Removed {  // also when load_config throws (the bad-config tests)
    std::string path;
    ~Removed() { std::remove(path.c_str()); }
  } file{write_temp_config(text)};
  return load_config(file.path, overrides);
}

/// config/corner-peel.cfg in small: a plate of n x 1 x n H8 cells of 1 mm bonded to a rigid
/// base by its face y = 0, lifted by one corner at 0.03 mm/s for 5 s, by sweeps; `mesh` (a
/// mesh section) replaces the built-in box.
inline Config corner_peel(int n, const std::vector<std::string>& overrides = {}, std::string mesh = "") {
  const std::string side = std::to_string(n);
  if (mesh.empty())
    mesh = "mesh = { size = [" + side + ".0, 1.0, " + side + ".0]; nx = " + side + "; ny = 1; nz = " + side + "; element = \"H8\"; };";
  return config_from_text(mesh + R"(
material = { E = 6.9e4; nu = 0.333; };
interface = { boundary = "bottom"; normal = [0.0, 1.0, 0.0]; Cn = 2.0e5; Ct = 2.0e5; w = 1.0e-6; alpha = 1.0; mu = 0.2; beta0 = 1.0; };
loads = ( { node_set = "top_left_back"; type = "displacement"; component = "y"; value = 0.15; } );
time = { T = 5.0; };
solver = { active_set = false; };
)",
                          overrides);
}

/// The model of a config on its built-in rectangle mesh, as `rccm run` builds it.
inline Model make_model(const Config& cfg) { return Model(cfg, make_mesh(cfg)); }

/// A CSV file of rccm (RFC 4180: fields may be quoted, "" inside quotes) as columns by header.
struct CsvTable {
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;
  /// The numbers of a column, by its header.
  std::vector<double> numbers(const std::string& name) const {
    for (std::size_t j = 0; j < header.size(); ++j)
      if (header[j] == name) {
        std::vector<double> v;
        for (const auto& r : rows) v.push_back(std::stod(r.at(j)));
        return v;
      }
    throw std::runtime_error("no column '" + name + "'");
  }
};

inline std::vector<std::string> split_csv_line(const std::string& line) {
  std::vector<std::string> cells(1);
  bool quoted = false;
  for (std::size_t k = 0; k < line.size(); ++k) {
    const char c = line[k];
    if (quoted && c == '"' && k + 1 < line.size() && line[k + 1] == '"') cells.back() += '"', ++k;
    else if (c == '"') quoted = !quoted;
    else if (c == ',' && !quoted) cells.emplace_back();
    else cells.back() += c;
  }
  return cells;
}

/// A file's whole text ("" if it cannot be read).
inline std::string read_text(const std::string& path) {
  std::ifstream in(path);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

inline CsvTable read_csv(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read " + path);
  CsvTable t;
  std::string line;
  std::getline(in, line);
  t.header = split_csv_line(line);
  while (std::getline(in, line)) t.rows.push_back(split_csv_line(line));
  return t;
}

/// Linear interpolation of (x, y) at xi (x increasing).
inline double interpolate(const std::vector<double>& x, const std::vector<double>& y, double xi) {
  if (xi <= x.front()) return y.front();
  if (xi >= x.back()) return y.back();
  std::size_t k = 1;
  while (x[k] < xi) ++k;
  const double s = (xi - x[k - 1]) / (x[k] - x[k - 1]);
  return y[k - 1] + s * (y[k] - y[k - 1]);
}

/// The built-in box of nx x ny x nz H8 cells over lx x ly x lz mm (make_box).
inline MeshParams box(double lx, double ly, double lz, int nx, int ny, int nz) {
  MeshParams p;
  p.size = {lx, ly};
  p.depth = lz;
  p.nx = nx, p.ny = ny, p.nz = nz;
  p.dimension = 3;
  p.element = ElementType::H8;
  return p;
}

/// A 2 x 2 patch of Q4 (or 8 T3) cells on [1, 3] x [0, 2] with its middle node moved off
/// centre, and its boundary edges.
inline Mesh distorted_patch(bool triangles, bool axisymmetric) {
  Mesh m;
  m.axisymmetric = axisymmetric;
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) m.nodes.emplace_back(1.0 + i, double(j), 0.0);
  m.nodes[4] = Eigen::Vector3d(2.3, 0.8, 0.0);
  const auto id = [](int i, int j) { return 3 * j + i; };
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 2; ++i) {
      const int a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
      if (triangles) {
        m.cells.push_back({a, b, c});
        m.cells.push_back({a, c, d});
      } else {
        m.cells.push_back({a, b, c, d});
      }
    }
  m.cell_body.assign(m.cells.size(), 0);
  m.body_names = {"patch"};
  for (int k = 0; k < 2; ++k) {
    m.facets.push_back({id(k, 0), id(k + 1, 0)});
    m.facets.push_back({id(2, k), id(2, k + 1)});
    m.facets.push_back({id(k + 1, 2), id(k, 2)});
    m.facets.push_back({id(0, k + 1), id(0, k)});
  }
  return m;
}

}  // namespace rccm::test
