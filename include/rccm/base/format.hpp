// A number as reports, tables and messages print it.
#pragma once

#include <string>
#include <vector>

namespace rccm {

/// `v` formatted by printf's `format` (one conversion of a double): fmt("%.3e", x).
std::string fmt(const char* format, double v);

/// Names as a phrase: "a, b, c" (empty for none).
std::string comma_list(const std::vector<std::string>& names);

}  // namespace rccm
