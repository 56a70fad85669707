#include "geometry/dog_mesh.h"

#include <algorithm>
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

// The crease stitching: the copies of each crease point in the patches that own its grid edge,
// the chained pairs, the patch adjacency and the junctions. Throws std::logic_error for a point
// with fewer than two copies.
CreaseStitching build_stitching(const PatchLayout& layout, const DogMesh& mesh) {
  CreaseStitching st;
  std::vector<std::set<int>> adjacency(layout.patch_count);
  for (size_t k = 0; k < layout.points.size(); ++k) {
    const auto& lp = layout.points[k];
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
    for (size_t c = 0; c + 1 < sp.copies.size(); ++c)
      st.pairs.push_back({static_cast<int>(k), static_cast<int>(c), static_cast<int>(c + 1)});
    for (int a : sp.patches)
      for (int b : sp.patches)
        if (a != b) adjacency[a].insert(b);
    if (sp.patches.size() > 2) st.junctions.push_back(static_cast<int>(k));
    st.points.push_back(std::move(sp));
  }
  for (const auto& s : adjacency) st.patch_adjacency.emplace_back(s.begin(), s.end());
  for (const auto& c : layout.curves) {
    CreaseStitching::Curve curve;
    curve.points = c.points;
    curve.closed = c.closed;
    st.curves.push_back(std::move(curve));
  }
  return st;
}

}  // namespace

DogMesh build_dog_mesh(const PatchLayout& layout, const Eigen::Vector2d& sheet_origin,
                       double scale) {
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
  mesh.stitching = build_stitching(layout, mesh);
  for (const auto& piece : layout.pieces) {
    const auto& cells = patch_cells[piece.patch];
    const auto at = std::lower_bound(cells.begin(), cells.end(), piece.cell) - cells.begin();
    mesh.quad_pieces.push_back({mesh.quad_patch_begin[piece.patch] + static_cast<int>(at), piece.uv});
  }
  std::stable_sort(mesh.quad_pieces.begin(), mesh.quad_pieces.end(),
                   [](const DogMesh::QuadPiece& a, const DogMesh::QuadPiece& b) { return a.quad < b.quad; });
  return mesh;
}

}  // namespace sdog
