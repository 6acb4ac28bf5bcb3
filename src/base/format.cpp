#include "rccm/base/format.hpp"

#include <cstdio>

namespace rccm {

std::string fmt(const char* format, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, format, v);
  return buf;
}

}  // namespace rccm
