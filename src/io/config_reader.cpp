// Reads a libconfig file into the plain structs of base/config.hpp, with every range check,
// one function per section. The only file of rccm that includes libconfig.
#include "rccm/io/config_reader.hpp"

#include "rccm/base/errors.hpp"
#include "rccm/base/memory.hpp"
#include "rccm/base/suggest.hpp"
#include "rccm/io/csv.hpp"
#include "rccm/io/result_writer.hpp"
#include "rccm/la/parallel.hpp"
#include "rccm/la/spd_solver.hpp"
#include "rccm/fem/gmsh_mesh.hpp"
#include "rccm/fem/rectangle_mesh.hpp"
#include "rccm/time/arkode_integrator.hpp"

#include <libconfig.h++>

#include <algorithm>
#include <filesystem>
#include <regex>
#include <fstream>
#include <iterator>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <initializer_list>
#include <sstream>

namespace rccm {

namespace {

using libconfig::Setting;

/// A number for a message: 3 significant digits.
std::string short_number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", v);
  return buf;
}

std::string type_name(const Setting& s) {
  switch (s.getType()) {
    case Setting::TypeInt:
    case Setting::TypeInt64: return "an integer";
    case Setting::TypeFloat: return "a number";
    case Setting::TypeString: return "a string";
    case Setting::TypeBoolean: return "a boolean";
    case Setting::TypeGroup: return "a group";
    case Setting::TypeArray: return "an array";
    case Setting::TypeList: return "a list";
    default: return "nothing";
  }
}

/// The file a setting or a syntax error comes from, as a path from the working directory:
/// libconfig 1.5 names an @include'd file as the line wrote it, relative to the top config's
/// directory (later versions put that directory in front themselves).
std::string source_path(const char* source, const std::string& top) {
  const std::filesystem::path dir = std::filesystem::path(top).parent_path();
  if (!source || source == top || source[0] == '/' || dir.empty() || std::string(source).rfind(dir.string() + "/", 0) == 0)
    return source ? source : top;
  return (dir / source).string();
}

/// Turns libconfig settings into values, with "file:line: path: message" errors.
class Reader {
 public:
  explicit Reader(std::string file) : file_(std::move(file)) {}

  [[noreturn]] void fail(const Setting& s, const std::string& what) const {
    std::ostringstream msg;
    const std::string path = s.isRoot() ? std::string("(top level)") : s.getPath();
    if (s.isRoot())
      msg << file_ << ": " << path << ": " << what;
    else if (s.getSourceLine() == 0)
      msg << "--set " << path << ": " << what;
    else
      msg << source_path(s.getSourceFile(), file_) << ":" << s.getSourceLine()
          << ": " << path << ": " << what;
    throw InputError(msg.str());
  }

  /// Fails on `s` unless `name` is one of `known`, suggesting the nearest one.
  void one_of(const Setting& s, const std::string& name, const std::vector<std::string>& known,
              const std::string& what) const {
    if (std::find(known.begin(), known.end(), name) == known.end()) fail(s, what + suggestion(name, known));
  }

  /// Rejects keys of a group that are not in `known`.
  void only(const Setting& group, const std::vector<std::string>& known) const {
    for (int i = 0; i < group.getLength(); ++i) {
      const Setting& child = group[i];
      one_of(child, child.getName() ? child.getName() : "", known, "unknown setting");
    }
  }

  const Setting& group(const Setting& parent, const char* name) const {
    if (!parent.exists(name)) fail(parent, std::string("missing section '") + name + "'");
    const Setting& s = parent[name];
    if (!s.isGroup()) fail(s, "must be a group { ... } (got " + type_name(s) + ")");
    return s;
  }

  const Setting* optional_group(const Setting& parent, const char* name) const {
    if (!parent.exists(name)) return nullptr;
    return &group(parent, name);
  }

  double number(const Setting& s) const {
    if (!s.isNumber()) fail(s, "must be a number (got " + type_name(s) + ")");
    const double v = s;
    if (!std::isfinite(v)) fail(s, "must be finite");
    return v;
  }

  double number(const Setting& g, const char* name) const {
    if (!g.exists(name)) fail(g, std::string("missing setting '") + name + "'");
    return number(g[name]);
  }

  double number(const Setting& g, const char* name, double fallback) const {
    return g.exists(name) ? number(g[name]) : fallback;
  }

  int integer(const Setting& g, const char* name, int fallback, bool required = false) const {
    if (!g.exists(name)) {
      if (required) fail(g, std::string("missing setting '") + name + "'");
      return fallback;
    }
    const Setting& s = g[name];
    if (s.getType() != Setting::TypeInt && s.getType() != Setting::TypeInt64)
      fail(s, "must be an integer (got " + type_name(s) + ")");
    const long long v = s;
    if (v < -2147483647LL || v > 2147483647LL) fail(s, "integer out of range");
    return static_cast<int>(v);
  }

  std::string text(const Setting& g, const char* name, const std::string& fallback,
                   bool required = false) const {
    if (!g.exists(name)) {
      if (required) fail(g, std::string("missing setting '") + name + "'");
      return fallback;
    }
    const Setting& s = g[name];
    if (s.getType() != Setting::TypeString) fail(s, "must be a string (got " + type_name(s) + ")");
    return s.c_str();
  }

  bool boolean(const Setting& g, const char* name, bool fallback) const {
    if (!g.exists(name)) return fallback;
    const Setting& s = g[name];
    if (s.getType() != Setting::TypeBoolean) fail(s, "must be true or false (got " + type_name(s) + ")");
    return s;
  }

  std::vector<double> numbers(const Setting& s) const {
    if (s.isNumber()) return {number(s)};
    if (!s.isArray() && !s.isList()) fail(s, "must be a number or an array [ ... ] of numbers");
    std::vector<double> out;
    for (int i = 0; i < s.getLength(); ++i) out.push_back(number(s[i]));
    return out;
  }

  /// A required array of numbers whose length is one of `lengths`; otherwise it "must be `what`".
  std::vector<double> array(const Setting& g, const char* name, const std::vector<std::size_t>& lengths,
                            const std::string& what) const {
    if (!g.exists(name)) fail(g, std::string("missing setting '") + name + "'");
    const Setting& s = g[name];
    const std::vector<double> v = numbers(s);
    if (s.isNumber() || std::find(lengths.begin(), lengths.end(), v.size()) == lengths.end()) fail(s, "must be " + what);
    return v;
  }

  /// A point or a direction of the mesh's dimension: `dim` numbers (z = 0 in 2D).
  std::array<double, 3> coordinates(const Setting& g, const char* name, int dim) const {
    const std::string n = std::to_string(dim);
    const std::vector<double> v = array(g, name, {std::size_t(dim)}, "an array of " + n + " numbers (the mesh is " + n + "D)");
    std::array<double, 3> out{};
    std::copy(v.begin(), v.end(), out.begin());
    return out;
  }

  /// A direction: `dim` numbers, not all zero, made unit.
  std::array<double, 3> direction(const Setting& g, const char* name, int dim) const {
    std::array<double, 3> v = coordinates(g, name, dim);
    const double len = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    check(len > 1e-12, g[name], "must be a nonzero vector", len);
    for (double& x : v) x /= len;
    return v;
  }

  /// A string that must be one of `choices`; returns its index.
  int choice(const Setting& g, const char* name, std::initializer_list<const char*> choices,
             int fallback) const {
    if (!g.exists(name)) return fallback;
    const std::string v = text(g, name, "");
    int k = 0;
    std::string all;
    for (const char* c : choices) {
      if (v == c) return k;
      all += std::string(k ? ", " : "") + "\"" + c + "\"";
      ++k;
    }
    fail(g[name], "must be one of " + all + " (got \"" + v + "\")");
  }

