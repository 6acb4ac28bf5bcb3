#include "rccm/io/csv.hpp"

#include "rccm/base/errors.hpp"
#include "rccm/io/atomic_file.hpp"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <limits>
#include <sstream>

namespace rccm {

std::string csv_field(const std::string& text) {
  if (text.find_first_of(",\"\r\n") == std::string::npos) return text;
  std::string out = "\"";
  for (char c : text) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

std::string csv_number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.12g", v);
  return buf;
}

std::vector<std::string> csv_split(const std::string& line) {
  std::vector<std::string> fields(1);
  bool quoted = false;
  for (std::size_t k = 0; k < line.size(); ++k) {
    const char c = line[k];
    if (quoted && c == '"' && k + 1 < line.size() && line[k + 1] == '"') {
      fields.back() += '"';
      ++k;
    } else if (c == '"') {
      quoted = !quoted;
    } else if (c == ',' && !quoted) {
      fields.emplace_back();
    } else if (c != '\r' || quoted) {
      fields.back() += c;
    }
  }
  return fields;
}

std::string csv_line(const std::vector<std::string>& fields) {
  std::string line;
  for (std::size_t k = 0; k < fields.size(); ++k) line += (k ? "," : "") + csv_field(fields[k]);
  return line;
}

std::istream& read_line(std::istream& in, std::string& line) {
  if (std::getline(in, line))
    if (!line.empty() && line.back() == '\r') line.pop_back();
  return in;
}

CsvStream::CsvStream(const std::string& path, const std::vector<std::string>& header)
    : path_(path), out_(path) {
  if (!out_) throw WriteError("cannot create " + path + " (" + std::strerror(errno) + ")");
  write(csv_line(header));
}

CsvStream::Kept CsvStream::lines_until(const std::string& path, double t) {
  std::ifstream in(path);
  std::vector<std::string> lines(1);  // CRLF line ends are read without their CR: appended rows end in LF
  if (!read_line(in, lines[0])) throw InputError(path + ": the result file to take up is missing or empty");
  const std::size_t columns = csv_split(lines[0]).size();
  const double eps = 1e-9 * std::max(1.0, std::abs(t));
  double last = -std::numeric_limits<double>::infinity();
  for (std::string line; read_line(in, line);) {
    const std::vector<std::string> fields = csv_split(line);
    char* end = nullptr;
    const double time = std::strtod(fields[0].c_str(), &end);
    const bool complete = fields.size() == columns && end != fields[0].c_str() && *end == '\0';
    if (!complete || time > t + eps) break;  // a line cut short by a crash, or after the checkpoint
    lines.push_back(line);
    last = time;
  }
  if (!(last >= t - eps)) {
    std::ostringstream m;
    m << path << ": its rows end " << (lines.size() > 1 ? "at t = " + csv_number(last) + " s" : "before any step")
      << ", before the checkpoint's t = " << csv_number(t) << " s (rows were lost, e.g. the file was cut short): a "
      << "restart cannot rebuild them; run afresh with --force";
    throw InputError(m.str());
  }
  return {lines};
}

CsvStream::CsvStream(const std::string& path, const Kept& kept) : path_(path) {
  {
    AtomicFile file(path);
    for (const std::string& line : kept.lines) file.stream() << line << "\n";
    file.commit();
  }
  out_.open(path, std::ios::app);
  if (!out_) throw WriteError("cannot append to " + path + " (" + std::strerror(errno) + ")");
}

void CsvStream::append(const std::vector<double>& row) {
  std::string line;
  for (std::size_t k = 0; k < row.size(); ++k) line += (k ? "," : "") + csv_number(row[k]);
  write(line);
}

void CsvStream::write(const std::string& line) {
  const std::string text = line + "\n";
  out_.write(text.data(), static_cast<std::streamsize>(text.size()));
  out_.flush();
  if (!out_) throw WriteError("cannot append to " + path_ + " (" + std::strerror(errno) + ")");
}

}  // namespace rccm
