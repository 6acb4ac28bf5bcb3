#include "rccm/fem/gmsh_mesh.hpp"

#include "rccm/base/child_process.hpp"
#include "rccm/base/errors.hpp"
#include "rccm/fem/gmsh_reader.hpp"
#include "rccm/fem/mesh_bytes.hpp"

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <map>
#include <mutex>
#include <optional>
#include <unistd.h>

namespace rccm {

namespace {

/// GmshReuse's answers by request, while one lives.
std::mutex reuse_mutex;
std::optional<std::map<std::string, std::string>> reused;

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

/// Why gmsh's process `program` ended without an answer, for a message.
std::string crash_message(const std::string& program, const ChildOutcome& out) {
  if (out.signal == SIGKILL)
    return "gmsh was killed while reading or meshing the file (signal 9, as the kernel does when the memory runs out): "
           "use coarser mesh sizes (the file's parameters) or fewer refinements";
  if (out.signal == 0 && out.status == 127)
    return program + " could not start (exit status 127: a library it needs is missing; run it by hand to see which)";
  return std::string("gmsh stopped abnormally while reading or meshing the file (") +
         (out.signal ? "signal " + std::to_string(out.signal) + ", " + strsignal(out.signal)
                     : "exit status " + std::to_string(out.status) + " without an answer") +
         "): gmsh 4.8 aborts on errors it cannot report, most often a mesh size of 0 or below on a Point or from a "
         "Field, or a mesh larger than the memory; check the file's mesh sizes (opening it in gmsh shows its own messages)";
}

/// Runs rccm-gmsh on `p` (gmsh_reader.hpp): an error gmsh throws from its threads, or memory
/// the kernel takes back, ends that process, not the run. Returns its answer without the
/// "M"; throws InputError "<place>..." on any error (gmsh_place).
std::string ask_gmsh(bool dimension_only, const MeshParams& p, const std::string& where) {
  const std::string program = gmsh_program(), place = gmsh_place(dimension_only, p, where);
  // The caller and the place in the config, then the request proper (gmsh_process_main.cpp).
  std::vector<std::string> args{std::to_string(::getpid()), where, dimension_only ? "dimension" : "mesh",
                                mesh_bytes_protocol(), p.file, std::to_string(p.refine)};
  for (const auto& [name, value] : p.parameters) {
    char number[32];
    std::snprintf(number, sizeof number, "%.17g", value);
    args.push_back(name), args.push_back(number);
  }
  std::string request = p.contents;  // GmshReuse's key: the request proper and the file's contents
  for (auto a = args.begin() + 2; a != args.end(); ++a) request += '\n' + *a;
  {
    const std::lock_guard<std::mutex> lock(reuse_mutex);
    if (reused && reused->count(request)) return reused->at(request);
  }
  ChildOutcome out;
  try {
    out = run_program(program, args);
  } catch (const std::runtime_error& e) {
    const bool missing = ::access(program.c_str(), X_OK) != 0;
    throw InputError(place + e.what() + (missing ? " (rccm-gmsh reads gmsh files: build it with rccm, cmake --build build)" : ""));
  }
  // Ctrl-C or SIGTERM to the process group ends gmsh's process too: the run was stopped.
  if (out.signal == SIGINT || out.signal == SIGTERM)
    throw Interrupted("stopped by signal " + std::to_string(out.signal) + " while gmsh read " + place.substr(0, place.size() - 2), out.signal);
  if (!out.finished || out.bytes.empty()) throw InputError(place + crash_message(program, out));
  if (out.bytes[0] == 'E') throw InputError(out.bytes.substr(1));
  if (out.bytes[0] == 'V')
    throw InputError(place + program + " is of another build (" + out.bytes.substr(1) + "; rccm " + mesh_bytes_protocol() +
                     "): build both again, cmake --build build");
  RCCM_VERIFY(out.bytes[0] == 'M', "rccm-gmsh's answer starts with M, E or V");
  const std::lock_guard<std::mutex> lock(reuse_mutex);
  if (reused) (*reused)[request] = out.bytes.substr(1);
  return out.bytes.substr(1);
}

}  // namespace

int read_gmsh_dimension(const MeshParams& p) {
  const std::string dim = ask_gmsh(true, p, "");
  RCCM_VERIFY(dim == "2" || dim == "3", "rccm-gmsh answers the dimension 2 or 3");
  return dim[0] - '0';
}

Mesh read_gmsh(const MeshParams& p, const std::string& where) {
  return unpack_mesh(ask_gmsh(false, p, where));
}

GmshReuse::GmshReuse() {
  const std::lock_guard<std::mutex> lock(reuse_mutex);
  RCCM_VERIFY(!reused, "one GmshReuse at a time");
  reused.emplace();
}

GmshReuse::~GmshReuse() {
  const std::lock_guard<std::mutex> lock(reuse_mutex);
  reused.reset();
}

}  // namespace rccm
