#include "geometry/mesh/fine_coarse_map.h"

#include <algorithm>
#include <map>
#include <stdexcept>

#include "base/errors.h"
#include "base/text_format.h"

namespace sdog {

std::vector<int> match_coarse_patches(const PatchLayout& fine, const PatchLayout& coarse) {
  const int nf = fine.patch_count, nc = coarse.patch_count;
  const int ccx = coarse.nx() - 1, fcx = fine.nx() - 1;
  // Shared cells, counted heavily where both cells belong to one patch only (no crease near).
  std::vector<std::vector<long long>> score(nc, std::vector<long long>(nf, 0));
  for (int cell = 0; cell < coarse.cell_count(); ++cell) {
    const int I = cell % ccx, J = cell / ccx;
    for (int a = 0; a < 2; ++a)
      for (int b = 0; b < 2; ++b) {
        const int fcell = (2 * J + b) * fcx + 2 * I + a;
        const bool uncut = coarse.owner_count(cell) == 1 && fine.owner_count(fcell) == 1;
        for (int k = 0; k < coarse.owner_count(cell); ++k)
          for (int l = 0; l < fine.owner_count(fcell); ++l)
            score[coarse.owners(cell)[k]][fine.owners(fcell)[l]] += uncut ? 1000 : 1;
      }
  }
  // Greedy assignment, best-scoring pairs first.
  std::vector<std::tuple<long long, int, int>> pairs;
  for (int c = 0; c < nc; ++c)
    for (int f = 0; f < nf; ++f)
      if (score[c][f] > 0) pairs.emplace_back(-score[c][f], c, f);
  std::sort(pairs.begin(), pairs.end());
  std::vector<int> match(nc, -1);
  std::vector<char> used(nf, 0);
  int matched = 0;
  for (const auto& [neg, c, f] : pairs) {
    if (match[c] >= 0 || used[f]) continue;
    match[c] = f;
    used[f] = 1;
    ++matched;
  }
  if (nc != nf || matched != nc)
    throw UsageError("the coarse grid cannot tell the patches apart (" + std::to_string(nc) +
                     " coarse patches for " + std::to_string(nf) +
                     " fine ones); use a higher resolution");
  return match;
}

int cover_fine_patches(PatchLayout& coarse, const PatchLayout& fine) {
  const int ccx = coarse.nx() - 1, fcx = fine.nx() - 1;
  std::vector<int> offsets{0}, patches;
  int added = 0;
  for (int cell = 0; cell < coarse.cell_count(); ++cell) {
    std::vector<int> owners(coarse.owners(cell), coarse.owners(cell) + coarse.owner_count(cell));
    const size_t own = owners.size();
    const int I = cell % ccx, J = cell / ccx;
    for (int a = 0; a < 2; ++a)
      for (int b = 0; b < 2; ++b) {
        const int fcell = (2 * J + b) * fcx + 2 * I + a;
        owners.insert(owners.end(), fine.owners(fcell),
                      fine.owners(fcell) + fine.owner_count(fcell));
      }
    std::sort(owners.begin(), owners.end());
    owners.erase(std::unique(owners.begin(), owners.end()), owners.end());
    added += static_cast<int>(owners.size() - own);
    for (int p : owners)  // an added owner has no part of the coarse cell: an empty piece
      if (!std::binary_search(coarse.owners(cell), coarse.owners(cell) + own, p))
        coarse.pieces.push_back({cell, p, {}});
    patches.insert(patches.end(), owners.begin(), owners.end());
    offsets.push_back(static_cast<int>(patches.size()));
  }
  coarse.cell_offsets = std::move(offsets);
  coarse.cell_patches = std::move(patches);
  return added;
}

namespace {

// Arc length along a crease curve of the flat fine mesh, from point index 0.
std::vector<double> arc_lengths(const CreaseStitching& st, const CreaseStitching::Curve& curve) {
  std::vector<double> s{0.0};
  const size_t n = curve.points.size();
  for (size_t k = 0; k + 1 < n + (curve.closed ? 1 : 0); ++k)
    s.push_back(
        s.back() +
        (st.points[curve.points[(k + 1) % n]].flat - st.points[curve.points[k]].flat).norm());
  return s;
}

// The error for fine vertex f when the coarse mesh has no vertex or quad for it in its patch.
std::logic_error uncovered(const DogMesh& fine, int f) {
  return std::logic_error("the coarse mesh does not cover fine patch " +
                          std::to_string(fine.vertex_patch[f]) + " near " +
                          format_point(fine.V.row(f).head<2>().transpose()));
}

// Types of the fine vertices by the parity of their grid position, with their coarse vertex,
// edge or quad; coarse vertices with a fine twin become links.
void map_vertices(const DogMesh& fine, const DogMesh& coarse, FineCoarseMap& map) {
  const std::map<QuadCorner, int> coarse_quad = quads_by_corner(coarse);
  for (int f = 0; f < fine.vertex_count(); ++f) {
    const int p = fine.vertex_patch[f];
    const int i = fine.grid[f].x(), j = fine.grid[f].y();
    if (i % 2 == 0 && j % 2 == 0) {
      const int c = coarse.vertex_at(p, i / 2, j / 2);
      if (c < 0) throw uncovered(fine, f);
      map.fine_type[f] = VertexType::kLink;
      map.fine_to_coarse[f] = c;
      map.coarse_to_fine[c] = f;
      map.coarse_type[c] = VertexType::kLink;
    } else if (i % 2 == 1 && j % 2 == 1) {
      auto it = coarse_quad.find({p, (i - 1) / 2, (j - 1) / 2});
      if (it == coarse_quad.end()) throw uncovered(fine, f);
      map.fine_type[f] = VertexType::kX;
      map.fine_to_coarse_quad[f] = it->second;
    } else {
      const int a = coarse.vertex_at(p, (i - i % 2) / 2, (j - j % 2) / 2);
      const int b = coarse.vertex_at(p, (i + i % 2) / 2, (j + j % 2) / 2);
      if (a < 0 || b < 0) throw uncovered(fine, f);
      map.fine_type[f] = VertexType::kI;
      map.fine_to_coarse_edge[f] = {a, b};
    }
  }
}

// The fine index of each coarse point of a curve, in order: the first fine point after the
// previous match within tol of it. Fewer than the coarse points when one has no match.
std::vector<int> matching_points(const CreaseStitching::Curve& fc, const CreaseStitching& fs,
                                 const CreaseStitching::Curve& cc, const CreaseStitching& cs,
                                 double tol) {
  std::vector<int> fine_at;
  size_t next = 0;
  for (size_t f = 0; f < fc.points.size() && next < cc.points.size(); ++f) {
    if ((fs.points[fc.points[f]].flat - cs.points[cc.points[next]].flat).norm() <= tol) {
      fine_at.push_back(static_cast<int>(f));
      ++next;
    }
  }
  return fine_at;
}

// Fine crease curve k against coarse curve k: coarse crease points are fine crease points at the
// same flat position (within tol); the fine points between them get their arc-length fraction.
std::vector<FineCoarseMap::CurvePoint> map_curve(const CreaseStitching& fs,
                                                 const CreaseStitching& cs, size_t k, double tol) {
  const auto& fc = fs.curves[k];
  const auto& cc = cs.curves[k];
  std::vector<int> coarse_at = matching_points(fc, fs, cc, cs, tol);
  if (coarse_at.size() != cc.points.size() || coarse_at.empty() || coarse_at.front() != 0)
    coarse_at = matching_points(fc, fs, cc, cs, 2 * kVertexCreaseDistance);
  if (coarse_at.size() != cc.points.size() || coarse_at.empty() || coarse_at.front() != 0)
    throw std::logic_error("coarse crease " + std::to_string(k) +
                           " is not a subset of the fine one");
  return interpolated_curve(fs, fc, coarse_at);
}

}  // namespace

FineCoarseMap build_fine_coarse_map(const DogMesh& fine, const DogMesh& coarse) {
  FineCoarseMap map = unmapped(fine.vertex_count(), coarse.vertex_count(), VertexType::kCoarseOnly);
  map_vertices(fine, coarse, map);
  count_vertex_types(map);

  // Crease curves: coarse crease points are fine crease points at the same flat position.
  const auto& fs = fine.stitching;
  const auto& cs = coarse.stitching;
  if (fs.curves.size() != cs.curves.size())
    throw std::logic_error("fine and coarse meshes have different numbers of creases");
  const double tol =
      1e-9 * std::max(fine.xs.back() - fine.xs.front(), fine.ys.back() - fine.ys.front());
  for (size_t k = 0; k < fs.curves.size(); ++k) map.curves.push_back(map_curve(fs, cs, k, tol));
  return map;
}

std::vector<FineCoarseMap::CurvePoint> interpolated_curve(const CreaseStitching& fine,
                                                          const CreaseStitching::Curve& curve,
                                                          const std::vector<int>& coarse_at) {
  const int n = static_cast<int>(curve.points.size());
  std::vector<FineCoarseMap::CurvePoint> out(n);
  for (size_t c = 0; c < coarse_at.size(); ++c) {
    out[coarse_at[c]].coarse = static_cast<int>(c);
    out[coarse_at[c]].segment = static_cast<int>(c);
  }
  const auto s = arc_lengths(fine, curve);  // closed: s[n] is the whole loop
  auto arc = [&](int f) { return f < n ? s[f] : s[n] + s[f - n]; };
  std::vector<int> at = coarse_at;
  if (curve.closed && !at.empty()) at.push_back(at.front() + n);  // back to the first kept point
  for (size_t m = 0; m + 1 < at.size(); ++m) {
    const int a = at[m], b = at[m + 1];
    for (int f = a + 1; f < b; ++f) {
      out[f % n].segment = static_cast<int>(m);
      out[f % n].fraction = (arc(f) - arc(a)) / (arc(b) - arc(a));
    }
  }
  return out;
}

FineCoarseMap unmapped(int fine_vertices, int coarse_vertices, VertexType coarse_type) {
  FineCoarseMap map;
  map.fine_type.assign(fine_vertices, VertexType::kX);
  map.coarse_type.assign(coarse_vertices, coarse_type);
  map.fine_to_coarse.assign(fine_vertices, -1);
  map.coarse_to_fine.assign(coarse_vertices, -1);
  map.fine_to_coarse_edge.assign(fine_vertices, {-1, -1});
  map.fine_to_coarse_quad.assign(fine_vertices, -1);
  return map;
}

void count_vertex_types(FineCoarseMap& map) {
  map.link_count = map.i_count = map.x_count = 0;
  for (auto t : map.fine_type) {
    if (t == VertexType::kLink) ++map.link_count;
    if (t == VertexType::kI) ++map.i_count;
    if (t == VertexType::kX) ++map.x_count;
  }
  map.coarse_only_count = static_cast<int>(
      std::count(map.coarse_type.begin(), map.coarse_type.end(), VertexType::kCoarseOnly));
}

CurveCoverage curve_coverage(const FineCoarseMap& map) {
  CurveCoverage c;
  for (const auto& curve : map.curves)
    for (const auto& p : curve) {
      if (p.coarse >= 0)
        ++c.kept;
      else if (p.segment >= 0)
        ++c.interpolated;
      else
        ++c.uninterpolable;
    }
  return c;
}

}  // namespace sdog
