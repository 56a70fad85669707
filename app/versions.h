#pragma once
// Versions of sdog and the libraries it was built with (for run.json and bench CSV headers).
#include <nlohmann/json.hpp>
#include <string>

namespace sdog::cli {

nlohmann::json software_versions();

/// "sdog 0.1.0 (commit abc1234)" for program "sdog": what `--version` prints.
std::string version_line(const std::string& program);

}  // namespace sdog::cli