  void check(bool ok, const Setting& s, const std::string& rule, double got) const {
    if (ok) return;
    std::ostringstream m;
    m << rule << " (got " << got << ")";
    fail(s, m.str());
  }

 private:
  std::string file_;
};

/// Copies a parsed value (scalar, array, list or group) into `dst`'s parent under `name`.
void copy_value(const Setting& src, Setting& parent, const std::string& name) {
  if (parent.exists(name)) parent.remove(name);
  const bool in_list = parent.isList() || parent.isArray();
  Setting& dst = in_list ? parent.add(src.getType()) : parent.add(name, src.getType());
  switch (src.getType()) {
    case Setting::TypeInt: dst = static_cast<int>(src); break;
    case Setting::TypeInt64: dst = static_cast<long long>(src); break;
    case Setting::TypeFloat: dst = static_cast<double>(src); break;
    case Setting::TypeString: dst = src.c_str(); break;
    case Setting::TypeBoolean: dst = static_cast<bool>(src); break;
    default:
      for (int i = 0; i < src.getLength(); ++i)
        copy_value(src[i], dst, src[i].getName() ? src[i].getName() : "");
  }
}

/// libconfig's parse message, with the fix for its most common cause.
std::string syntax_hint(const std::string& error) {
  if (error.find("mismatched element type") != std::string::npos)
    return error + ": an array holds values of one type: numbers only, without quotes, and 1.0 (not 1) beside other decimals";
  return error;
}

/// libconfig 1.5 reads an integer literal beyond 32 bits without an L suffix as garbage
/// (100000000000000000000 becomes -1, 4294967296 becomes 0): every integer literal of the
/// text outside strings and comments is checked first. `where(line)` names its place.
void check_integer_literals(const std::string& text, const std::function<std::string(int)>& where) {
  int line = 1;
  for (std::size_t k = 0; k < text.size(); ++k) {
    const char c = text[k];
    if (c == '\n') ++line;
    if (c == '"') {  // a string: to its closing quote (\" escapes)
      for (++k; k < text.size() && text[k] != '"'; ++k) {
        if (text[k] == '\\') ++k;
        else if (text[k] == '\n') ++line;
      }
    } else if (c == '#' || (c == '/' && k + 1 < text.size() && text[k + 1] == '/')) {
      while (k < text.size() && text[k] != '\n') ++k;
      --k;
    } else if (c == '/' && k + 1 < text.size() && text[k + 1] == '*') {
      for (k += 2; k + 1 < text.size() && !(text[k] == '*' && text[k + 1] == '/'); ++k)
        if (text[k] == '\n') ++line;
      ++k;
    } else if (std::isdigit(static_cast<unsigned char>(c)) &&
               (k == 0 || !(std::isalnum(static_cast<unsigned char>(text[k - 1])) || text[k - 1] == '.' ||
                            text[k - 1] == '_'))) {
      std::size_t end = k;
      while (end < text.size() && std::isalnum(static_cast<unsigned char>(text[end]))) ++end;
      const std::string token = text.substr(k, end - k);
      const bool decimal_integer =
          std::all_of(token.begin(), token.end(), [](unsigned char ch) { return std::isdigit(ch); }) &&
          (end >= text.size() || text[end] != '.');
      if (decimal_integer) {
        const bool negative = k > 0 && text[k - 1] == '-';
        // Beyond 2^31 - 1 (or 2^31 negative): compare as digit strings, no overflow.
        const std::string limit = negative ? "2147483648" : "2147483647";
        const std::string digits = token.substr(std::min(token.find_first_not_of('0'), token.size() - 1));
        if (digits.size() > limit.size() || (digits.size() == limit.size() && digits > limit))
          throw InputError(where(line) + ": the integer " + (negative ? "-" : "") + token +
                           " is beyond what libconfig reads as an integer (2147483647): a count must be below it, and a real "
                           "number may be written with a decimal point (" + (negative ? "-" : "") + token + ".0)");
      }
      k = end - 1;
    }
  }
}

/// `text` as a libconfig string literal: quoted, its quotes and backslashes escaped.
std::string string_literal(const std::string& text) {
  std::string quoted = "\"";
  for (char c : text) quoted += (c == '"' || c == '\\') ? std::string("\\") + c : std::string(1, c);
  return quoted + "\"";
}

/// A setting name of a --set path: letters, digits, '_', '-', '*', starting with a letter.
bool setting_name(const std::string& part) {
  return !part.empty() && std::isalpha(static_cast<unsigned char>(part[0])) &&
         std::all_of(part.begin(), part.end(),
                     [](unsigned char ch) { return std::isalnum(ch) || ch == '_' || ch == '-' || ch == '*'; });
}

/// Applies one "--set path=value"; the value is parsed by libconfig itself, and a value that
/// is no libconfig value (output.directory=/tmp/x, solver.form=jacobi) is a string: the
/// shell has eaten its quotes. A path part [k] selects the k-th element of a list
/// (loads.[0].value).
void apply_override(libconfig::Config& cfg, const std::string& item) {
  const auto eq = item.find('=');
  if (eq == std::string::npos || eq == 0)
    throw InputError("--set " + item + ": expected path=value, e.g. interface.alpha=0.1");
  const std::string path = item.substr(0, eq), given = item.substr(eq + 1);
  const auto fail = [&](const std::string& what) -> InputError { return InputError("--set " + path + ": " + what); };
  check_integer_literals(given, [&](int) { return "--set " + path; });
  libconfig::Config value;
  value.setAutoConvert(true);
  const bool structured = !given.empty() && std::string("[({\"").find(given[0]) != std::string::npos;
  try {
    value.readString("v = " + given + ";");
  } catch (const libconfig::ParseException& e) {
    if (structured || given.empty())
      throw fail("cannot parse the value '" + given + "' (" + syntax_hint(e.getError()) + ")");
    value.readString("v = " + string_literal(given) + ";");
  }
  if (value.getRoot().getLength() != 1)  // "10;steps=5": libconfig reads two settings, the second would be lost
    throw fail("the value '" + given + "' holds more than one setting: give each its own --set");
  std::vector<std::string> parts(1);
  for (char c : path) {
    if (c == '.') parts.emplace_back();
    else parts.back().push_back(c);
  }
  Setting* parent = &cfg.getRoot();
  for (std::size_t k = 0; k + 1 < parts.size(); ++k) {
    const std::string& part = parts[k];
    if (part.size() > 2 && part.front() == '[' && part.back() == ']') {  // loads.[0].value: a list element
      const std::string digits = part.substr(1, part.size() - 2);
      const bool number = std::all_of(digits.begin(), digits.end(), [](unsigned char ch) { return std::isdigit(ch); });
      if (!parent->isList()) throw fail("'" + part + "' indexes a list; the setting before it is not one");
      if (!number || digits.size() > 9 || std::stol(digits) >= parent->getLength())
        throw fail("'" + part + "': the list has " + std::to_string(parent->getLength()) + " element(s), numbered from 0");
      parent = &(*parent)[static_cast<int>(std::stol(digits))];
    } else {
      if (!setting_name(part)) throw fail("'" + part + "' is not a setting name (letters, digits and '_', from a letter)");
      if (!parent->isGroup()) throw fail("'" + part + "' must follow a group");
      if (!parent->exists(part)) parent->add(part, Setting::TypeGroup);
      parent = &(*parent)[part.c_str()];
    }
    if (!parent->isGroup() && !parent->isList()) throw fail("'" + part + "' is not a group or a list");
  }
  if (!setting_name(parts.back()))
    throw fail("'" + parts.back() + "' is not a setting name (letters, digits and '_', from a letter)");
  if (!parent->isGroup()) throw fail("a list element is set by its index, e.g. loads.[0].value");
  // A load is a ramp (value) or a table: setting one replaces the other.
  for (const auto& [set, other] : {std::pair<const char*, const char*>{"value", "table"}, {"table", "value"}})
    if (parts.back() == set && parent->exists(other)) parent->remove(other);
  copy_value(value.lookup("v"), *parent, parts.back());
}

TimeFunction read_amplitude(const Reader& r, const Setting& load, double T) {
  const bool has_value = load.exists("value"), has_table = load.exists("table");
  if (has_value == has_table) r.fail(load, "give exactly one of 'value' (a ramp value*t/T) or 'table'");
  if (has_value) return {{0.0, T}, {0.0, r.number(load, "value")}};
  const Setting& table = load["table"];
  if (!table.isList() && !table.isArray())
    r.fail(table, "must be a list of (t, value) pairs, e.g. ( (0.0, 0.0), (10.0, 0.3) )");
  TimeFunction f;
  for (int i = 0; i < table.getLength(); ++i) {
    const std::vector<double> p = r.numbers(table[i]);
    if (p.size() != 2) r.fail(table[i], "each entry must be a pair (t, value)");
    if (!f.t.empty() && p[0] <= f.t.back()) r.fail(table[i], "times must increase");
    f.t.push_back(p[0]);
    f.v.push_back(p[1]);
  }
  if (f.t.empty()) r.fail(table, "must have at least one (t, value) pair");
  return f;
}

/// The box node sets of mesh.node_sets: 4 numbers (x and y ranges, every z), or 6 on a 3D mesh.
std::vector<NodeSetDef> read_box_sets(const Reader& r, const Setting& m, bool rectangle, int dim) {
  std::vector<NodeSetDef> out;
  if (!m.exists("node_sets")) return out;
  const Setting& sets = m["node_sets"];
  if (!sets.isList()) r.fail(sets, "must be a list ( { name = ...; box = [...]; }, ... )");
  for (int i = 0; i < sets.getLength(); ++i) {
    const Setting& s = sets[i];
    if (!s.isGroup()) r.fail(s, "must be a group { name = ...; box = [xmin, xmax, ymin, ymax]; }");
    r.only(s, {"name", "box"});
    const bool solid = dim == 3;
    NodeSetDef d{r.text(s, "name", "", true),
                 r.array(s, "box", solid ? std::vector<std::size_t>{4, 6} : std::vector<std::size_t>{4},
                         solid ? "an array of 4 numbers [xmin, xmax, ymin, ymax] (every z) or 6 [xmin, xmax, ymin, ymax, "
                                 "zmin, zmax]"
                               : "an array of 4 numbers [xmin, xmax, ymin, ymax] (a z range needs a 3D mesh)")};
    const bool z_range = d.box.size() == 6;
    if (d.name.empty()) r.fail(s["name"], "must not be empty");
    const std::vector<std::string>& builtin = rectangle_set_names();
    if (rectangle && std::find(builtin.begin(), builtin.end(), d.name) != builtin.end())
      r.fail(s["name"], "'" + d.name + "' is a node set every rectangle has; give the box set another name");
    for (const NodeSetDef& earlier : out)
      if (earlier.name == d.name) r.fail(s["name"], "a node set named '" + d.name + "' is already defined above");
    if (d.box[0] > d.box[1] || d.box[2] > d.box[3] || (z_range && d.box[4] > d.box[5]))
      r.fail(s["box"], z_range ? "needs xmin <= xmax, ymin <= ymax and zmin <= zmax" : "needs xmin <= xmax and ymin <= ymax");
    out.push_back(d);
  }
  return out;
}

/// A hash of a file's text, so that a checkpoint restarts a run on the same mesh only.
std::string file_hash(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  return std::to_string(text.size()) + ":" + std::to_string(std::hash<std::string>()(text));
}

/// mesh.rotation: an angle in degrees in 2D (about z); a group { axis = [x, y, z]; angle; } in 3D.
void read_rotation(const Reader& r, const Setting& m, MeshParams& p) {
  if (!m.exists("rotation")) return;
  const Setting& g = m["rotation"];
  if (p.dim() == 2) {
    if (g.isGroup()) r.fail(g, "a 2D mesh turns in its plane: give the angle in degrees (rotation = 30.0;)");
    p.rotation = r.number(m, "rotation");
    return;
  }
  if (!g.isGroup()) r.fail(g, "a 3D mesh turns about an axis: rotation = { axis = [x, y, z]; angle = degrees; }");
  r.only(g, {"axis", "angle"});
  p.axis = r.direction(g, "axis", 3);
  p.rotation = r.number(g, "angle");
}

/// A length, a modulus, an interface stiffness or a duration (mm, MPa, MPa/mm, s) below this is
/// no physical magnitude in the config's units (a picometre, a millipascal, a nanosecond of a
/// quasi-static process), and the others' round-off swallows it. Refused here, naming the
/// setting: a mesh of 1e-300 mm was refused as an interface.boundary off the boundary, a
/// modulus of 1e-300 MPa as an ill-conditioned stiffness at loads, a time.T of 1e-300 s as
/// output.times beyond it.
constexpr double min_magnitude = 1e-9;
void check_magnitude(const Reader& r, const Setting& s, double value, const char* unit) {
  r.check(value >= min_magnitude, s, std::string("must be at least 1e-9 ") + unit +
                                         " (the units are mm, N, MPa, s: a smaller value is no physical one)", value);
}

MeshParams read_mesh(const Reader& r, const Setting& root, const std::string& config_dir) {
  const Setting& m = r.group(root, "mesh");
  MeshParams p;
  // The settings of the other kind of mesh source, named as such rather than as unknown.
  for (const char* key : {"size", "nx", "ny", "nz", "element"})
    if (m.exists("file") && m.exists(key)) r.fail(m[key], "sets the built-in mesh: a mesh file (mesh.file) brings its own cells; leave it out");
  for (const char* key : {"refine", "parameters"})
    if (!m.exists("file") && m.exists(key)) r.fail(m[key], "applies to a gmsh file (mesh.file), not to the built-in mesh");
  if (m.exists("file")) {  // a gmsh file
    r.only(m, {"file", "refine", "parameters", "node_sets", "rotation", "origin"});
    const std::string file = r.text(m, "file", "", true);
    if (file.empty()) r.fail(m["file"], "must not be empty");
    p.file = file[0] == '/' || config_dir.empty() ? file : config_dir + "/" + file;
    std::error_code ec;
    if (std::filesystem::is_directory(p.file, ec)) r.fail(m["file"], p.file + " is a directory, not a mesh file");
    if (!std::ifstream(p.file)) r.fail(m["file"], "cannot read " + p.file + " (a mesh file is found relative to the config)");
    p.contents = file_hash(p.file);
    p.refine = r.integer(m, "refine", 0);
    if (m.exists("refine")) r.check(p.refine >= 0 && p.refine <= 6, m["refine"], "must be in [0, 6] (each level has 4 times the cells, 8 times in 3D)", p.refine);
    if (m.exists("parameters")) {
      const Setting& g = r.group(m, "parameters");
      for (int i = 0; i < g.getLength(); ++i) p.parameters[g[i].getName()] = r.number(g[i]);
    }
    try {
      p.dimension = read_gmsh_dimension(p);
    } catch (const InputError& e) {
      r.fail(m["file"], e.what());
    }
  } else {
    r.only(m, {"origin", "size", "nx", "ny", "nz", "element", "rotation", "node_sets"});
    // [x, y]: the rectangle; [x, y, z]: the box (3D).
    const bool box = m.exists("size") && m["size"].isArray() && m["size"].getLength() == 3;
    const std::array<double, 3> size = r.coordinates(m, "size", box ? 3 : 2);
    p.size = {size[0], size[1]};
    p.depth = size[2];
    for (int k = 0; k < (box ? 3 : 2); ++k) {
      r.check(size[k] > 0, m["size"], "lengths must be > 0", size[k]);
      check_magnitude(r, m["size"], size[k], "mm");
    }
    p.nx = r.integer(m, "nx", 0, true);
    p.ny = r.integer(m, "ny", 0, true);
    r.check(p.nx >= 1, m["nx"], "must be >= 1", p.nx);
    r.check(p.ny >= 1, m["ny"], "must be >= 1", p.ny);
    if (box) {
      p.dimension = 3;
      p.nz = r.integer(m, "nz", 0, true);
      r.check(p.nz >= 1, m["nz"], "must be >= 1", p.nz);
      p.element = static_cast<ElementType>(r.choice(m, "element", {"T3", "Q4", "H8"}, 2));
      if (p.element != ElementType::H8) r.fail(m["element"], "a box (size with 3 numbers) is meshed with \"H8\" cells");
    } else {
      if (m.exists("nz")) r.fail(m["nz"], "applies to a box: give size three numbers [x, y, z]");
      p.element = static_cast<ElementType>(r.choice(m, "element", {"T3", "Q4", "H8"}, 0));
      if (p.element == ElementType::H8) r.fail(m["element"], "H8 cells fill a box: give size three numbers [x, y, z] and nz");
    }
  }
  if (m.exists("origin")) p.origin = r.coordinates(m, "origin", p.dim());
  const std::array<double, 3> extent{p.size[0], p.size[1], p.depth};
  for (int k = 0; k < p.dim(); ++k)
    r.check(std::abs(p.origin[k]) + extent[k] < mesh_reach, m.exists("size") ? m["size"] : m, "the mesh must lie within 1e15 mm of 0",
            extent[k]);
  if (p.file.empty()) {
    // Refused up front rather than failing after minutes.
    const double nodes = (p.nx + 1.0) * (p.ny + 1.0) * (p.nz + 1.0), dofs = p.dim() * nodes;
    const std::string shortfall =
        memory_shortfall(assembly_bytes(dofs), "a " + std::to_string(p.nx) + " x " + std::to_string(p.ny) +
                                                   (p.nz ? " x " + std::to_string(p.nz) : "") + " mesh (" + short_number(dofs) + " unknowns)");
    if (!shortfall.empty()) r.fail(m["nx"], shortfall + "; use fewer cells");
  }
  read_rotation(r, m, p);
  p.node_sets = read_box_sets(r, m, p.file.empty(), p.dimension);
  return p;
}

/// A modulus (MPa) or an interface stiffness (MPa/mm) above this is a typo (a billion times
/// diamond's Young's modulus), and the stiffness assembled from it overflows.
constexpr double max_modulus = 1e15;
void check_modulus(const Reader& r, const Setting& s, double value, const char* unit) {
  r.check(value <= max_modulus, s, std::string("must be at most 1e15 ") + unit + " (beyond, the stiffness overflows)", value);
  check_magnitude(r, s, value, unit);
}

/// An orthotropic material's settings besides E1 (which makes a material orthotropic).
const std::vector<std::string> orthotropic_settings = {"E2",  "E3",  "nu12", "nu13",  "nu23", "G12",
                                                       "G13", "G23", "angle", "axis3"};

MaterialParams read_material(const Reader& r, const Setting& mat, int dim) {
  if (!mat.isGroup()) r.fail(mat, "must be a group { E = ...; nu = ...; } (or E1, E2, E3, nu12, nu13, nu23, G12; 3D: G13, G23)");
  MaterialParams p;
  p.path = mat.getPath();
  p.hypothesis = static_cast<Hypothesis>(r.choice(mat, "hypothesis", {"plane_strain", "plane_stress", "axisymmetric"}, 0));
  p.orthotropic = mat.exists("E1");
  if (dim == 3 && mat.exists("hypothesis")) r.fail(mat["hypothesis"], "a 3D body has no plane hypothesis: leave it out");
  for (const char* isotropic : {"E", "nu"})  // both kinds of material at once: not a typo of E1
    if (p.orthotropic && mat.exists(isotropic))
      r.fail(mat[isotropic], "an isotropic setting beside E1: give E and nu (isotropic) or E1, E2, E3, nu12, ... "
                             "(orthotropic), not both");
  if (!p.orthotropic) {
    for (const std::string& orthotropic : orthotropic_settings)
      if (mat.exists(orthotropic))
        r.fail(mat[orthotropic.c_str()], "a setting of an orthotropic material, and this one is isotropic (E, nu): an "
                                 "orthotropic material gives E1, E2, E3, nu12, nu13, nu23, G12 (3D: G13, G23) instead of E and nu");
    r.only(mat, {"E", "nu", "hypothesis"});
    p.E = r.number(mat, "E");
    r.check(p.E > 0, mat["E"], "must be > 0", p.E);
    check_modulus(r, mat["E"], p.E, "MPa");
    p.nu = r.number(mat, "nu");
    r.check(p.nu > -1 && p.nu < 0.5, mat["nu"], "must be in (-1, 0.5)", p.nu);
    return p;
  }
  std::vector<std::string> known = {"E1"};
  known.insert(known.end(), orthotropic_settings.begin(), orthotropic_settings.end());
  known.push_back("hypothesis");
  r.only(mat, known);
  for (auto [name, v] : {std::pair<const char*, double*>{"E1", &p.E1}, {"E2", &p.E2}, {"E3", &p.E3}, {"G12", &p.G12}}) {
    *v = r.number(mat, name);
    r.check(*v > 0, mat[name], "must be > 0", *v);
    check_modulus(r, mat[name], *v, "MPa");
  }
  // The out-of-plane shears: a 3D body needs them, a plane one does not use them.
  for (auto [name, v] : {std::pair<const char*, double*>{"G13", &p.G13}, {"G23", &p.G23}}) {
    if (dim == 2 && mat.exists(name)) r.fail(mat[name], "is the out-of-plane shear modulus of a 3D body: a plane body does not use it, leave it out");
    if (dim == 2) continue;
    if (!mat.exists(name)) r.fail(mat, std::string("missing setting '") + name + "': a 3D orthotropic body needs G12, G13 and G23");
    *v = r.number(mat, name);
    r.check(*v > 0, mat[name], "must be > 0", *v);
    check_modulus(r, mat[name], *v, "MPa");
  }
  p.nu12 = r.number(mat, "nu12");
  p.nu13 = r.number(mat, "nu13");
  p.nu23 = r.number(mat, "nu23");
  p.angle = r.number(mat, "angle", 0.0);
  if (dim == 2 && mat.exists("axis3"))
    r.fail(mat["axis3"], "turns the material axes of a 3D body: a plane body's axis 3 is z, leave it out");
  if (mat.exists("axis3")) p.axis3 = r.direction(mat, "axis3", 3);
  // A positive definite compliance (each nu_ij^2 < E_i / E_j, and the determinant of the
  // normal block positive): otherwise no strain energy is positive.
  const double n21 = p.nu12 * p.E2 / p.E1, n31 = p.nu13 * p.E3 / p.E1, n32 = p.nu23 * p.E3 / p.E2;
  const double det = 1 - p.nu12 * n21 - p.nu23 * n32 - p.nu13 * n31 - 2 * n21 * n32 * p.nu13;
  for (auto [name, ok] : {std::pair<const char*, bool>{"nu12", p.nu12 * p.nu12 < p.E1 / p.E2},
                          {"nu13", p.nu13 * p.nu13 < p.E1 / p.E3}, {"nu23", p.nu23 * p.nu23 < p.E2 / p.E3}})
    if (!ok) r.fail(mat[name], "is too large for the moduli: the material would not be stable (nu_ij^2 < E_i / E_j)");
  if (det <= 0)
    r.fail(mat, "the Poisson's ratios make the material unstable (1 - nu12 nu21 - nu23 nu32 - nu13 nu31 - 2 nu21 nu32 nu13 = " +
                    short_number(det) + " <= 0)");
  return p;
}

/// The bodies and their materials: `material` for every body, or `bodies` by name.
std::vector<BodyParams> read_bodies(const Reader& r, const Setting& root, int dim) {
  const bool one = root.exists("material"), several = root.exists("bodies");
  if (one == several) r.fail(root, "give exactly one of 'material' (one material for every body) or 'bodies' (one per body of the mesh)");
  if (one) return {{"", read_material(r, r.group(root, "material"), dim)}};
  const Setting& list = root["bodies"];
  if (!list.isList() || list.getLength() == 0) r.fail(list, "must be a list ( { name = \"...\"; material = { ... }; }, ... )");
  std::vector<BodyParams> out;
  for (int i = 0; i < list.getLength(); ++i) {
    const Setting& b = list[i];
    if (!b.isGroup()) r.fail(b, "must be a group { name = \"...\"; material = { ... }; }");
    r.only(b, {"name", "material"});
    BodyParams p{r.text(b, "name", "", true), read_material(r, r.group(b, "material"), dim)};
    for (const BodyParams& earlier : out)
      if (earlier.name == p.name) r.fail(b["name"], "body '" + p.name + "' has a material already");
    const Setting& mat = b["material"];
    if (!out.empty() && p.material.hypothesis != out.front().material.hypothesis)
      r.fail(mat.exists("hypothesis") ? mat["hypothesis"] : mat, "the hypothesis (plane strain, plane stress or axisymmetric) must be the same for every body");
    out.push_back(p);
  }
  return out;
}

InterfaceParams read_interface(const Reader& r, const Setting& in, int dim) {
  if (!in.isGroup()) r.fail(in, "must be a group { boundary = ...; Cn = ...; ... }");
  r.only(in, {"boundary", "normal", "circle", "opposite", "tolerance", "precrack", "Cn", "Ct", "w", "alpha", "mu", "beta0", "g0"});
  InterfaceParams p;
  p.path = in.getPath();
  p.boundary = r.text(in, "boundary", "", true);
  const int facings = in.exists("normal") + in.exists("circle") + in.exists("opposite");
  if (facings > 1) r.fail(in, "give one of 'normal' (a rigid line), 'circle' (a rigid circle) or 'opposite' (another body)");
  if (in.exists("normal")) p.normal = r.direction(in, "normal", dim);
  if (in.exists("circle")) {
    const Setting& c = r.group(in, "circle");
    r.only(c, {"centre", "radius", "side", "axis"});
    if (c.exists("axis")) {
      if (dim == 2) r.fail(c["axis"], "a circle in 2D is a cylinder along z already: leave 'axis' out (3D: a cylinder's axis)");
      p.axis = r.direction(c, "axis", 3);
    }
    p.facing = Facing::Circle;
    p.centre = r.coordinates(c, "centre", dim);
    p.radius = r.number(c, "radius");
    r.check(p.radius > 0, c["radius"], "must be > 0", p.radius);
    if (!c.exists("side")) r.fail(c, "missing setting 'side': \"inside\" (the body fills a circular hole) or \"outside\" (it wraps a cylinder)");
    p.inside = r.choice(c, "side", {"inside", "outside"}, 0) == 0;
  }
  if (in.exists("opposite")) {
    p.facing = Facing::Body;
    p.opposite = r.text(in, "opposite", "");
    if (p.opposite.empty()) r.fail(in["opposite"], "must name the node set of the other body along the interface");
    if (p.opposite == p.boundary) r.fail(in["opposite"], "must be another node set than 'boundary'");
  }
  p.tolerance = r.number(in, "tolerance", 0.0);
  if (in.exists("tolerance")) {
    r.check(p.tolerance > 0, in["tolerance"], "must be > 0", p.tolerance);
    if (p.facing != Facing::Body) r.fail(in["tolerance"], "applies to an interface between two bodies ('opposite')");
  }
  p.precrack = r.text(in, "precrack", "");
  if (in.exists("precrack") && p.precrack.empty()) r.fail(in["precrack"], "must name a node set");
  if (in.exists("g0") && p.facing != Facing::Line)
    r.fail(in["g0"], "the gap of a circle or of two bodies comes from their geometry: leave g0 out");
  p.Cn = r.number(in, "Cn");
  r.check(p.Cn > 0, in["Cn"], "must be > 0", p.Cn);
  check_modulus(r, in["Cn"], p.Cn, "MPa/mm");
  p.Ct = r.number(in, "Ct");
  r.check(p.Ct > 0, in["Ct"], "must be > 0", p.Ct);
  check_modulus(r, in["Ct"], p.Ct, "MPa/mm");
  p.w = r.number(in, "w");
  r.check(p.w >= 0, in["w"], "must be >= 0", p.w);
  p.alpha = r.number(in, "alpha", p.alpha);
  if (in.exists("alpha")) r.check(p.alpha >= 0, in["alpha"], "must be >= 0", p.alpha);
  p.mu = r.number(in, "mu");
  r.check(p.mu >= 0, in["mu"], "must be >= 0", p.mu);
  r.check(p.mu <= 10, in["mu"], "must be at most 10 (friction coefficients of real interfaces are below 2)", p.mu);
  if (in.exists("beta0")) {
    p.beta0 = r.numbers(in["beta0"]);
    if (p.beta0.empty()) r.fail(in["beta0"], "must not be empty");
    for (double b : p.beta0) r.check(b >= 0 && b <= 1, in["beta0"], "must be in [0, 1]", b);
  }
  if (in.exists("g0")) {
    p.g0 = r.numbers(in["g0"]);
    if (p.g0.empty()) r.fail(in["g0"], "must not be empty");
    for (double g : p.g0) r.check(g >= 0, in["g0"], "must be >= 0", g);
  }
  return p;
}

/// `interface` (one) or `interfaces` (a list).
std::vector<InterfaceParams> read_interfaces(const Reader& r, const Setting& root, int dim) {
  const bool one = root.exists("interface"), several = root.exists("interfaces");
  if (one == several) r.fail(root, "give exactly one of 'interface' (one interface) or 'interfaces' (a list of them)");
  if (one) return {read_interface(r, r.group(root, "interface"), dim)};
  const Setting& list = root["interfaces"];
  if (!list.isList() || list.getLength() == 0) r.fail(list, "must be a list ( { boundary = ...; ... }, ... )");
  std::vector<InterfaceParams> out;
  for (int i = 0; i < list.getLength(); ++i) out.push_back(read_interface(r, list[i], dim));
  return out;
}

TimeParams read_time(const Reader& r, const Setting& root) {
  const Setting& t = r.group(root, "time");
  r.only(t, {"T", "steps"});
  TimeParams p;
  p.T = r.number(t, "T");
  r.check(p.T > 0, t["T"], "must be > 0", p.T);
  r.check(p.T <= 1e15, t["T"], "must be at most 1e15 s (the steps of a longer run are below round-off)", p.T);
  check_magnitude(r, t["T"], p.T, "s");
  p.steps = r.integer(t, "steps", p.steps);
  if (t.exists("steps")) r.check(p.steps >= 1, t["steps"], "must be >= 1", p.steps);
  // Each fixed step keeps its time and a record of its work (64 bytes).
  if (64.0 * p.steps > available_memory())
    r.fail(t["steps"], std::to_string(p.steps) + " steps need about " + short_number(64e-9 * p.steps) +
                           " GB, the machine has " + short_number(available_memory() / 1e9) + " GB available");
  return p;
}

std::vector<LoadParams> read_loads(const Reader& r, const Setting& root, double T, int dim) {
  if (!root.exists("loads")) r.fail(root, "missing section 'loads'");
  const Setting& loads = root["loads"];
  if (!loads.isList()) r.fail(loads, "must be a list ( { node_set = ...; type = ...; ... }, ... )");
  if (loads.getLength() == 0) r.fail(loads, "must hold at least one load (with none, nothing moves)");
  std::vector<LoadParams> out;
  for (int i = 0; i < loads.getLength(); ++i) {
    const Setting& l = loads[i];
    if (!l.isGroup()) r.fail(l, "must be a group { node_set = ...; type = ...; component = ...; value = ...; }");
    r.only(l, {"node_set", "type", "component", "value", "table"});
    LoadParams p;
    p.path = l.getPath();
    p.node_set = r.text(l, "node_set", "", true);
    if (!l.exists("type")) r.fail(l, "missing setting 'type'");
    p.kind = static_cast<LoadKind>(r.choice(l, "type", {"displacement", "force", "traction", "pressure"}, 0));
    if (p.kind == LoadKind::Pressure) {
      if (l.exists("component")) r.fail(l["component"], "a pressure acts along the boundary's normal: leave 'component' out");
    } else {
      if (!l.exists("component")) r.fail(l, "missing setting 'component'");
      p.component = r.choice(l, "component", {"x", "y", "z"}, 0);
      if (p.component == 2 && dim == 2) r.fail(l["component"], "\"z\" is a component of a 3D mesh (a box, or a gmsh file with a Physical Volume)");
    }
    p.amplitude = read_amplitude(r, l, T);
    out.push_back(p);
  }
  return out;
}

SolverParams read_solver(const Reader& r, const Setting& root, int dim) {
  SolverParams S;
  // The exact step in 3D rebuilds its dense (3n)^2 system whenever slip directions turn:
  // sweeps alone by default there (README "3D", measured 8x faster on the corner peel).
  S.active_set = dim == 2;
  // The sweeps alone (3D) need 2-3 times fewer passes late in a peel once K0's springs follow
  // the damage (docs/PERFORMANCE.md); the 2D exact step does not need it.
  S.springs_follow_beta = dim == 3;
  // Each block of neighbouring pairs swept twice per sweep: a third fewer sweeps over a 3D
  // surface, where W0 couples a pair's neighbours strongly all around (docs/PERFORMANCE.md).
  S.block_sweeps = dim == 3 ? 2 : 1;
  const Setting* s = r.optional_group(root, "solver");
  if (!s) return S;
  r.only(*s, {"method", "over_relaxation", "tolerance", "max_iterations", "local_iterations", "form", "anderson", "block_sweeps", "rho", "relaxation",
              "active_set", "active_set_max_nodes", "compressed_min_nodes", "springs_follow_beta", "linear", "linear_tolerance", "out_of_core"});
  S.method = static_cast<ContactMethod>(r.choice(*s, "method", {"bipotential", "rccm", "newton"}, 0));
  S.over_relaxation = r.number(*s, "over_relaxation", S.over_relaxation);
  if (s->exists("over_relaxation"))
    r.check(S.over_relaxation > 0 && S.over_relaxation < 2, (*s)["over_relaxation"], "must be in (0, 2)", S.over_relaxation);
  S.tolerance = r.number(*s, "tolerance", S.tolerance);
  if (s->exists("tolerance")) r.check(S.tolerance > 0 && S.tolerance < 1, (*s)["tolerance"], "must be in (0, 1)", S.tolerance);
  S.max_iterations = r.integer(*s, "max_iterations", S.max_iterations);
  if (s->exists("max_iterations")) r.check(S.max_iterations >= 1, (*s)["max_iterations"], "must be >= 1", S.max_iterations);
  S.local_iterations = r.integer(*s, "local_iterations", S.local_iterations);
  if (s->exists("local_iterations"))
    r.check(S.local_iterations >= 1, (*s)["local_iterations"], "must be >= 1", S.local_iterations);
  S.form = static_cast<SweepForm>(r.choice(*s, "form", {"gauss-seidel", "jacobi"}, 0));
  S.anderson = r.integer(*s, "anderson", S.anderson);
  if (s->exists("anderson"))
    r.check(S.anderson >= 0 && S.anderson <= 50, (*s)["anderson"], "must be in [0, 50]", S.anderson);
  S.block_sweeps = r.integer(*s, "block_sweeps", S.block_sweeps);
  if (s->exists("block_sweeps"))
    r.check(S.block_sweeps >= 1 && S.block_sweeps <= 20, (*s)["block_sweeps"], "must be in [1, 20]", S.block_sweeps);
  S.rho = static_cast<RhoRule>(r.choice(*s, "rho", {"eigen", "paper"}, 0));
  S.relaxation = r.number(*s, "relaxation", S.relaxation);
  if (s->exists("relaxation"))
    r.check(S.relaxation > 0 && S.relaxation <= 1, (*s)["relaxation"], "must be in (0, 1]", S.relaxation);
  S.active_set = r.boolean(*s, "active_set", S.active_set);
  S.springs_follow_beta = r.boolean(*s, "springs_follow_beta", S.springs_follow_beta);
  S.active_set_max_nodes = r.integer(*s, "active_set_max_nodes", S.active_set_max_nodes);
  if (s->exists("active_set_max_nodes"))
    r.check(S.active_set_max_nodes >= 0, (*s)["active_set_max_nodes"], "must be >= 0", S.active_set_max_nodes);
  S.compressed_min_nodes = r.integer(*s, "compressed_min_nodes", S.compressed_min_nodes);
  if (s->exists("compressed_min_nodes"))
    r.check(S.compressed_min_nodes >= 0, (*s)["compressed_min_nodes"], "must be >= 0", S.compressed_min_nodes);
  // "auto" read as the solver it stands for in this run: who reads solver.linear_tolerance
  // (unused_settings) follows the solver that runs, not the word.
  S.linear.kind = chosen_linear_solver(static_cast<LinearSolver>(r.choice(*s, "linear", {"auto", "cholmod", "mumps", "cg-gamg"}, 0)));
  if (S.linear.kind == LinearSolver::Cholmod && parallel::size() > 1)
    r.fail((*s)["linear"], "\"cholmod\" solves in one process; under mpirun (" + std::to_string(parallel::size()) +
                              " processes) use \"mumps\" or \"cg-gamg\", or \"auto\"");
  S.linear.tolerance = r.number(*s, "linear_tolerance", S.linear.tolerance);
  if (s->exists("linear_tolerance"))
    r.check(S.linear.tolerance > 0 && S.linear.tolerance < 1, (*s)["linear_tolerance"], "must be in (0, 1)",
            S.linear.tolerance);
  S.linear.out_of_core = r.boolean(*s, "out_of_core", S.linear.out_of_core);
  return S;
}

IntegratorParams read_integrator(const Reader& r, const Setting& root) {
  IntegratorParams A;
  const Setting* g = r.optional_group(root, "integrator");
  if (!g) return A;
  r.only(*g, {"method", "scheme", "table", "rtol", "atol", "max_step", "initial_step", "fixed_step", "min_step",
              "max_steps", "fixed_point_tolerance", "fixed_point_iterations"});
  A.method = static_cast<Method>(r.choice(*g, "method", {"arkode", "euler", "rate-independent", "contact-only"}, 0));
  A.scheme = static_cast<ArkodeScheme>(r.choice(*g, "scheme", {"dirk", "erk"}, 0));
  A.table = r.text(*g, "table", "");
  // A number that must be > 0 (strict) or >= 0.
  const auto sign_checked = [&](const char* key, double& v, bool strict) {
    v = r.number(*g, key, v);
    if (g->exists(key)) r.check(strict ? v > 0 : v >= 0, (*g)[key], strict ? "must be > 0" : "must be >= 0", v);
  };
  sign_checked("rtol", A.rtol, true);
  sign_checked("atol", A.atol, true);
  sign_checked("max_step", A.max_step, false);
  sign_checked("initial_step", A.initial_step, false);
  sign_checked("fixed_step", A.fixed_step, false);
  sign_checked("min_step", A.min_step, false);
  A.max_steps = r.integer(*g, "max_steps", A.max_steps);
  if (g->exists("max_steps")) r.check(A.max_steps >= 1, (*g)["max_steps"], "must be >= 1", A.max_steps);
  sign_checked("fixed_point_tolerance", A.fixed_point_tolerance, true);
  A.fixed_point_iterations = r.integer(*g, "fixed_point_iterations", A.fixed_point_iterations);
  if (g->exists("fixed_point_iterations"))
    r.check(A.fixed_point_iterations >= 1, (*g)["fixed_point_iterations"], "must be >= 1", A.fixed_point_iterations);
  return A;
}

OutputParams read_output(const Reader& r, const Setting& root, double T, int dim) {
  OutputParams O;
  const Setting* o = r.optional_group(root, "output");
  if (!o) return O;
  r.only(*o, {"directory", "times", "watch", "probes", "checkpoint_steps", "every"});
  O.every = r.integer(*o, "every", O.every);
  if (o->exists("every")) r.check(O.every >= 0, (*o)["every"], "must be >= 0 (0: frames at the output times only)", O.every);
  O.checkpoint_steps = r.integer(*o, "checkpoint_steps", O.checkpoint_steps);
  if (o->exists("checkpoint_steps"))
    r.check(O.checkpoint_steps >= 0, (*o)["checkpoint_steps"], "must be >= 0 (0: a checkpoint only when the run stops)",
            O.checkpoint_steps);
  O.directory = r.text(*o, "directory", O.directory);
  if (O.directory.empty()) r.fail((*o)["directory"], "must not be empty");
  if (o->exists("times")) {
    O.times = r.numbers((*o)["times"]);
    std::ostringstream range;  // T as read: it may come from a --set far from this line
    range << "must be in [0, time.T = " << T << "]";
    for (double tt : O.times) r.check(tt >= 0 && tt <= T, (*o)["times"], range.str(), tt);
    std::sort(O.times.begin(), O.times.end());
  }
  std::vector<std::string> names;  // watch points and probes name columns: one name once
  std::vector<std::string> columns = history_run_columns();  // and no column twice ("min beta")
  for (const char* list : {"watch", "probes"}) {
    if (!o->exists(list)) continue;
    const Setting& ws = (*o)[list];
    if (!ws.isList()) r.fail(ws, "must be a list ( { name = \"B\"; point = [x, y]; }, ... )");
    for (int i = 0; i < ws.getLength(); ++i) {
      if (!ws[i].isGroup()) r.fail(ws[i], "must be a group { name = ...; point = [x, y]; }");
      r.only(ws[i], {"name", "point"});
      const NamedPoint p{r.text(ws[i], "name", "", true), r.coordinates(ws[i], "point", dim)};
      if (p.name.empty()) r.fail(ws[i]["name"], "must not be empty (it names the columns of history.csv)");
      if (std::any_of(p.name.begin(), p.name.end(), [](unsigned char c) { return std::iscntrl(c); }))
        r.fail(ws[i]["name"], "must not hold control characters (tabs, line breaks)");
      if (std::find(names.begin(), names.end(), p.name) != names.end())
        r.fail(ws[i]["name"], "'" + p.name + "' names another watch point or probe already");
      names.push_back(p.name);
      const bool watch = std::string(list) == "watch";
      for (const std::string& column : history_point_columns(p.name, watch, dim)) {
        if (std::find(columns.begin(), columns.end(), column) != columns.end())
          r.fail(ws[i]["name"], "'" + p.name + "' would name history.csv's column '" + column + "' twice: choose another name");
        columns.push_back(column);
      }
      (watch ? O.watch : O.probes).push_back(p);
    }
  }
  return O;
}

/// Rules across sections.
void check_consistency(const Reader& r, const Setting& root, Config& c) {
  // alpha = 0 is the rate-independent limit (docs/MODEL.md s3), whatever viscous integrator
  // integrator.method names (they need alpha > 0; contact-only holds beta and reads no
  // alpha): one rule for `rccm run`, `sweep` and `compare` (rate_independent_limit).
  std::size_t zero = 0;
  for (const InterfaceParams& p : c.interfaces) zero += p.alpha == 0;
  if (zero == c.interfaces.size()) c.integrator.method = rate_independent_limit(c.integrator.method);
  for (const InterfaceParams& p : c.interfaces) {
    const Setting& in = root.lookup(p.path);
    if (zero > 0 && zero < c.interfaces.size() && p.alpha == 0)
      r.fail(in.exists("alpha") ? in["alpha"] : in,
             "alpha = 0 (the rate-independent limit) on some interfaces only: give every interface alpha > 0, or "
             "every one alpha = 0");
  }
  const Setting* integrator = root.exists("integrator") ? &root["integrator"] : nullptr;
  const IntegratorParams& A = c.integrator;
  const double max_step = A.largest_step(c.time.T);  // ARKODE's, as the integrator sets it
  if (A.min_step > max_step)
    r.fail((*integrator)["min_step"], "must not exceed integrator.max_step (" + csv_number(max_step) + " s" +
                                          (A.max_step > 0 ? "" : ", its default T/50") + ")");
  if (A.fixed_step > c.time.T) r.fail((*integrator)["fixed_step"], "must not exceed time.T");
  if (!A.table.empty() && !arkode_table_exists(A.scheme == ArkodeScheme::Dirk, A.table))
    r.fail((*integrator)["table"], "no " + std::string(A.scheme == ArkodeScheme::Dirk ? "DIRK" : "ERK") +
                                       " table of ARKODE is named '" + A.table + "' (e.g. " +
                                       (A.scheme == ArkodeScheme::Dirk ? "ARKODE_SDIRK_5_3_4" : "ARKODE_ZONNEVELD_5_3_4") +
                                       "; SUNDIALS' arkode_butcher_" + (A.scheme == ArkodeScheme::Dirk ? "dirk" : "erk") +
                                       ".h lists them)");
}

Config read(const Reader& r, const Setting& root, const std::string& path) {
  Config c;
  c.file = path;
  r.only(root, {"mesh", "material", "bodies", "interface", "interfaces", "loads", "time", "solver", "integrator", "output"});
  c.mesh = read_mesh(r, root, std::filesystem::path(path).parent_path().string());
  const int dim = c.mesh.dim();
  c.bodies = read_bodies(r, root, dim);
  c.interfaces = read_interfaces(r, root, dim);
  c.time = read_time(r, root);
  c.loads = read_loads(r, root, c.time.T, dim);
  c.solver = read_solver(r, root, dim);
  c.integrator = read_integrator(r, root);
  c.output = read_output(r, root, c.time.T, dim);
  check_consistency(r, root, c);
  return c;
}

/// The line of every setting, by path, for messages after reading (Config::where).
/// The paths are built on the way down: libconfig's getPath() searches each element's index
/// in its parent, quadratic over a long array (a 1e5-node g0 took seconds). The numbers of an
/// array are not recorded: messages name the array.
void record_lines(const Setting& s, const std::string& path, std::map<std::string, int>& lines) {
  if (!path.empty()) lines[path] = static_cast<int>(s.getSourceLine());
  if (s.isGroup() || s.isList())
    for (int i = 0; i < s.getLength(); ++i) {
      const Setting& child = s[i];
      const std::string name = s.isList() ? "[" + std::to_string(i) + "]" : std::string(child.getName());
      record_lines(child, path.empty() ? name : path + "." + name, lines);
    }
}

}  // namespace


