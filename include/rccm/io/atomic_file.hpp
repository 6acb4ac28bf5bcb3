// A whole file written under a temporary name and renamed into place by commit(): a reader
// (ParaView, tools/plot, a script watching the directory) sees the previous version or the
// complete new one, never half a file.
#pragma once

#include <fstream>
#include <string>

namespace rccm {

class AtomicFile {
 public:
  /// Opens PATH.tmp; throws SolveError when it cannot be created.
  explicit AtomicFile(std::string path);
  ~AtomicFile();  // an uncommitted temporary is removed
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  std::ostream& stream() { return out_; }

  /// Closes and renames PATH.tmp to PATH; throws SolveError naming PATH on any write error.
  void commit();

 private:
  std::string path_, temporary_;
  std::ofstream out_;
  bool committed_ = false;
};

}  // namespace rccm
