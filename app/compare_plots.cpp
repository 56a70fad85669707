#include "app/compare_plots.h"

#include <algorithm>
#include <map>
#include <set>

namespace sdog::cli {
namespace {

// A fixed colour per mode name, so that every plot of a comparison (and of later ones) agrees: the
// palette's colours in the order of the modes, except that the sixth mode (coarse) takes the fifth
// colour (orange) and the fifth mode the sixth (sky blue), which is hard to tell from the standard
// mode's blue, and coarse is usually drawn beside it.
vis::Rgb mode_colour(ModeKind mode) {
  const int index = static_cast<int>(mode);
  const int kOrange = 4, kSkyBlue = 5;
  return vis::series_colour(index == kSkyBlue ? kOrange : index == kOrange ? kSkyBlue : index);
}

vis::ChartSeries mode_series(const CaseResult& r) {
  vis::ChartSeries s;
  s.name = std::string(enum_name(r.mode)) +
           (r.completed() ? "" : std::string(" (") + enum_name(r.status) + ")");
  s.colour = mode_colour(r.mode);
  return s;
}

// Plots of one pattern and resolution: objective and time per iteration against iteration.
std::vector<std::pair<std::string, vis::LineChart>> case_charts(
    const std::vector<const CaseResult*>& rows) {
  const std::string place = rows.front()->pattern + " " + rows.front()->res;
  vis::LineChart objective =
      vis::titled_chart(place + ": objective", "iteration", "objective (weighted, fine mesh)");
  vis::LineChart time =
      vis::titled_chart(place + ": time per iteration", "iteration", "time per iteration (ms)");
  // The modes' objectives differ by orders of magnitude (thesis Fig. 6.2), and the first and last
  // iterations (symbolic analysis, final polish) take many times longer than the others.
  objective.log_y = time.log_y = true;
  for (const CaseResult* r : rows) {
    if (r->series.empty()) continue;
    vis::ChartSeries o = mode_series(*r), t = mode_series(*r);
    for (const auto& p : r->series) {
      o.x.push_back(p.iteration);
      o.y.push_back(p.objective);
      t.x.push_back(p.iteration);
      t.y.push_back(p.ms);
    }
    objective.series.push_back(o);
    time.series.push_back(t);
  }
  if (objective.series.empty()) return {};
  const std::string suffix = rows.front()->pattern + "_" + rows.front()->res + ".png";
  return {{"objective_" + suffix, objective}, {"time_" + suffix, time}};
}

// ms per iteration per DoF against the vertex count, one line per mode, for a pattern run at more
// than one resolution (completed runs only).
std::optional<vis::LineChart> scaling_chart(const std::string& pattern,
                                            const std::vector<CaseResult>& rows) {
  vis::LineChart chart = vis::titled_chart(pattern + ": time per iteration per DoF",
                                           "fine vertices", "time per iteration per DoF (ms)");
  std::set<std::string> resolutions;
  std::map<ModeKind, vis::ChartSeries> by_mode;
  for (const auto& r : rows) {
    if (r.pattern != pattern || !r.completed()) continue;
    resolutions.insert(r.res);
    auto [it, fresh] = by_mode.try_emplace(r.mode, mode_series(r));
    it->second.x.push_back(r.vertices);
    it->second.y.push_back(r.ms_per_dof());
  }
  if (resolutions.size() < 2) return std::nullopt;
  for (ModeKind mode : enum_values<ModeKind>()) {
    const auto it = by_mode.find(mode);
    if (it == by_mode.end()) continue;
    vis::ChartSeries s = it->second;
    std::vector<size_t> order(s.x.size());
    for (size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::sort(order.begin(), order.end(), [&](size_t i, size_t j) { return s.x[i] < s.x[j]; });
    vis::ChartSeries sorted{s.name, {}, {}, s.colour};
    for (size_t i : order) {
      sorted.x.push_back(s.x[i]);
      sorted.y.push_back(s.y[i]);
    }
    chart.series.push_back(sorted);
  }
  return chart;
}

}  // namespace

std::vector<std::pair<std::string, vis::LineChart>> comparison_charts(
    const std::vector<CaseResult>& rows) {
  std::vector<std::pair<std::string, vis::LineChart>> charts;
  std::vector<std::string> patterns;
  for (size_t i = 0; i < rows.size();) {
    std::vector<const CaseResult*> place;
    size_t j = i;
    for (; j < rows.size() && rows[j].pattern == rows[i].pattern && rows[j].res == rows[i].res; ++j)
      place.push_back(&rows[j]);
    for (auto& c : case_charts(place)) charts.push_back(std::move(c));
    if (std::find(patterns.begin(), patterns.end(), rows[i].pattern) == patterns.end())
      patterns.push_back(rows[i].pattern);
    i = j;
  }
  for (const auto& p : patterns)
    if (auto chart = scaling_chart(p, rows)) charts.push_back({"ms_per_dof_" + p + ".png", *chart});
  return charts;
}

}  // namespace sdog::cli
