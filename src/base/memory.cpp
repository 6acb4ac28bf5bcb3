#include "rccm/base/memory.hpp"

#include "rccm/base/errors.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>

namespace rccm {

double available_memory() {
  std::ifstream in("/proc/meminfo");
  std::string key;
  double kb = 0;
  while (in >> key >> kb) {
    if (key == "MemAvailable:") return 1024 * kb;
    in.ignore(256, '\n');
  }
  return 1e18;
}

double assembly_bytes(double unknowns) { return unknowns * (600 + 100 * std::log2(std::max(unknowns, 2.0))); }

std::string memory_shortfall(double bytes, const std::string& what) {
  const double available = available_memory();
  if (bytes <= available) return "";
  char text[160];
  std::snprintf(text, sizeof text, "%s needs about %.3g GB, the machine has %.3g GB available", what.c_str(),
                bytes / 1e9, available / 1e9);
  return text;
}

void require_memory(double bytes, const std::string& where, const std::string& what, const std::string& advice) {
  const std::string shortfall = memory_shortfall(bytes, what);
  if (!shortfall.empty()) throw InputError(where + ": " + shortfall + "; " + advice);
}

}  // namespace rccm
