#pragma once
// Reading the CSV files sdog writes, in the app tests (plain fields: no quoting).
#include <algorithm>
#include <sstream>
#include <string>
#include <vector>

#include "tests/app/run_sdog.h"

namespace sdog::test {

inline std::vector<std::string> split(const std::string& line, char sep = ',') {
  std::vector<std::string> out;
  std::stringstream s(line);
  for (std::string field; std::getline(s, field, sep);) out.push_back(field);
  return out;
}

inline std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> out;
  std::stringstream s(text);
  for (std::string line; std::getline(s, line);)
    if (!line.empty()) out.push_back(line);
  return out;
}

// A CSV as header + rows of fields.
struct Csv {
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;
  int column(const std::string& name) const {
    const auto it = std::find(header.begin(), header.end(), name);
    return it == header.end() ? -1 : static_cast<int>(it - header.begin());
  }
};

inline Csv read_csv(const std::string& path) {
  Csv csv;
  const auto lines = lines_of(slurp(path));
  if (lines.empty()) return csv;
  csv.header = split(lines[0]);
  for (size_t i = 1; i < lines.size(); ++i) csv.rows.push_back(split(lines[i]));
  return csv;
}

}  // namespace sdog::test
