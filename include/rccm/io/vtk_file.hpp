// A VTK XML file (UnstructuredGrid or PolyData) with its arrays appended in binary, zlib
// compressed (ParaView's own format): a VTK reader needs no text parsing, and files stay
// small. Array names are plain words (letters, digits, '_'): ParaView's calculator reads them.
#pragma once

#include <Eigen/Core>

#include <cstdint>
#include <string>
#include <vector>

namespace rccm {

class VtkFile {
 public:
  enum class Kind { UnstructuredGrid, PolyData, PolySurface };  // PolyData: lines; PolySurface: polygons
  /// One array of `components` values per point or cell, stored as Float64, Int64, Int32 or UInt8.
  struct Array {
    std::string name;
    std::string type;                       // "Float64", "Int64", "Int32", "UInt8"
    int components = 1;
    std::vector<std::string> component_names;  // shown by ParaView (empty: 0, 1, 2 ...)
    std::string bytes;                      // the raw little-endian values
  };

  static Array floats(const std::string& name, int components, const std::vector<double>& values,
                      std::vector<std::string> component_names = {});
  static Array integers(const std::string& name, const std::string& type, const std::vector<std::int64_t>& values);

  explicit VtkFile(Kind kind) : kind_(kind) {}
  void points(const std::vector<double>& xyz) { points_ = floats("Points", 3, xyz); }
  /// Cells (UnstructuredGrid) or lines (PolyData) by their node lists and VTK types.
  void cells(const std::vector<std::vector<int>>& cells, const std::vector<int>& vtk_types);
  void point_data(Array a) { point_data_.push_back(std::move(a)); }
  void cell_data(Array a) { cell_data_.push_back(std::move(a)); }

  /// The whole file, written under a temporary name and renamed (AtomicFile).
  void write(const std::string& path) const;

 private:
  Kind kind_;
  Array points_;
  std::vector<Array> topology_;  // connectivity, offsets (and types)
  std::size_t cells_count_ = 0;
  std::vector<Array> point_data_, cell_data_;
};

/// A .pvd collection: the files of a time series with their times, rewritten whole.
void write_collection(const std::string& path, const std::vector<std::pair<double, std::string>>& files);

}  // namespace rccm
