#pragma once
// Number and point formatting for user-facing messages (short, locale independent).
#include <Eigen/Core>
#include <string>
#include <vector>

namespace sdog {

/// Shortest round-trip-free formatting with up to 6 significant digits: 12.5, 0.001, 3e+07.
std::string format_number(double v);
/// "(x, y)" with format_number.
std::string format_point(const Eigen::Vector2d& p);
/// Text for one cell of a Markdown table: line breaks become spaces, pipes are escaped.
std::string markdown_cell(const std::string& text);
/// The items separated by `separator`: join({"a", "b"}, ", ") is "a, b".
std::string join(const std::vector<std::string>& items, const std::string& separator);

}  // namespace sdog
