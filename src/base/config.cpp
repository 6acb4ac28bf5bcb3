#include "rccm/base/config.hpp"

namespace rccm {

std::string Config::where(const std::string& path) const {
  const auto it = lines.find(path);
  if (it == lines.end() || it->second == 0) return file + ": " + path;
  return file + ":" + std::to_string(it->second) + ": " + path;
}

const char* method_name(Method m) {
  switch (m) {
    case Method::Arkode: return "arkode";
    case Method::Euler: return "euler";
    case Method::RateIndependent: return "rate-independent";
    case Method::ContactOnly: return "contact-only";
  }
  return "";
}

}  // namespace rccm
