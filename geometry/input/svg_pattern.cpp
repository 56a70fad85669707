#include "geometry/input/svg_pattern.h"

#include <algorithm>
#include <set>
#include <sstream>

#include "base/errors.h"
#include "base/text_format.h"
#include "geometry/input/fold_conventions.h"
#include "geometry/pattern/pattern_assembly.h"

namespace sdog {
namespace {

// Open boundary pieces are chained across gaps up to this fraction of the sheet size (the default
// merge tolerance of pattern cleaning).
constexpr double kBoundaryJoinFraction = 0.01;

std::string origin_of(const std::string& source, const SvgCurve& c) {
  std::ostringstream s;
  s << source;
  if (c.line > 0) s << ":" << c.line;
  s << ": <" << c.element;
  if (!c.id.empty()) s << " id=\"" << c.id << "\"";
  s << ">";
  return s.str();
}

void drop_repeated_points(Polyline2& pts, bool closed) {
  pts.erase(std::unique(pts.begin(), pts.end()), pts.end());
  if (closed && pts.size() > 1 && pts.front() == pts.back()) pts.pop_back();
}

struct OpenCurve {
  Polyline2 points;
  std::string origin;
  bool cut = false;  ///< a cut line, not a black boundary curve
  std::string id;    ///< the element's id (a slit keeps it)
};

InputError not_closed_error(const OpenCurve& c) {
  const std::string what = c.cut ? "this cut line" : "the sheet boundary (black)";
  return InputError(c.origin + ": " + what + " is not closed: it ends at " +
                    format_point(c.points.back()) + ", " +
                    format_number((c.points.front() - c.points.back()).norm()) +
                    " units from its start " + format_point(c.points.front()) +
                    "; close the path (Z) or draw the boundary as one closed shape");
}

// For each end of the open pieces (end 2k: piece k's first point, 2k + 1: its last), the other
// pieces' ends within tol of it.
std::vector<std::vector<size_t>> meeting_ends(const std::vector<OpenCurve>& open, double tol) {
  auto end = [&](size_t i) -> const Eigen::Vector2d& {
    return i % 2 == 0 ? open[i / 2].points.front() : open[i / 2].points.back();
  };
  std::vector<std::vector<size_t>> meets(2 * open.size());
  for (size_t i = 0; i < meets.size(); ++i)
    for (size_t j = i + 1; j < meets.size(); ++j)
      if (i / 2 != j / 2 && (end(i) - end(j)).norm() <= tol)
        meets[i].push_back(j), meets[j].push_back(i);
  return meets;
}

// Takes the slits out of the open boundary and cut curves: pieces with an end that no other
// piece's end meets (within tol), repeatedly, so that what remains can close into loops. A slit
// from the boundary inward, an interior slit and a cut drawn in pieces to the slit's tip all go.
std::vector<OpenCurve> split_off_slits(std::vector<OpenCurve>& open, double tol) {
  const size_t n = open.size();
  const std::vector<std::vector<size_t>> meets = meeting_ends(open, tol);
  std::vector<char> slit(n, 0);
  for (bool changed = true; changed;) {
    changed = false;
    for (size_t c = 0; c < n; ++c) {
      if (slit[c] || (open[c].points.front() - open[c].points.back()).norm() <= tol) continue;
      for (size_t i : {2 * c, 2 * c + 1})
        if (std::none_of(meets[i].begin(), meets[i].end(), [&](size_t j) { return !slit[j / 2]; }))
          slit[c] = 1;
      changed = changed || slit[c];
    }
  }
  std::vector<OpenCurve> slits, rest;
  for (size_t c = 0; c < n; ++c) (slit[c] ? slits : rest).push_back(std::move(open[c]));
  open = std::move(rest);
  return slits;
}

// Refuses a point where more than two open boundary or cut pieces end (within tol): a network of
// lines, which has no single reading as closed loops. Names the point where most of them meet.
void check_no_branch_points(const std::vector<OpenCurve>& open, double tol) {
  const std::vector<std::vector<size_t>> meets = meeting_ends(open, tol);
  int most = 2;
  const OpenCurve* where = nullptr;
  Eigen::Vector2d at = Eigen::Vector2d::Zero();
  for (size_t i = 0; i < meets.size(); ++i) {
    std::set<size_t> pieces{i / 2};
    for (size_t j : meets[i]) pieces.insert(j / 2);
    if (static_cast<int>(pieces.size()) > most) {
      most = static_cast<int>(pieces.size());
      where = &open[i / 2];
      at = i % 2 == 0 ? where->points.front() : where->points.back();
    }
  }
  if (where)
    throw InputError(where->origin + ": " + std::to_string(most) +
                     " sheet boundary (black) or cut lines meet at " + format_point(at) +
                     ": the boundary must be closed loops, each point on two of their lines, and "
                     "lines branching off them (a network of cuts) are not read; draw the sheet as "
                     "one closed outline and cuts inside it as lines with a free end (slits)");
}

// Chains open boundary curves end to end into closed loops: each continues with the piece whose
// nearer end is nearest its end, within tol. Ends within snap_tol of each other are one point (the
// piece's first point is dropped: a step that small would fold the boundary back over itself where
// pieces overlap by a hair); a wider gap is closed by the chain's straight step.
std::vector<Polyline2> chain_into_loops(std::vector<OpenCurve> open, double tol, double snap_tol) {
  std::vector<Polyline2> loops;
  while (!open.empty()) {
    OpenCurve current = std::move(open.front());
    open.erase(open.begin());
    while ((current.points.front() - current.points.back()).norm() > tol) {
      size_t best = open.size();
      bool reversed = false;
      double nearest = tol;
      for (size_t k = 0; k < open.size(); ++k) {
        const Polyline2& next = open[k].points;
        for (const bool back : {false, true}) {
          const double d = ((back ? next.back() : next.front()) - current.points.back()).norm();
          if (d <= nearest) best = k, reversed = back, nearest = d;
        }
      }
      const bool extended = best < open.size();
      if (extended) {
        Polyline2& next = open[best].points;
        if (reversed) std::reverse(next.begin(), next.end());
        current.points.insert(current.points.end(), next.begin() + (nearest <= snap_tol ? 1 : 0),
                              next.end());
        current.cut = current.cut || open[best].cut;
        open.erase(open.begin() + static_cast<std::ptrdiff_t>(best));
      }
      if (!extended) throw not_closed_error(current);
    }
    current.points.pop_back();  // the last point repeats the first one (within tolerance)
    while (current.points.size() > 1 &&
           (current.points.back() - current.points.front()).norm() <= snap_tol)
      current.points.pop_back();
    loops.push_back(std::move(current.points));
  }
  return loops;
}

// The tolerance for closing curves: closed_fraction of the sheet size, which is not known yet, so
// of the viewBox (or, without one, of the drawing's extent).
double closing_tolerance(const SvgDrawing& drawing, double closed_fraction) {
  Box2 extent = drawing.viewbox;
  if (!drawing.has_viewbox) {
    Polyline2 all;
    for (const auto& c : drawing.curves) all.insert(all.end(), c.points.begin(), c.points.end());
    if (!all.empty()) extent = box_of(all);
  }
  return closed_fraction * std::max(extent.width(), extent.height());
}

// The drawing's curves sorted: black ones into closed boundary loops (open pieces chained end to
// end within `tol`), the others kept as crease curves in drawing order.
struct SortedCurves {
  std::vector<Polyline2> loops;
  std::vector<std::string> loop_origins;
  std::vector<OpenCurve> slits;  ///< open boundary and cut curves that end inside the sheet
  std::vector<const SvgCurve*> creases;
  std::vector<CurveReading> readings;  ///< of each crease curve
  int facet_lines = 0;
};

SortedCurves sort_curves(const SvgDrawing& drawing, double tol, double join_tol) {
  SortedCurves out;
  std::vector<OpenCurve> open_boundary;
  for (const auto& c : drawing.curves) {
    if (c.points.size() < 2) continue;
    const CurveReading reading = read_curve(c, origin_of(drawing.source, c));
    if (reading.role == CurveRole::kFacet) {
      ++out.facet_lines;
      continue;
    }
    if (reading.role == CurveRole::kCrease) {
      out.creases.push_back(&c);
      out.readings.push_back(reading);
      continue;
    }
    Polyline2 pts = c.points;
    const bool closed = c.closed || (pts.size() > 2 && (pts.front() - pts.back()).norm() <= tol);
    if (closed) {
      if (!c.closed) pts.pop_back();
      drop_repeated_points(pts, true);
      out.loops.push_back(std::move(pts));
      out.loop_origins.push_back(origin_of(drawing.source, c));
    } else {
      open_boundary.push_back(
          {pts, origin_of(drawing.source, c), reading.role == CurveRole::kCut, c.id});
    }
  }
  out.slits = split_off_slits(open_boundary, join_tol);
  // Without any loop, an open black line is a boundary left open, not a slit in the viewBox.
  if (out.loops.empty() && open_boundary.empty())
    for (const OpenCurve& s : out.slits)
      if (!s.cut) throw not_closed_error(s);
  check_no_branch_points(open_boundary, join_tol);
  if (!open_boundary.empty()) {
    const std::string origin = open_boundary.front().origin;
    for (auto& loop : chain_into_loops(std::move(open_boundary), join_tol, tol)) {
      drop_repeated_points(loop, true);
      out.loops.push_back(std::move(loop));
      out.loop_origins.push_back(origin);
    }
  }
  return out;
}

// The sheet of a drawing without boundary curves: its viewBox rectangle (bbox not yet set).
Sheet sheet_from_viewbox(const SvgDrawing& drawing) {
  if (!drawing.has_viewbox)
    throw InputError(drawing.source +
                     ": the drawing has neither a viewBox nor a black boundary curve, so the "
                     "sheet is unknown; add viewBox=\"0 0 W H\" to <svg>");
  const Box2& b = drawing.viewbox;
  if (!(b.width() > 0) || !(b.height() > 0))
    throw InputError(drawing.source + ": the sheet has zero area (viewBox " +
                     format_number(b.width()) + " x " + format_number(b.height()) +
                     "); give the viewBox a positive width and height");
  Sheet sheet;
  sheet.outer = {{b.xmin, b.ymin}, {b.xmax, b.ymin}, {b.xmax, b.ymax}, {b.xmin, b.ymax}};
  sheet.from_viewbox = true;
  return sheet;
}

// Appends to `crease` the curves after curves[k] that continue it: later open subpaths of the
// same <path> that start within `tol` of its end. Returns the index of the last curve used.
size_t append_continuations(const std::vector<const SvgCurve*>& curves, size_t k, double tol,
                            Crease& crease) {
  const SvgCurve& c = *curves[k];
  while (!crease.closed && k + 1 < curves.size()) {
    const SvgCurve& next = *curves[k + 1];
    const bool same_element = next.line == c.line && next.element == c.element && next.id == c.id &&
                              next.subpath > 0 && !next.closed;
    if (!same_element || (next.points.front() - crease.points.back()).norm() > tol) break;
    crease.points.insert(crease.points.end(), next.points.begin() + 1, next.points.end());
    ++k;
  }
  return k;
}

// The creases of the crease curves: subpaths of one <path> that continue each other are joined,
// and a crease whose ends meet within closed_fraction of the sheet size is closed.
void add_creases(const std::vector<const SvgCurve*>& curves,
                 const std::vector<CurveReading>& readings, const std::string& source,
                 double closed_fraction, CreasePattern& pattern) {
  const double sheet_tol = closed_fraction * pattern.size();
  for (size_t k = 0; k < curves.size(); ++k) {
    const SvgCurve& c = *curves[k];
    check_near_sheet(c.points, origin_of(source, c), pattern);
    Crease crease;
    crease.points = c.points;
    crease.closed = c.closed;
    crease.fold = readings[k].fold;
    crease.angle = readings[k].angle;
    crease.id = c.id;
    crease.origin = origin_of(source, c);
    crease.layer = readings[k].layer;
    k = append_continuations(curves, k, sheet_tol, crease);
    if (!crease.closed && crease.points.size() > 2 &&
        (crease.points.front() - crease.points.back()).norm() <= sheet_tol) {
      crease.closed = true;
      crease.points.pop_back();
    }
    drop_repeated_points(crease.points, crease.closed);
    if (crease.points.size() < 2 || (crease.closed && crease.points.size() < 3)) continue;
    pattern.creases.push_back(std::move(crease));
  }
}

// Slits are flat curves of kind kSlit (crease_pattern.h), after the creases.
void add_slits(const std::vector<OpenCurve>& slits, CreasePattern& pattern) {
  std::string origins;
  for (const OpenCurve& s : slits) {
    Crease slit;
    slit.points = s.points;
    drop_repeated_points(slit.points, false);
    if (slit.points.size() < 2) continue;
    slit.fold = Fold::kFlat;
    slit.kind = CurveKind::kSlit;
    slit.origin = s.origin;
    slit.id = s.id;
    origins += (origins.empty() ? "" : ", ") + s.origin;
    pattern.creases.push_back(std::move(slit));
  }
  if (!origins.empty())
    pattern.warnings.push_back(std::to_string(slits.size()) +
                               " open boundary or cut line(s) end inside the sheet and are read "
                               "as slits (cuts whose two sides are free): " +
                               origins);
}

}  // namespace

CreasePattern crease_pattern_from_svg(const SvgDrawing& drawing, double closed_fraction) {
  CreasePattern pattern;
  pattern.source = drawing.source;
  const double tol = closing_tolerance(drawing, closed_fraction);
  const SortedCurves curves =
      sort_curves(drawing, tol, closing_tolerance(drawing, kBoundaryJoinFraction));
  pattern.sheet = curves.loops.empty() ? sheet_from_viewbox(drawing)
                                       : sheet_from_loops(curves.loops, curves.loop_origins);
  pattern.sheet.bbox = box_of(pattern.sheet.outer);
  add_creases(curves.creases, curves.readings, drawing.source, closed_fraction, pattern);
  add_slits(curves.slits, pattern);
  if (curves.facet_lines > 0)
    pattern.warnings.push_back(
        std::to_string(curves.facet_lines) +
        " facet line(s) (yellow, Origami Simulator's triangulation) ignored");
  return pattern;
}

}  // namespace sdog
