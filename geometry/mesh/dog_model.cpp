#include "geometry/mesh/dog_model.h"

#include <algorithm>
#include <cmath>

#include "base/errors.h"
#include "base/text_format.h"
#include "geometry/mesh/alt_coarse.h"
#include "geometry/pattern/fold_tips.h"
#include "geometry/pattern/pattern_faces.h"

namespace sdog {
namespace {

// Lines of one axis: for an odd count the coarse layout refined, so coarse line j = fine line 2j.
AxisLayout axis_layout(double lo, double hi, int n, const std::vector<double>& pins) {
  if (n % 2 == 1) return refine_axis(layout_axis(lo, hi, (n + 1) / 2, pins));
  return layout_axis(lo, hi, n, pins);
}

PatchLayout checked_layout(const DogModel& m, const Resolution& res, const AxisLayout& x,
                           const AxisLayout& y, int stride) {
  PatchLayout layout = build_patch_layout(m.clean, x, y, stride);
  if (layout.patch_count != m.expected_patches)
    throw UsageError(m.pattern.source + ": at resolution " + res.str() +
                     " the grid-snapped pattern has " + std::to_string(layout.patch_count) +
                     " patches instead of " + std::to_string(m.expected_patches) +
                     " (creases come closer than a grid cell); use a higher resolution");
  return layout;
}

// The stitching curves are the cleaned creases in the same order.
void copy_folds(const CleanPattern& clean, DogMesh& mesh) {
  for (size_t k = 0; k < mesh.stitching.curves.size(); ++k) {
    auto& curve = mesh.stitching.curves[k];
    curve.fold = clean.creases[k].fold;
    curve.angle = clean.creases[k].angle;
    curve.id = clean.creases[k].id;
    curve.kind = clean.creases[k].kind;
  }
  mesh.fold_tips.clear();
  for (const FoldTip& tip : fold_tips(clean)) mesh.fold_tips.push_back(mesh.to_mesh(tip.point));
}

// build_dog_model from the pattern's cleaned form, which does not depend on the resolution.
DogModel build_from_clean(const CreasePattern& pattern, CleanPattern clean, const Resolution& res,
                          const MeshOptions& options) {
  DogModel m;
  m.pattern = pattern;
  m.clean = std::move(clean);
  m.expected_patches = count_pattern_patches(m.clean);
  if (const int k = first_non_separating_crease(m.clean); k >= 0)
    throw InputError(
        "crease " + std::to_string(k) + " (" + m.clean.creases[k].origin +
        ") does not separate the sheet: the same piece of paper lies on both of its sides (as for "
        "a crease from the outer boundary to a hole), and a DOG patch cannot fold along a crease "
        "inside it; extend the crease so that it divides the sheet, or remove it");
  m.fine_res = res;

  const Box2& b = m.clean.sheet.bbox;
  std::vector<double> px, py;
  for (const auto& p : m.clean.pins) px.push_back(p.x()), py.push_back(p.y());
  AxisLayout fx, fy;
  try {
    fx = axis_layout(b.xmin, b.xmax, res.nx, px);
    fy = axis_layout(b.ymin, b.ymax, res.ny, py);
  } catch (const UsageError& e) {
    throw UsageError(pattern.source + ": resolution " + res.str() +
                     " is too low for the pattern's " + std::to_string(m.clean.pins.size()) +
                     " points that must be grid vertices (junctions, crease ends on slanted "
                     "boundary edges): " +
                     e.what());
  }
  const bool nested = res.nx % 2 == 1 && res.ny % 2 == 1;
  const PatchLayout fine = checked_layout(m, res, fx, fy, nested ? 2 : 1);
  const Eigen::Vector2d origin(b.xmin, b.ymin);
  const double scale = (res.nx - 1) / b.width();
  m.fine = build_dog_mesh(fine, origin, scale, nested ? 2 : 1);
  copy_folds(m.clean, m.fine);
  m.fine_topology = quad_topology(m.fine);
  for (const auto& ring : fine.boundary) {
    Polyline2 r;
    for (const auto& p : ring) r.push_back(m.fine.to_mesh(p));
    m.fine_boundary.push_back(std::move(r));
  }
  if (!options.build_coarse) return m;

  m.has_coarse = true;
  m.coarse_res = coarse_resolution(res);
  if (options.coarse == CoarseKind::kAlt) {
    m.coarse_kind = CoarseKind::kAlt;
    m.coarse = build_alt_coarse_mesh(m.fine);
    m.coarse_topology = quad_topology(m.coarse);
    m.map = build_alt_fine_coarse_map(m.fine, m.coarse);
    return m;
  }
  AxisLayout cx = fx, cy = fy;
  cx.n = m.coarse_res.nx;
  cy.n = m.coarse_res.ny;
  for (auto& a : cx.anchors) a.first /= 2;
  for (auto& a : cy.anchors) a.first /= 2;
  PatchLayout coarse = checked_layout(m, m.coarse_res, cx, cy, 1);
  renumber_patches(coarse, match_coarse_patches(fine, coarse));
  m.coarse_cover_cells = cover_fine_patches(coarse, fine);
  m.coarse = build_dog_mesh(coarse, origin, scale);
  copy_folds(m.clean, m.coarse);
  m.coarse_topology = quad_topology(m.coarse);
  m.map = build_fine_coarse_map(m.fine, m.coarse);
  return m;
}

}  // namespace

DogModel build_dog_model(const CreasePattern& pattern, const Resolution& res,
                         const MeshOptions& options) {
  check_resolution(res, options.build_coarse);
  return build_from_clean(pattern, clean_pattern(pattern, options.cleaning), res, options);
}

std::vector<std::string> model_warnings(const DogModel& model) {
  std::vector<std::string> warnings = model.clean.warnings;
  const auto& box = model.pattern.sheet.bbox;
  if (std::string grid = cell_shape_warning(model.fine_res, box.width(), box.height());
      !grid.empty())
    warnings.push_back(std::move(grid));
  // A crease that crosses no grid edge between two patches runs along grid lines (or from vertex
  // to vertex): it has no fold site, so nothing folds it and nothing measures its angle.
  const CreaseStitching& st = model.fine.stitching;
  for (size_t k = 0; k < st.curves.size() && k < model.clean.creases.size(); ++k) {
    const auto& points = st.curves[k].points;
    const bool crosses = std::any_of(points.begin(), points.end(), [&](int p) {
      const auto& copies = st.points[p].copies;
      return copies.size() == 2 && copies[0].v1 != copies[0].v2;
    });
    if (!crosses && st.curves[k].fold != Fold::kFlat)
      warnings.push_back(
          "crease " + std::to_string(k) + " (" + model.clean.creases[k].origin +
          ") runs along grid lines at " + model.fine_res.str() +
          " and crosses no grid edge: it has no fold site, so the fold scenario cannot fold it "
          "and creases.csv has no angle for it (another resolution moves the grid lines off it)");
  }
  for (const FoldTip& tip : fold_tips(model.clean)) {
    const auto& c = model.clean.creases;
    const int seam = c[tip.creases[0]].kind == CurveKind::kSeam ? 0 : 1;
    if (c[tip.creases[seam]].kind == CurveKind::kSeam) {
      warnings.push_back("fold sites within " + format_number(kFoldTipRadius) +
                         " grid edges of crease " + std::to_string(tip.creases[1 - seam]) +
                         "'s end inside the sheet at " + format_point(tip.point) +
                         ", where its fold fades, are counted apart when folds are compared with "
                         "their targets");
      continue;
    }
    warnings.push_back(
        "creases " + std::to_string(tip.creases[0]) + " (" + c[tip.creases[0]].origin + ") and " +
        std::to_string(tip.creases[1]) + " (" + c[tip.creases[1]].origin + ") end together at " +
        format_point(tip.point) + " inside the sheet, at " +
        format_number(std::round(tip.angle_degrees)) +
        " degrees to each other: a sheet that bends smoothly cannot keep a fold up to such a point "
        "(around it the sheet would be a cone), so their folds fade there; fold sites within " +
        format_number(kFoldTipRadius) +
        " grid edges of it may bend less than asked or the other way and are counted apart");
  }
  return warnings;
}

std::optional<Resolution> lowest_meshing_resolution(const CreasePattern& pattern,
                                                    const Resolution& from,
                                                    const MeshOptions& options) {
  auto grown = [&](int n, double factor) {
    int m = std::max(n + 1, static_cast<int>(std::ceil(n * factor)));
    if (options.build_coarse && m % 2 == 0) ++m;
    return std::min(m, kMaxResolution);
  };
  auto at = [&](double factor) {
    return Resolution{grown(from.nx, factor), grown(from.ny, factor)};
  };
  const CleanPattern clean = clean_pattern(pattern, options.cleaning);  // once for every attempt
  auto meshes = [&](const Resolution& res) {
    try {
      build_from_clean(pattern, clean, res, options);
      return true;
    } catch (const UsageError&) {
      return false;
    }
  };
  // Steps of kResolutionStep until one meshes, then halving the factor between it and the step
  // before, while that gives resolutions in between.
  double below = 1, above = 0;
  Resolution res = from;
  for (double factor = kResolutionStep; factor <= kResolutionReach * (1 + 1e-9);
       factor *= kResolutionStep) {
    const Resolution next = at(factor);
    if (next == res) break;
    res = next;
    if (meshes(res)) {
      above = factor;
      break;
    }
    below = factor;
  }
  if (above == 0) return std::nullopt;
  for (;;) {
    const double mid = 0.5 * (below + above);
    const Resolution candidate = at(mid);
    if (candidate == res || (below > 1 && candidate == at(below)) || candidate == from) break;
    if (meshes(candidate)) {
      above = mid;
      res = candidate;
    } else {
      below = mid;
    }
  }
  return res;
}

}  // namespace sdog
