#pragma once
// ParaView collection files (.pvd): a list of data files with a time step each, which ParaView
// opens as one time series.
#include <string>
#include <utility>
#include <vector>

namespace sdog::vis {

/// (time step, file name relative to the .pvd) in the order listed.
using TimeSteps = std::vector<std::pair<int, std::string>>;

/// The text of a .pvd file listing `steps`.
std::string pvd_collection(const TimeSteps& steps);

}  // namespace sdog::vis
