// Small helpers shared by the tests.
#pragma once

#include "rccm/base/config.hpp"
#include "rccm/fem/rectangle_mesh.hpp"
#include "rccm/io/config_reader.hpp"
#include "rccm/model/model.hpp"

#include <cstdio>
#include <fstream>
#include <string>
#include <unistd.h>

namespace rccm::test {

/// A config shipped in config/.
inline std::string shipped(const std::string& name) { return std::string(RCCM_SOURCE_DIR) + "/config/" + name; }

/// Writes `text` to a temporary .cfg file and returns its path.
inline std::string write_temp_config(const std::string& text) {
  char name[] = "/tmp/rccm_test_XXXXXX.cfg";
  const int fd = mkstemps(name, 4);
  ::close(fd);
  std::ofstream(name) << text;
  return name;
}

inline Config config_from_text(const std::string& text, const std::vector<std::string>& overrides = {}) {
  const std::string path = write_temp_config(text);
  Config c = load_config(path, overrides);
  std::remove(path.c_str());
  return c;
}

/// The model of a config on its built-in rectangle mesh, as `rccm run` builds it.
inline Model make_model(const Config& cfg) { return Model(cfg, make_rectangle(cfg.mesh)); }

}  // namespace rccm::test
