// CSV as RFC 4180 writes and reads it: a field holding a comma, a double quote or a line
// break is quoted, with its quotes doubled. Every CSV file of rccm goes through here, and a
// restart reads its files back with the same rules (never by counting commas).
#pragma once

#include <fstream>
#include <string>
#include <vector>

namespace rccm {

/// A text field, quoted when it needs to be.
std::string csv_field(const std::string& text);

/// A number with 12 significant digits (enough to read back what was computed to 1e-10).
std::string csv_number(double v);

/// The fields of one line.
std::vector<std::string> csv_split(const std::string& line);

/// A line of fields, each quoted when it needs to be.
std::string csv_line(const std::vector<std::string>& fields);

/// Reads a line of a text file rccm wrote and reads back (a CSV, the checkpoint, a manifest)
/// without its line end: LF, or CRLF after a copy through another system.
std::istream& read_line(std::istream& in, std::string& line);

/// A CSV file that grows by one complete line per append, written with a single write, so
/// that a reader (a plot script, `tail -f`) never sees half a line.
class CsvStream {
 public:
  /// Creates `path` with its header line.
  CsvStream(const std::string& path, const std::vector<std::string>& header);
  /// The lines of a file an earlier run left, kept to take it up at its checkpoint.
  struct Kept {
    std::vector<std::string> lines;
  };
  /// The header and the complete rows of `path` whose first field (the time) is at most `t`
  /// (the checkpoint's). Throws InputError when they end before `t` (rows lost: a restart
  /// cannot rebuild them), before anything is written.
  static Kept lines_until(const std::string& path, double t);
  /// Takes up `path` with its `kept` lines (the rest dropped), then appends.
  CsvStream(const std::string& path, const Kept& kept);
  /// Appends a row of numbers. Throws WriteError naming the file when it cannot.
  void append(const std::vector<double>& row);

 private:
  void write(const std::string& line);
  std::string path_;
  std::ofstream out_;
};

}  // namespace rccm
