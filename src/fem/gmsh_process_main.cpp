// rccm-gmsh: reads or meshes one gmsh file for rccm (gmsh_mesh.cpp starts it) and writes its
// answer (gmsh_reader.hpp) to file descriptor 3. Not meant to be run by hand.
//   rccm-gmsh CALLER_PID WHERE mesh|dimension PROTOCOL FILE REFINE [PARAMETER VALUE]...
// PROTOCOL is the caller's mesh_bytes_protocol(): another answers "V" and its own.
#include "rccm/base/child_process.hpp"
#include "rccm/fem/gmsh_reader.hpp"
#include "rccm/fem/mesh_bytes.hpp"

#include <cerrno>
#include <cstdlib>
#include <string>
#include <unistd.h>

int main(int argc, char** argv) {
  if (argc < 5 || !rccm::follow_caller(std::atol(argv[1]))) return 2;
  const std::string kind = argv[3], protocol = rccm::mesh_bytes_protocol();
  std::string answer;
  if (argv[4] != protocol || argc < 7 || (argc - 7) % 2 != 0 || (kind != "mesh" && kind != "dimension")) {
    answer = "V" + protocol;
  } else {
    rccm::MeshParams p;
    p.file = argv[5];
    p.refine = std::atoi(argv[6]);
    for (int a = 7; a < argc; a += 2) p.parameters[argv[a]] = std::strtod(argv[a + 1], nullptr);
    answer = rccm::gmsh_answer(kind == "dimension", p, argv[2]);
  }
  for (std::size_t done = 0; done < answer.size();) {
    const ssize_t n = ::write(3, answer.data() + done, answer.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return 1;  // the caller is gone
    done += static_cast<std::size_t>(n);
  }
  // _exit: gmsh is never finalized (freeing a large model would only delay the answer).
  ::_exit(0);
}
