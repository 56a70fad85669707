#include "geometry/mesh/alt_coarse.h"

#include <algorithm>
#include <map>
#include <optional>
#include <set>
#include <stdexcept>

namespace sdog {
namespace {

// The quad edges of a mesh, (smaller, larger) vertex.
std::set<std::pair<int, int>> quad_edges(const DogMesh& mesh) {
  std::set<std::pair<int, int>> edges;
  for (int q = 0; q < mesh.quad_count(); ++q)
    for (int k = 0; k < 4; ++k) {
      const int a = mesh.F(q, k), b = mesh.F(q, (k + 1) % 4);
      edges.insert({std::min(a, b), std::max(a, b)});
    }
  return edges;
}

// Does patch p have the four fine quads of the coarse cell with lower-left fine vertex (i, j)?
bool has_coarse_cell(const std::map<QuadCorner, int>& quads, int p, int i, int j) {
  for (int a = 0; a < 2; ++a)
    for (int b = 0; b < 2; ++b)
      if (!quads.count({p, i + a, j + b})) return false;
  return true;
}

// The coarse vertices and quads: per patch, the fine link vertices that are corners of a coarse
// cell the patch has all of, in fine order (so row by row, as vertex_at expects).
void add_vertices_and_quads(const DogMesh& fine, const std::map<QuadCorner, int>& quads,
                            DogMesh& coarse) {
  std::vector<int> kept;
  std::vector<Eigen::Vector4i> F;
  coarse.patch_begin.assign(1, 0);
  coarse.quad_patch_begin.assign(1, 0);
  for (int p = 0; p < fine.patch_count(); ++p) {
    std::set<std::pair<int, int>> corners;  // coarse grid (j, i), row by row
    std::vector<std::array<int, 2>> cells;
    for (int v = fine.patch_begin[p]; v < fine.patch_begin[p + 1]; ++v) {
      const int i = fine.grid[v].x(), j = fine.grid[v].y();
      if (i % 2 || j % 2 || !has_coarse_cell(quads, p, i, j)) continue;
      cells.push_back({i / 2, j / 2});
      for (int a = 0; a < 2; ++a)
        for (int b = 0; b < 2; ++b) corners.insert({j / 2 + b, i / 2 + a});
    }
    const int first = static_cast<int>(kept.size());
    for (const auto& [cj, ci] : corners) {
      kept.push_back(fine.vertex_at(p, 2 * ci, 2 * cj));
      coarse.grid.emplace_back(ci, cj);
      coarse.vertex_patch.push_back(p);
    }
    auto at = [&](int ci, int cj) {
      const auto it = corners.find({cj, ci});
      return first + static_cast<int>(std::distance(corners.begin(), it));
    };
    for (const auto& [ci, cj] : cells)
      F.emplace_back(at(ci, cj), at(ci + 1, cj), at(ci + 1, cj + 1), at(ci, cj + 1));
    coarse.patch_begin.push_back(static_cast<int>(kept.size()));
    coarse.quad_patch_begin.push_back(static_cast<int>(F.size()));
  }
  coarse.V.resize(static_cast<Eigen::Index>(kept.size()), 3);
  for (size_t k = 0; k < kept.size(); ++k)
    coarse.V.row(static_cast<Eigen::Index>(k)) = fine.V.row(kept[k]);
  coarse.F.resize(static_cast<Eigen::Index>(F.size()), 4);
  for (size_t k = 0; k < F.size(); ++k)
    coarse.F.row(static_cast<Eigen::Index>(k)) = F[k].transpose();
}

// The part of each coarse quad's cell in its patch, from the pieces of its four fine cells (a fine
// cell without pieces lies wholly in the patch): listed where some fine cell is cut.
void add_quad_pieces(const DogMesh& fine, const std::map<QuadCorner, int>& fine_quad,
                     DogMesh& coarse) {
  std::map<int, std::vector<const DogMesh::QuadPiece*>> pieces;
  for (const auto& piece : fine.quad_pieces) pieces[piece.quad].push_back(&piece);
  for (int q = 0; q < coarse.quad_count(); ++q) {
    const int v = coarse.F(q, 0), p = coarse.vertex_patch[v];
    const int ci = coarse.grid[v].x(), cj = coarse.grid[v].y();
    const double x0 = coarse.xs[ci], y0 = coarse.ys[cj];
    const double w = coarse.xs[ci + 1] - x0, h = coarse.ys[cj + 1] - y0;
    std::vector<DogMesh::QuadPiece> out;
    bool cut = false;
    for (int b = 0; b < 2; ++b)
      for (int a = 0; a < 2; ++a) {
        const int i = 2 * ci + a, j = 2 * cj + b;
        // Fine cell coordinates to coarse ones.
        auto to_coarse = [&](const Eigen::Vector2d& uv) -> Eigen::Vector2d {
          return {(fine.xs[i] + uv.x() * (fine.xs[i + 1] - fine.xs[i]) - x0) / w,
                  (fine.ys[j] + uv.y() * (fine.ys[j + 1] - fine.ys[j]) - y0) / h};
        };
        const auto it = pieces.find(fine_quad.at({p, i, j}));
        if (it == pieces.end()) {
          out.push_back(
              {q, {to_coarse({0, 0}), to_coarse({1, 0}), to_coarse({1, 1}), to_coarse({0, 1})}});
          continue;
        }
        cut = true;
        for (const auto* piece : it->second) {
          DogMesh::QuadPiece mapped{q, {}};
          for (const auto& uv : piece->uv) mapped.uv.push_back(to_coarse(uv));
          out.push_back(std::move(mapped));
        }
      }
    if (cut) coarse.quad_pieces.insert(coarse.quad_pieces.end(), out.begin(), out.end());
  }
}

// A fine copy of a crease point as a point of the coarse mesh (on a coarse vertex, or on a coarse
// quad edge of its patch), when it is one.
std::optional<EdgePoint> coarse_copy(const DogMesh& fine, const DogMesh& coarse,
                                     const std::set<std::pair<int, int>>& edges,
                                     const EdgePoint& e) {
  const int p = fine.vertex_patch[e.v1];
  const Eigen::Vector2i g1 = fine.grid[e.v1], g2 = fine.grid[e.v2];
  if (e.v1 == e.v2) {
    if (g1.x() % 2 || g1.y() % 2) return std::nullopt;
    const int c = coarse.vertex_at(p, g1.x() / 2, g1.y() / 2);
    if (c < 0) return std::nullopt;
    return EdgePoint{c, c, 1};
  }
  const bool first_link = g1.x() % 2 == 0 && g1.y() % 2 == 0;
  const bool second_link = g2.x() % 2 == 0 && g2.y() % 2 == 0;
  if (first_link == second_link) return std::nullopt;  // an edge on an odd grid line
  // The link end L, the I vertex M (the coarse edge's midpoint) and the far end L + 2 (M - L).
  const Eigen::Vector2i link = first_link ? g1 : g2, mid = first_link ? g2 : g1;
  const Eigen::Vector2i far = 2 * mid - link;
  const int a = coarse.vertex_at(p, link.x() / 2, link.y() / 2);
  const int b = coarse.vertex_at(p, far.x() / 2, far.y() / 2);
  if (a < 0 || b < 0 || !edges.count({std::min(a, b), std::max(a, b)})) return std::nullopt;
  // The point's weight on L: t * V(v1) + (1 - t) * V(v2) with V(M) = (V(L) + V(far)) / 2.
  const double on_link = first_link ? (1 + e.t) / 2 : 1 - e.t / 2;
  const bool link_first = link.x() + link.y() < far.x() + far.y();  // v1: the smaller grid end
  return link_first ? EdgePoint{a, b, on_link} : EdgePoint{b, a, 1 - on_link};
}

// The coarse stitching: the fine crease points all of whose copies are coarse points, with the
// fine pairs between them, the curves through them and the patch adjacency they give.
void add_stitching(const DogMesh& fine, DogMesh& coarse) {
  const std::set<std::pair<int, int>> edges = quad_edges(coarse);
  const CreaseStitching& fs = fine.stitching;
  CreaseStitching& cs = coarse.stitching;
  std::vector<int> index(fs.points.size(), -1);
  std::vector<std::set<int>> adjacency(fine.patch_count());
  for (size_t k = 0; k < fs.points.size(); ++k) {
    const auto& fp = fs.points[k];
    CreaseStitching::Point cp{fp.flat, {}, fp.patches};
    for (const EdgePoint& e : fp.copies)
      if (const auto c = coarse_copy(fine, coarse, edges, e)) cp.copies.push_back(*c);
    if (cp.copies.size() != fp.copies.size()) continue;
    index[k] = static_cast<int>(cs.points.size());
    for (int a : cp.patches)
      for (int b : cp.patches)
        if (a != b) adjacency[a].insert(b);
    if (cp.patches.size() > 2) cs.junctions.push_back(index[k]);
    cs.points.push_back(std::move(cp));
  }
  for (const auto& pair : fs.pairs)
    if (index[pair.point] >= 0) cs.pairs.push_back({index[pair.point], pair.a, pair.b});
  for (const auto& s : adjacency) cs.patch_adjacency.emplace_back(s.begin(), s.end());
  for (const auto& fc : fs.curves) {
    CreaseStitching::Curve curve = fc;
    curve.points.clear();
    for (int p : fc.points)
      if (index[p] >= 0) curve.points.push_back(index[p]);
    cs.curves.push_back(std::move(curve));
  }
}

}  // namespace

DogMesh build_alt_coarse_mesh(const DogMesh& fine) {
  if (fine.nx() % 2 == 0 || fine.ny() % 2 == 0)
    throw std::logic_error("the alternative coarse DOG needs a fine DOG on a nested grid");
  DogMesh coarse;
  coarse.sheet_origin = fine.sheet_origin;
  coarse.scale = fine.scale;
  for (int i = 0; i < fine.nx(); i += 2) coarse.xs.push_back(fine.xs[i]);
  for (int j = 0; j < fine.ny(); j += 2) coarse.ys.push_back(fine.ys[j]);
  coarse.fold_tips = fine.fold_tips;
  const std::map<QuadCorner, int> fine_quads = quads_by_corner(fine);
  add_vertices_and_quads(fine, fine_quads, coarse);
  add_quad_pieces(fine, fine_quads, coarse);
  add_stitching(fine, coarse);
  return coarse;
}

FineCoarseMap build_alt_fine_coarse_map(const DogMesh& fine, const DogMesh& coarse) {
  const int nf = fine.vertex_count();
  FineCoarseMap map = unmapped(nf, coarse.vertex_count(), VertexType::kLink);
  const std::map<QuadCorner, int> coarse_quad = quads_by_corner(coarse);
  const std::set<std::pair<int, int>> edges = quad_edges(coarse);
  for (int f = 0; f < nf; ++f) {
    const int p = fine.vertex_patch[f], i = fine.grid[f].x(), j = fine.grid[f].y();
    bool covered = false;
    if (i % 2 == 0 && j % 2 == 0) {
      map.fine_type[f] = VertexType::kLink;
      if (const int c = coarse.vertex_at(p, i / 2, j / 2); c >= 0) {
        map.fine_to_coarse[f] = c;
        map.coarse_to_fine[c] = f;
        covered = true;
      }
    } else if (i % 2 == 1 && j % 2 == 1) {
      if (const auto it = coarse_quad.find({p, (i - 1) / 2, (j - 1) / 2});
          it != coarse_quad.end()) {
        map.fine_to_coarse_quad[f] = it->second;
        covered = true;
      }
    } else {
      map.fine_type[f] = VertexType::kI;
      const int a = coarse.vertex_at(p, (i - i % 2) / 2, (j - j % 2) / 2);
      const int b = coarse.vertex_at(p, (i + i % 2) / 2, (j + j % 2) / 2);
      if (a >= 0 && b >= 0 && edges.count({std::min(a, b), std::max(a, b)})) {
        map.fine_to_coarse_edge[f] = {a, b};
        covered = true;
      }
    }
    map.uncovered_count += !covered;
  }
  count_vertex_types(map);
  // Coarse crease points are fine ones, in the same order along each crease.
  const auto& fs = fine.stitching;
  const auto& cs = coarse.stitching;
  for (size_t k = 0; k < fs.curves.size(); ++k) {
    std::vector<int> coarse_at;
    const auto& fc = fs.curves[k];
    const auto& cc = cs.curves[k];
    for (size_t f = 0; f < fc.points.size() && coarse_at.size() < cc.points.size(); ++f)
      if (fs.points[fc.points[f]].flat == cs.points[cc.points[coarse_at.size()]].flat)
        coarse_at.push_back(static_cast<int>(f));
    map.curves.push_back(interpolated_curve(fs, fc, coarse_at));
  }
  return map;
}

}  // namespace sdog
