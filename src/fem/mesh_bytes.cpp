#include "rccm/fem/mesh_bytes.hpp"

#include "rccm/base/errors.hpp"

#include <cstring>
#include <type_traits>

namespace rccm {

namespace {

class Packer {
 public:
  template <class T>
  void put(const T& v) {
    static_assert(std::is_arithmetic_v<T>);
    bytes.append(reinterpret_cast<const char*>(&v), sizeof v);
  }
  void put(const std::string& s) { put(s.size()), bytes += s; }
  void put(const Eigen::Vector3d& x) { put(x[0]), put(x[1]), put(x[2]); }
  template <class T>
  void put(const std::vector<T>& v) {
    put(v.size());
    for (const T& e : v) put(e);
  }
  std::string bytes;
};

class Unpacker {
 public:
  explicit Unpacker(const std::string& bytes) : bytes_(bytes) {}
  template <class T>
  void get(T& v) {
    static_assert(std::is_arithmetic_v<T>);
    std::memcpy(&v, take(sizeof v), sizeof v);
  }
  void get(std::string& s) {
    std::size_t n = 0;
    get(n);
    s.assign(take(n), n);
  }
  void get(Eigen::Vector3d& x) { get(x[0]), get(x[1]), get(x[2]); }
  template <class T>
  void get(std::vector<T>& v) {
    std::size_t n = 0;
    get(n);
    RCCM_VERIFY(n <= bytes_.size() - at_, "a mesh's bytes from gmsh's process are cut short");
    v.resize(n);
    for (T& e : v) get(e);
  }
  bool done() const { return at_ == bytes_.size(); }

 private:
  const char* take(std::size_t n) {
    RCCM_VERIFY(n <= bytes_.size() - at_, "a mesh's bytes from gmsh's process are cut short");
    at_ += n;
    return bytes_.data() + at_ - n;
  }
  const std::string& bytes_;
  std::size_t at_ = 0;
};

}  // namespace

std::string pack_mesh(const Mesh& m) {
  Packer b;
  b.put(m.dim), b.put(m.source), b.put(m.nodes), b.put(m.cells), b.put(m.cell_body), b.put(m.body_names), b.put(m.facets);
  b.put(m.node_sets.size());
  for (const auto& [name, nodes] : m.node_sets) b.put(name), b.put(nodes);
  b.put(m.set_elements.size());
  for (const auto& [name, elements] : m.set_elements) b.put(name), b.put(elements);
  return std::move(b.bytes);
}

Mesh unpack_mesh(const std::string& bytes) {
  Unpacker b(bytes);
  Mesh m;
  b.get(m.dim), b.get(m.source), b.get(m.nodes), b.get(m.cells), b.get(m.cell_body), b.get(m.body_names), b.get(m.facets);
  std::size_t sets = 0;
  for (b.get(sets); sets > 0; --sets) {
    std::string name;
    b.get(name);
    b.get(m.node_sets[name]);
  }
  for (b.get(sets); sets > 0; --sets) {
    std::string name;
    b.get(name);
    b.get(m.set_elements[name]);
  }
  RCCM_VERIFY(b.done(), "a mesh's bytes from gmsh's process are longer than the mesh");
  return m;
}

}  // namespace rccm
