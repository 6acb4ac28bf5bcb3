#include "rccm/io/vtk_file.hpp"

#include "rccm/base/errors.hpp"
#include "rccm/io/atomic_file.hpp"

#include <zlib.h>

#include <cstdio>
#include <cstring>
#include <ostream>

namespace rccm {

namespace {

template <class T>
std::string raw(const std::vector<T>& values) {
  return std::string(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(T));
}

/// One zlib block with the UInt64 header of vtkZLibDataCompressor: #blocks, block size,
/// last partial block size (0: the block is full), compressed size.
std::string compressed(const std::string& bytes) {
  uLongf size = compressBound(static_cast<uLong>(bytes.size()));
  std::string packed(size, '\0');
  if (compress2(reinterpret_cast<Bytef*>(packed.data()), &size, reinterpret_cast<const Bytef*>(bytes.data()),
                static_cast<uLong>(bytes.size()), Z_DEFAULT_COMPRESSION) != Z_OK)
    throw InternalError("zlib compress2 failed");
  packed.resize(size);
  const std::vector<std::uint64_t> header = {1, bytes.size(), 0, size};
  return raw(header) + packed;
}

void declare(std::ostream& out, const VtkFile::Array& a, std::size_t offset) {
  out << "<DataArray type=\"" << a.type << "\" Name=\"" << a.name << "\" NumberOfComponents=\"" << a.components
      << "\"";
  for (std::size_t k = 0; k < a.component_names.size(); ++k)
    out << " ComponentName" << k << "=\"" << a.component_names[k] << "\"";
  out << " format=\"appended\" offset=\"" << offset << "\"/>\n";
}

}  // namespace

VtkFile::Array VtkFile::floats(const std::string& name, int components, const std::vector<double>& values,
                               std::vector<std::string> component_names) {
  return {name, "Float64", components, std::move(component_names), raw(values)};
}

VtkFile::Array VtkFile::integers(const std::string& name, const std::string& type,
                                 const std::vector<std::int64_t>& values) {
  Array a{name, type, 1, {}, {}};
  if (type == "Int64") {
    a.bytes = raw(values);
  } else if (type == "Int32") {
    a.bytes = raw(std::vector<std::int32_t>(values.begin(), values.end()));
  } else {
    RCCM_VERIFY(type == "UInt8", "VTK integer types: Int64, Int32, UInt8");
    a.bytes = raw(std::vector<std::uint8_t>(values.begin(), values.end()));
  }
  return a;
}

void VtkFile::cells(const std::vector<std::vector<int>>& cells, const std::vector<int>& vtk_types) {
  std::vector<std::int64_t> connectivity, offsets, types(vtk_types.begin(), vtk_types.end());
  for (const auto& c : cells) {
    connectivity.insert(connectivity.end(), c.begin(), c.end());
    offsets.push_back(static_cast<std::int64_t>(connectivity.size()));
  }
  topology_ = {integers("connectivity", "Int64", connectivity), integers("offsets", "Int64", offsets)};
  if (kind_ == Kind::UnstructuredGrid) topology_.push_back(integers("types", "UInt8", types));
  cells_count_ = cells.size();
}

void VtkFile::write(const std::string& path) const {
  const std::size_t points = points_.bytes.size() / (3 * sizeof(double));
  const bool grid = kind_ == Kind::UnstructuredGrid;
  // The blocks, in the order of their declaration; offsets count from the '_' of AppendedData.
  std::vector<const Array*> order = {&points_};
  for (const Array& a : topology_) order.push_back(&a);
  for (const Array& a : point_data_) order.push_back(&a);
  for (const Array& a : cell_data_) order.push_back(&a);
  std::vector<std::string> blocks;
  std::vector<std::size_t> offsets;
  std::size_t offset = 0;
  for (const Array* a : order) {
    blocks.push_back(compressed(a->bytes));
    offsets.push_back(offset);
    offset += blocks.back().size();
  }
  AtomicFile file(path);
  std::ostream& out = file.stream();
  const char* type = grid ? "UnstructuredGrid" : "PolyData";
  const char* section = grid ? "Cells" : kind_ == Kind::PolySurface ? "Polys" : "Lines";
  out << "<?xml version=\"1.0\"?>\n<VTKFile type=\"" << type << "\" version=\"1.0\" byte_order=\"LittleEndian\" "
      << "header_type=\"UInt64\" compressor=\"vtkZLibDataCompressor\">\n<" << type << ">\n<Piece NumberOfPoints=\""
      << points << "\" NumberOf" << section << "=\"" << cells_count_ << "\">\n<Points>\n";
  std::size_t k = 0;
  declare(out, *order[k], offsets[k]), ++k;
  out << "</Points>\n<" << section << ">\n";
  for (std::size_t j = 0; j < topology_.size(); ++j) declare(out, *order[k], offsets[k]), ++k;
  out << "</" << section << ">\n<PointData>\n";
  for (std::size_t j = 0; j < point_data_.size(); ++j) declare(out, *order[k], offsets[k]), ++k;
  out << "</PointData>\n<CellData>\n";
  for (std::size_t j = 0; j < cell_data_.size(); ++j) declare(out, *order[k], offsets[k]), ++k;
  out << "</CellData>\n</Piece>\n</" << type << ">\n<AppendedData encoding=\"raw\">\n_";
  for (const std::string& b : blocks) out.write(b.data(), static_cast<std::streamsize>(b.size()));
  out << "\n</AppendedData>\n</VTKFile>\n";
  file.commit();
}

void write_collection(const std::string& path, const std::vector<std::pair<double, std::string>>& files) {
  AtomicFile collection(path);
  std::ostream& pvd = collection.stream();
  pvd << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n<Collection>\n";
  for (const auto& [t, file] : files) {
    char time[32];
    std::snprintf(time, sizeof time, "%.12g", t);
    pvd << "<DataSet timestep=\"" << time << "\" file=\"" << file << "\"/>\n";
  }
  pvd << "</Collection>\n</VTKFile>\n";
  collection.commit();
}

}  // namespace rccm
