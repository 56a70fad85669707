#pragma once
// Versions of sdog and the libraries it was built with (for run.json and bench CSV headers).
#include <nlohmann/json.hpp>

namespace sdog::cli {

nlohmann::json software_versions();

}  // namespace sdog::cli
