#pragma once
// The command-line reference (docs/reference/command-line.md) rendered from the commands' own
// option definitions, so that the documentation lists exactly what the programs accept.
#include <string>

namespace sdog::cli {

/// Markdown: for sdog, each of its commands and sdog-studio, the description and a table of every
/// option (names, value type, default, meaning).
std::string command_line_reference();

}  // namespace sdog::cli
