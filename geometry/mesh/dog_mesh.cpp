#include "geometry/mesh/dog_mesh.h"

#include <algorithm>
#include <array>
#include <optional>
#include <set>
#include <stdexcept>

#include "base/text_format.h"

namespace sdog {

int DogMesh::vertex_at(int patch, int i, int j) const {
  const auto begin = grid.begin() + patch_begin[patch];
  const auto end = grid.begin() + patch_begin[patch + 1];
  const Eigen::Vector2i key(i, j);
  auto less = [](const Eigen::Vector2i& a, const Eigen::Vector2i& b) {
    return a.y() < b.y() || (a.y() == b.y() && a.x() < b.x());
  };
  auto it = std::lower_bound(begin, end, key, less);
  return (it != end && *it == key) ? static_cast<int>(it - grid.begin()) : -1;
}

std::map<QuadCorner, int> quads_by_corner(const DogMesh& mesh) {
  std::map<QuadCorner, int> quads;
  for (int q = 0; q < mesh.quad_count(); ++q) {
    const int v = mesh.F(q, 0);
    quads[{mesh.vertex_patch[v], mesh.grid[v].x(), mesh.grid[v].y()}] = q;
  }
  return quads;
}

namespace {

bool owns_cell(const PatchLayout& layout, int patch, int i, int j) {
  if (i < 0 || j < 0 || i >= layout.nx() - 1 || j >= layout.ny() - 1) return false;
  const int cell = j * (layout.nx() - 1) + i;
  const int* o = layout.owners(cell);
  return std::binary_search(o, o + layout.owner_count(cell), patch);
}

// Does patch p have the grid edge of e as a quad edge (or the vertex, for a point on a vertex)?
bool owns_edge(const PatchLayout& layout, int p, const GridEdgePoint& e) {
  if (e.on_vertex()) {
    for (int di = -1; di <= 0; ++di)
      for (int dj = -1; dj <= 0; ++dj)
        if (owns_cell(layout, p, e.i0 + di, e.j0 + dj)) return true;
    return false;
  }
  if (e.i0 == e.i1)  // vertical edge on line i0 between rows j0 and j0 + 1
    return owns_cell(layout, p, e.i0 - 1, e.j0) || owns_cell(layout, p, e.i0, e.j0);
  return owns_cell(layout, p, e.i0, e.j0 - 1) || owns_cell(layout, p, e.i0, e.j0);
}

// The cells of each patch, ascending.
std::vector<std::vector<int>> cells_of_patches(const PatchLayout& layout) {
  std::vector<std::vector<int>> patch_cells(layout.patch_count);
  for (int c = 0; c < layout.cell_count(); ++c)
    for (int k = 0; k < layout.owner_count(c); ++k) patch_cells[layout.owners(c)[k]].push_back(c);
  return patch_cells;
}

// Appends patch p, made of `cells`, to the mesh: its vertices (the cells' corners, row by row) to
// V with their grid positions, and its quads to F; then closes its vertex and quad ranges.
void add_patch(int p, const std::vector<int>& cells, int nx, DogMesh& mesh,
               std::vector<Eigen::Vector3d>& V, std::vector<Eigen::Vector4i>& F) {
  const int ncx = nx - 1;
  std::vector<long long> keys;  // j * nx + i: row-major order
  for (int c : cells) {
    const long long i = c % ncx, j = c / ncx;
    for (long long dj = 0; dj < 2; ++dj)
      for (long long di = 0; di < 2; ++di) keys.push_back((j + dj) * nx + i + di);
  }
  std::sort(keys.begin(), keys.end());
  keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
  const int base = static_cast<int>(V.size());
  for (long long key : keys) {
    const int i = static_cast<int>(key % nx), j = static_cast<int>(key / nx);
    V.emplace_back(mesh.xs[i], mesh.ys[j], 0.0);
    mesh.grid.emplace_back(i, j);
    mesh.vertex_patch.push_back(p);
  }
  auto index = [&](long long i, long long j) {
    return base +
           static_cast<int>(std::lower_bound(keys.begin(), keys.end(), j * nx + i) - keys.begin());
  };
  for (int c : cells) {
    const long long i = c % ncx, j = c / ncx;
    F.emplace_back(index(i, j), index(i + 1, j), index(i + 1, j + 1), index(i, j + 1));
  }
  mesh.patch_begin.push_back(static_cast<int>(V.size()));
  mesh.quad_patch_begin.push_back(static_cast<int>(F.size()));
}

// The grid vertex that crease points a and b (consecutive along a crease, between the same two
// patches, each strictly inside a grid edge) both lie within kVertexCreaseDistance of, as an
// on-vertex point, if there is one and the nesting allows it (build_dog_mesh).
std::optional<GridEdgePoint> shared_vertex(const PatchLayout::CreasePoint& a,
                                           const PatchLayout::CreasePoint& b, const DogMesh& mesh,
                                           int coarse_step) {
  if (a.edge.on_vertex() || b.edge.on_vertex() || a.patches.size() != 2 || a.patches != b.patches)
    return std::nullopt;
  const Eigen::Vector2i ends_a[2] = {{a.edge.i0, a.edge.j0}, {a.edge.i1, a.edge.j1}};
  const Eigen::Vector2i ends_b[2] = {{b.edge.i0, b.edge.j0}, {b.edge.i1, b.edge.j1}};
  for (const auto& v : ends_a)
    for (const auto& w : ends_b) {
      if (v != w) continue;
      const Eigen::Vector2d corner(mesh.xs[v.x()], mesh.ys[v.y()]);
      if ((mesh.to_mesh(a.position) - corner).norm() >= kVertexCreaseDistance ||
          (mesh.to_mesh(b.position) - corner).norm() >= kVertexCreaseDistance)
        continue;
      if (coarse_step > 1 && (v.x() % coarse_step == 0) != (v.y() % coarse_step == 0)) continue;
      return GridEdgePoint{v.x(), v.y(), v.x(), v.y(), 1.0};
    }
  return std::nullopt;
}

// The layout's crease points and curves with every run of points at one place on a grid edge
// taken as one of them, and every pair that passes close to a grid vertex replaced by one point on
// it (build_dog_mesh): the vertex points are appended to `points`, `taken` marks the points left
// out, and the curves refer to the points that stay.
void merge_close_points(const PatchLayout& layout, const DogMesh& mesh, int coarse_step,
                        std::vector<PatchLayout::CreasePoint>& points,
                        std::vector<PatchLayout::Curve>& curves, std::vector<bool>& taken) {
  points = layout.points;
  curves = layout.curves;
  taken.assign(points.size(), false);
  std::vector<int> uses(points.size(), 0);
  for (const auto& c : curves)
    for (int p : c.points) ++uses[p];
  // A crease that touches a grid line crosses it back and forth at one place: a run of
  // consecutive points on one grid edge, between the same two patches and within
  // kVertexCreaseDistance of the run's first, has nearly equal stitching rows that restoration
  // cannot meet together once the sheet bends (the gaps stall equal and opposite). The run is
  // taken as its middle point.
  // On a fine mesh with a coarse twin (coarse_step > 1), points on a coarse grid line count as on
  // one edge when they are on one coarse edge, so the fine mesh takes the same middle point as the
  // coarse one and the coarse crease points stay fine crease points.
  auto edge_key = [&](const GridEdgePoint& e) {
    const int c = std::max(coarse_step, 1);
    if (e.i0 == e.i1 && e.i0 % c == 0) return std::array<int, 5>{0, e.i0, e.j0 / c, 0, 0};
    if (e.j0 == e.j1 && e.j0 % c == 0) return std::array<int, 5>{1, e.j0, e.i0 / c, 0, 0};
    return std::array<int, 5>{2, e.i0, e.j0, e.i1, e.j1};
  };
  auto same_place = [&](int a, int b) {
    const auto &p = points[a], &q = points[b];
    return uses[a] == 1 && uses[b] == 1 && !p.edge.on_vertex() && !q.edge.on_vertex() &&
           p.patches.size() == 2 && p.patches == q.patches &&
           edge_key(p.edge) == edge_key(q.edge) &&
           (mesh.to_mesh(p.position) - mesh.to_mesh(q.position)).norm() < kVertexCreaseDistance;
  };
  for (auto& c : curves) {
    std::vector<int> out;
    for (size_t k = 0; k < c.points.size();) {
      size_t m = k + 1;
      while (m < c.points.size() && same_place(c.points[k], c.points[m])) ++m;
      const size_t middle = k + (m - k) / 2;
      for (size_t r = k; r < m; ++r)
        if (r != middle) taken[c.points[r]] = true;
      out.push_back(c.points[middle]);
      k = m;
    }
    c.points = std::move(out);
  }
  // The vertex point replacing a and b, or -1 when they stay.
  auto vertex_point = [&](int a, int b) {
    if (uses[a] != 1 || uses[b] != 1 || taken[a] || taken[b]) return -1;
    const auto vertex = shared_vertex(points[a], points[b], mesh, coarse_step);
    if (!vertex) return -1;
    PatchLayout::CreasePoint merged;
    merged.edge = *vertex;
    merged.position = Eigen::Vector2d(layout.xs[vertex->i0], layout.ys[vertex->j0]);
    merged.patches = points[a].patches;
    points.push_back(merged);
    taken[a] = taken[b] = true;
    taken.push_back(false);
    return static_cast<int>(points.size()) - 1;
  };
  for (auto& c : curves) {
    const int n = static_cast<int>(c.points.size());
    std::vector<int> out;
    // A closed curve's last and first points first.
    const int wrapped = c.closed && n > 2 ? vertex_point(c.points[n - 1], c.points[0]) : -1;
    if (wrapped >= 0) out.push_back(wrapped);
    const int begin = wrapped >= 0 ? 1 : 0, end = wrapped >= 0 ? n - 1 : n;
    for (int k = begin; k < end; ++k) {
      const int merged = k + 1 < end ? vertex_point(c.points[k], c.points[k + 1]) : -1;
      out.push_back(merged >= 0 ? merged : c.points[k]);
      if (merged >= 0) ++k;
    }
    c.points = std::move(out);
  }
}

// The crease stitching: the copies of each crease point in the patches that own its grid edge,
// the chained pairs (none for a point on slits only), the patch adjacency and the junctions. Throws
// std::logic_error for a point with fewer than two copies.
CreaseStitching build_stitching(const PatchLayout& layout, const DogMesh& mesh, int coarse_step) {
  std::vector<PatchLayout::CreasePoint> points;
  std::vector<PatchLayout::Curve> curves;
  std::vector<bool> taken;
  merge_close_points(layout, mesh, coarse_step, points, curves, taken);
  std::vector<int> index(points.size(), -1), used;  // the points kept, renumbered
  for (size_t k = 0; k < points.size(); ++k)
    if (!taken[k]) {
      index[k] = static_cast<int>(used.size());
      used.push_back(static_cast<int>(k));
    }
  // Points that lie on slits only are not stitched: a slit's two sides are free.
  std::vector<char> stitched(points.size(), 0);
  for (const auto& c : curves)
    if (!c.slit)
      for (int p : c.points) stitched[p] = 1;
  CreaseStitching st;
  std::vector<std::set<int>> adjacency(layout.patch_count);
  for (size_t k = 0; k < used.size(); ++k) {
    const auto& lp = points[used[k]];
    CreaseStitching::Point sp;
    sp.flat = mesh.to_mesh(lp.position);
    for (int p : lp.patches) {
      if (!owns_edge(layout, p, lp.edge)) continue;
      const int v1 = mesh.vertex_at(p, lp.edge.i0, lp.edge.j0);
      const int v2 = mesh.vertex_at(p, lp.edge.i1, lp.edge.j1);
      sp.copies.push_back({v1, v2, lp.edge.t});
      sp.patches.push_back(p);
    }
    if (sp.copies.size() < 2)
      throw std::logic_error("crease point " + format_point(lp.position) + " has " +
                             std::to_string(sp.copies.size()) + " copies");
    for (size_t c = 0; stitched[used[k]] && c + 1 < sp.copies.size(); ++c)
      st.pairs.push_back({static_cast<int>(k), static_cast<int>(c), static_cast<int>(c + 1)});
    for (int a : sp.patches)
      for (int b : sp.patches)
        if (a != b) adjacency[a].insert(b);
    if (sp.patches.size() > 2) st.junctions.push_back(static_cast<int>(k));
    st.points.push_back(std::move(sp));
  }
  for (const auto& s : adjacency) st.patch_adjacency.emplace_back(s.begin(), s.end());
  for (const auto& c : curves) {
    CreaseStitching::Curve curve;
    for (int p : c.points) curve.points.push_back(index[p]);
    curve.closed = c.closed;
    st.curves.push_back(std::move(curve));
  }
  return st;
}

}  // namespace

DogMesh build_dog_mesh(const PatchLayout& layout, const Eigen::Vector2d& sheet_origin, double scale,
                       int coarse_step) {
  DogMesh mesh;
  mesh.sheet_origin = sheet_origin;
  mesh.scale = scale;
  for (double x : layout.xs) mesh.xs.push_back((x - sheet_origin.x()) * scale);
  for (double y : layout.ys) mesh.ys.push_back((y - sheet_origin.y()) * scale);

  const std::vector<std::vector<int>> patch_cells = cells_of_patches(layout);
  std::vector<Eigen::Vector3d> V;
  std::vector<Eigen::Vector4i> F;
  mesh.patch_begin.assign(1, 0);
  mesh.quad_patch_begin.assign(1, 0);
  for (int p = 0; p < layout.patch_count; ++p)
    add_patch(p, patch_cells[p], layout.nx(), mesh, V, F);
  mesh.V.resize(static_cast<Eigen::Index>(V.size()), 3);
  for (size_t k = 0; k < V.size(); ++k) mesh.V.row(static_cast<Eigen::Index>(k)) = V[k].transpose();
  mesh.F.resize(static_cast<Eigen::Index>(F.size()), 4);
  for (size_t k = 0; k < F.size(); ++k) mesh.F.row(static_cast<Eigen::Index>(k)) = F[k].transpose();
  mesh.stitching = build_stitching(layout, mesh, coarse_step);
  for (const auto& piece : layout.pieces) {
    const auto& cells = patch_cells[piece.patch];
    const auto at = std::lower_bound(cells.begin(), cells.end(), piece.cell) - cells.begin();
    mesh.quad_pieces.push_back(
        {mesh.quad_patch_begin[piece.patch] + static_cast<int>(at), piece.uv});
  }
  std::stable_sort(
      mesh.quad_pieces.begin(), mesh.quad_pieces.end(),
      [](const DogMesh::QuadPiece& a, const DogMesh::QuadPiece& b) { return a.quad < b.quad; });
  return mesh;
}

}  // namespace sdog
