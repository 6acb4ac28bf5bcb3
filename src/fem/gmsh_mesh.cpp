#include "rccm/fem/gmsh_mesh.hpp"

#include "rccm/base/child_process.hpp"
#include "rccm/base/errors.hpp"
#include "rccm/fem/mesh_bytes.hpp"

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <unistd.h>

namespace rccm {

namespace {

/// rccm-gmsh: next to the running program (rccm), else where the build put it (the tests
/// and the examples run from folders of their own).
std::string gmsh_program() {
  char self[4096];
  const ssize_t n = ::readlink("/proc/self/exe", self, sizeof self - 1);
  if (n > 0) {
    std::string beside(self, static_cast<std::size_t>(n));
    beside = beside.substr(0, beside.find_last_of('/') + 1) + "rccm-gmsh";
    if (::access(beside.c_str(), X_OK) == 0) return beside;
  }
  return RCCM_GMSH_PROGRAM;
}

/// Why gmsh's process ended without an answer (ended by `signal`, or 0), for a message.
std::string crash_message(int signal) {
  if (signal == SIGKILL)
    return "gmsh was killed while reading or meshing the file (signal 9, as the kernel does when the memory runs out): "
           "use coarser mesh sizes (the file's parameters) or fewer refinements";
  return std::string("gmsh stopped abnormally while reading or meshing the file (") +
         (signal ? "signal " + std::to_string(signal) + ", " + strsignal(signal) : std::string("no answer")) +
         "): gmsh 4.8 aborts on errors it cannot report, most often a mesh size of 0 or below on a Point or from a "
         "Field, or a mesh larger than the memory; check the file's mesh sizes (opening it in gmsh shows its own messages)";
}

/// Runs rccm-gmsh on `p` (gmsh_reader.hpp): an error gmsh throws from its threads, or memory
/// the kernel takes back, ends that process, not the run. Returns its answer without the
/// "M"; throws InputError "<place>..." on any error (`place`: the file, or the setting and
/// the file).
std::string ask_gmsh(bool dimension_only, const MeshParams& p, const std::string& where, const std::string& place) {
  std::vector<std::string> args{dimension_only ? "dimension" : "mesh", std::to_string(::getpid()), p.file,
                                std::to_string(p.refine), where};
  for (const auto& [name, value] : p.parameters) {
    char number[32];
    std::snprintf(number, sizeof number, "%.17g", value);
    args.push_back(name), args.push_back(number);
  }
  ChildOutcome out;
  try {
    out = run_program(gmsh_program(), args);
  } catch (const std::runtime_error& e) {
    throw InputError(place + e.what() + " (rccm-gmsh reads gmsh files: build it with rccm, cmake --build build)");
  }
  // Ctrl-C or SIGTERM to the process group ends gmsh's process too: the run was stopped.
  if (out.signal == SIGINT || out.signal == SIGTERM)
    throw Interrupted("stopped by signal " + std::to_string(out.signal) + " while gmsh read " + place.substr(0, place.size() - 2), out.signal);
  if (!out.finished || out.bytes.empty()) throw InputError(place + crash_message(out.signal));
  if (out.bytes[0] == 'E') throw InputError(out.bytes.substr(1));
  return out.bytes.substr(1);
}

}  // namespace

int read_gmsh_dimension(const MeshParams& p) {
  return std::stoi(ask_gmsh(true, p, "", p.file + ": "));
}

Mesh read_gmsh(const MeshParams& p, const std::string& where) {
  return unpack_mesh(ask_gmsh(false, p, where, where + ": " + p.file + ": "));
}

}  // namespace rccm
