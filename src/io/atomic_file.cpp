#include "rccm/io/atomic_file.hpp"

#include "rccm/base/errors.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>

namespace rccm {

AtomicFile::AtomicFile(std::string path) : path_(std::move(path)), temporary_(path_ + ".tmp"), out_(temporary_) {
  if (!out_) throw WriteError("cannot write " + temporary_ + " (" + std::strerror(errno) + ")");
}

AtomicFile::~AtomicFile() {
  if (!committed_) std::remove(temporary_.c_str());
}

void AtomicFile::commit() {
  out_.close();
  if (!out_ || std::rename(temporary_.c_str(), path_.c_str()) != 0)
    throw WriteError("cannot write " + path_ + " (" + std::strerror(errno) + ")");
  committed_ = true;
}

}  // namespace rccm
