#include "rccm/base/memory.hpp"

#include "rccm/base/errors.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>

namespace rccm {

namespace {

/// RCCM_MEMORY_GB in bytes, or a large number when it is not set.
double memory_cap() {
  const char* text = std::getenv("RCCM_MEMORY_GB");
  if (text == nullptr) return 1e18;
  char* end = nullptr;
  const double gb = std::strtod(text, &end);
  if (end == text || *end != '\0' || !(gb > 0) || !std::isfinite(gb))
    throw InputError(std::string("RCCM_MEMORY_GB=") + text + ": must be a number of gigabytes > 0 (the memory rccm may plan with)");
  return gb * 1e9;
}

}  // namespace

double available_memory() {
  const double cap = memory_cap();
  std::ifstream in("/proc/meminfo");
  std::string key;
  double kb = 0;
  while (in >> key >> kb) {
    if (key == "MemAvailable:") return std::min(cap, 1024 * kb);
    in.ignore(256, '\n');
  }
  return cap;
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
