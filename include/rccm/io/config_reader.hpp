// Reading a config: libconfig text into the plain structs of base/config.hpp, with every
// range check; errors read "config/b1.cfg:14: interface.mu: must be >= 0 (got -0.3)".
#pragma once

#include "rccm/base/config.hpp"

#include <string>
#include <vector>

namespace rccm {

/// Reads and checks a config file; `overrides` are "path=value" strings (the command line's
/// --set). Throws InputError "file:line: setting: what is wrong".
Config load_config(const std::string& path, const std::vector<std::string>& overrides = {});

/// The same from the text of a config (`name` stands for the file in messages).
Config parse_config(const std::string& text, const std::string& name, const std::vector<std::string>& overrides = {});

/// The override "path=value" that sets `path` to the string `text` whatever it reads like
/// (-o 2024, -o .: a directory named like a number is still a string).
std::string string_override(const std::string& path, const std::string& text);

}  // namespace rccm
