#pragma once
// The plots of `sdog compare`: objective and time per iteration against iteration for every
// pattern and resolution (thesis Figs. 6.2, 6.6), and time per iteration per DoF against the mesh
// size for a pattern run at several resolutions (Fig. 6.7). Every mode keeps its colour.
#include <string>
#include <utility>
#include <vector>

#include "solver/experiments/case_rounds.h"
#include "ui/vis/line_chart.h"

namespace sdog::cli {

/// Every plot of the comparison with its file name, from results ordered by pattern and resolution.
std::vector<std::pair<std::string, vis::LineChart>> comparison_charts(
    const std::vector<CaseResult>& results);

}  // namespace sdog::cli
