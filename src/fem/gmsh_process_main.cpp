// rccm-gmsh: reads or meshes one gmsh file for rccm (gmsh_mesh.cpp starts it) and writes its
// answer (gmsh_reader.hpp) to file descriptor 3. Not meant to be run by hand.
//   rccm-gmsh mesh|dimension CALLER_PID FILE REFINE WHERE [PARAMETER VALUE]...
#include "rccm/base/child_process.hpp"
#include "rccm/fem/gmsh_reader.hpp"

#include <cerrno>
#include <cstdlib>
#include <string>
#include <unistd.h>

int main(int argc, char** argv) {
  if (argc < 6 || (argc - 6) % 2 != 0) return 2;
  const std::string kind = argv[1];
  if ((kind != "mesh" && kind != "dimension") || !rccm::follow_caller(std::atol(argv[2]))) return 2;
  rccm::MeshParams p;
  p.file = argv[3];
  p.refine = std::atoi(argv[4]);
  for (int a = 6; a < argc; a += 2) p.parameters[argv[a]] = std::strtod(argv[a + 1], nullptr);
  const std::string answer = rccm::gmsh_answer(kind == "dimension", p, argv[5]);
  for (std::size_t done = 0; done < answer.size();) {
    const ssize_t n = ::write(3, answer.data() + done, answer.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return 1;  // the caller is gone
    done += static_cast<std::size_t>(n);
  }
  // _exit: gmsh is never finalized (freeing a large model would only delay the answer).
  ::_exit(0);
}
