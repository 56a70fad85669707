#pragma once
// CSV fields and lines (RFC 4180 quoting) for the tables the commands write.
#include <optional>
#include <string>
#include <vector>

namespace sdog {

/// A number for a CSV field: printf's %g with `digits` significant digits; empty when absent.
std::string csv_number(double v, int digits);
std::string csv_number(const std::optional<double>& v, int digits);

/// A CSV line from fields (fields with a comma, quote or newline are quoted).
std::string csv_line(const std::vector<std::string>& fields);

}  // namespace sdog
