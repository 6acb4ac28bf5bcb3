// A number as reports, tables and messages print it.
#pragma once

#include <string>

namespace rccm {

/// `v` formatted by printf's `format` (one conversion of a double): fmt("%.3e", x).
std::string fmt(const char* format, double v);

}  // namespace rccm
