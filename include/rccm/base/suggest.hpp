// "Did you mean ...?" for a name that is not one of the known ones (config keys, node sets).
#pragma once

#include <string>
#include <vector>

namespace rccm {

/// "; did you mean 'x'?" for the known name nearest to `name` (at most 2 edits, case
/// ignored), else "; known here: a, b, c".
std::string suggestion(const std::string& name, const std::vector<std::string>& known);

}  // namespace rccm