namespace {

/// What libconfig's "syntax error" at `line` of a config's `text` most likely is, read from
/// that line: a UTF-8 byte-order mark (an editor's "UTF-8 with BOM"), or a bare word where a
/// value goes (nan, inf, a string without its quotes). Empty when the line shows neither.
std::string line_hint(const std::string& config, int line) {
  std::istringstream in(config);
  std::string text;
  for (int n = 0; n < line && std::getline(in, text);) ++n;
  if (line == 1 && text.rfind("\xEF\xBB\xBF", 0) == 0)
    return "the file starts with a UTF-8 byte-order mark, which libconfig does not read: save it as plain UTF-8";
  static const std::regex bare(R"(=\s*([A-Za-z_][A-Za-z0-9_.\-]*)\s*[;,\]\)}])");
  std::smatch m;
  if (std::regex_search(text, m, bare) && m[1] != "true" && m[1] != "false")
    return "'" + m[1].str() + "' is no value: a number (1.0e3), a quoted string (\"text\"), true or false";
  return "";
}

/// The bytes of a config file or of a file it includes, read once: a regular file, or a pipe
/// (`rccm run /dev/stdin`, `<(...)`, a FIFO), whose bytes a second read would not find. Anything
/// else (a directory, a device: /dev/zero has no end), a file beyond max_config_bytes, and a NUL
/// byte (libconfig would stop reading there) are refused.
constexpr std::size_t max_config_bytes = 16 << 20;
std::string config_bytes(const std::string& path) {
  std::error_code ec;
  const std::filesystem::file_status kind = std::filesystem::status(path, ec);
  if (std::filesystem::is_directory(kind)) throw InputError(path + ": a directory, not a config file");
  if (std::filesystem::exists(kind) && !std::filesystem::is_regular_file(kind) && !std::filesystem::is_fifo(kind))
    throw InputError(path + ": neither a file nor a pipe (a device?): a config is a text file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": cannot read the file (does it exist?)");
  std::string text;
  char chunk[1 << 16];
  while (in.read(chunk, sizeof chunk) || in.gcount() > 0) {
    text.append(chunk, static_cast<std::size_t>(in.gcount()));
    if (text.size() > max_config_bytes)
      throw InputError(path + ": more than 16 MiB, not a config (a config is text of a few kilobytes): the wrong file?");
  }
  const std::size_t nul = text.find('\0');
  if (nul != std::string::npos)
    throw InputError(path + ":" + std::to_string(1 + std::count(text.begin(), text.begin() + nul, '\n')) +
                     ": a NUL byte: not a text file (a config is libconfig text)");
  return text;
}

/// `config` is the text of `path`, the top config (an @include'd file is read anew).
InputError syntax_error(const libconfig::ParseException& e, const std::string& path, const std::string& config) {
  const std::string file = source_path(e.getFile(), path);
  const std::string hint = line_hint(file == path ? config : config_bytes(file), e.getLine());
  return InputError(file + ":" + std::to_string(e.getLine()) + ": syntax error: " +
                    (hint.empty() ? syntax_hint(e.getError()) : hint));
}

/// Checks the text of a config (`path`) and the files it includes before libconfig reads them:
/// integer literals (check_integer_literals) and @include lines, which name a file relative to
/// the directory of the top config (libconfig's include directory).
void check_config_text(const std::string& text, const std::string& path, const std::string& include_dir, int depth = 0) {
  check_integer_literals(text, [&](int line) { return path + ":" + std::to_string(line); });
  std::istringstream lines(text);
  int n = 0;
  for (std::string line; std::getline(lines, line);) {
    ++n;
    const std::size_t at = line.find_first_not_of(" \t");
    if (at == std::string::npos || line.compare(at, 8, "@include") != 0) continue;
    const std::size_t open = line.find('"', at), close = line.find('"', open + 1);
    if (open == std::string::npos || close == std::string::npos)
      throw InputError(path + ":" + std::to_string(n) + ": @include needs a file name in quotes");
    const std::string name = line.substr(open + 1, close - open - 1);
    const std::string included = !name.empty() && name[0] == '/' ? name : include_dir + "/" + name;
    if (depth > 8) throw InputError(path + ":" + std::to_string(n) + ": @include \"" + name + "\": nested too deep (a loop?)");
    if (!std::ifstream(included))
      throw InputError(path + ":" + std::to_string(n) + ": @include \"" + name + "\": cannot read " + included +
                       " (included files are found relative to the directory of " + "the config file)");
    check_config_text(config_bytes(included), included, include_dir, depth + 1);
  }
}

/// libconfig's tree of the text of a config (`name` in messages); @include'd files are found
/// in `include_dir` (none: the working directory).
void parse(libconfig::Config& cfg, const std::string& text, const std::string& name, const std::string& include_dir) {
  cfg.setAutoConvert(true);
  if (!include_dir.empty()) cfg.setIncludeDir(include_dir.c_str());
  try {
    cfg.readString(text);
  } catch (const libconfig::ParseException& e) {
    throw syntax_error(e, name, text);
  }
}

/// The file's own values of the settings an override replaces (`replaced`: "file:line: path:"
/// of each), read as the next run without the overrides would read them: a value it would
/// refuse (`directory = 5;` or `directory = "";` under -o) is refused now, not left to stop it.
void check_replaced_values(const std::string& text, const std::string& path, const std::string& include_dir,
                           const std::vector<std::string>& replaced) {
  libconfig::Config file;
  parse(file, text, path, include_dir);
  try {
    read(Reader(path), file.getRoot(), path);
  } catch (const InputError& e) {
    const std::string what = e.what();
    for (const std::string& r : replaced)
      if (what.rfind(r, 0) == 0)
        throw InputError(what + "; --set or -o replaces it in this run, but the file's value is wrong: mend it");
  }
}

/// The checked read of the text of a config under `overrides`.
Config read_config(const std::string& text, const std::string& path, const std::string& include_dir,
                   const std::vector<std::string>& overrides) {
  libconfig::Config cfg;
  parse(cfg, text, path, include_dir);
  std::vector<std::string> replaced;
  for (const std::string& o : overrides) {
    const std::string setting = o.substr(0, o.find('='));
    if (cfg.exists(setting) && cfg.lookup(setting).getSourceLine() > 0) {
      const Setting& s = cfg.lookup(setting);
      replaced.push_back(source_path(s.getSourceFile(), path) + ":" + std::to_string(s.getSourceLine()) + ": " + setting + ":");
    }
    apply_override(cfg, o);
  }
  Reader reader(path);
  try {
    Config c = read(reader, cfg.getRoot(), path);
    if (!replaced.empty()) check_replaced_values(text, path, include_dir, replaced);
    record_lines(cfg.getRoot(), "", c.lines);
    c.settings = c.fingerprint();
    c.settings_parts = c.fingerprint_parts();
    return c;
  } catch (const libconfig::SettingException& e) {
    throw InputError(path + ": " + e.getPath() + ": " + e.what());
  }
}

}  // namespace

Config load_config(const std::string& path, const std::vector<std::string>& overrides) {
  const std::string dir = std::filesystem::path(path).parent_path().string();
  const std::string include_dir = dir.empty() ? "." : dir;
  const std::string text = config_bytes(path);  // once: a pipe is not there to be read again
  check_config_text(text, path, include_dir);
  return read_config(text, path, include_dir, overrides);
}

Config parse_config(const std::string& text, const std::string& name, const std::vector<std::string>& overrides) {
  check_integer_literals(text, [&](int line) { return name + ":" + std::to_string(line); });
  return read_config(text, name, "", overrides);
}

std::string string_override(const std::string& path, const std::string& text) {
  return path + "=" + string_literal(text);
}

}  // namespace rccm
