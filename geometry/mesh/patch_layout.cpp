#include "geometry/mesh/patch_layout.h"

#include <CGAL/Arr_batched_point_location.h>
#include <CGAL/Arr_segment_traits_2.h>
#include <CGAL/Arrangement_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>

#include <algorithm>
#include <map>
#include <numeric>
#include <stdexcept>
#include <unordered_map>

#include "base/errors.h"
#include "base/text_format.h"
#include "geometry/pattern/plane_geometry.h"

namespace sdog {
namespace {

using K = CGAL::Epeck;
using FT = K::FT;
using Point = K::Point_2;
using Traits = CGAL::Arr_segment_traits_2<K>;
using Arrangement = CGAL::Arrangement_2<Traits>;
using LocateResult = CGAL::Arr_point_location_result<Arrangement>::Type;
using Poly = std::vector<Point>;

Point exact(const Eigen::Vector2d& p) {
  return Point(p.x(), p.y());
}
Eigen::Vector2d approx(const Point& p) {
  return {CGAL::to_double(p.x()), CGAL::to_double(p.y())};
}

std::vector<FT> exact_lines(const AxisLayout& a) {
  std::vector<FT> out(a.n);
  for (size_t k = 0; k + 1 < a.anchors.size(); ++k) {
    const int i0 = a.anchors[k].first, i1 = a.anchors[k + 1].first;
    const FT v0(a.anchors[k].second), v1(a.anchors[k + 1].second);
    for (int i = i0; i <= i1; ++i) out[i] = v0 + (v1 - v0) * FT(i - i0) / FT(i1 - i0);
  }
  for (auto& v : out) v.exact();  // resolve lazily built values once
  return out;
}

// Index of the line at exactly v, or -1.
int line_at(const std::vector<FT>& lines, const FT& v) {
  auto it = std::lower_bound(lines.begin(), lines.end(), v);
  return (it != lines.end() && *it == v) ? static_cast<int>(it - lines.begin()) : -1;
}

// Index i of the interval [lines[i], lines[i+1]) containing v, clamped to the grid.
int interval_at(const std::vector<FT>& lines, const FT& v) {
  const int i =
      static_cast<int>(std::upper_bound(lines.begin(), lines.end(), v) - lines.begin()) - 1;
  return std::clamp(i, 0, static_cast<int>(lines.size()) - 2);
}

FT cross(const FT& ax, const FT& ay, const FT& bx, const FT& by) {
  return ax * by - ay * bx;
}

class Grid {
 public:
  Grid(const AxisLayout& x, const AxisLayout& y) : X(exact_lines(x)), Y(exact_lines(y)) {}
  std::vector<FT> X, Y;
  int nx() const { return static_cast<int>(X.size()); }
  int ny() const { return static_cast<int>(Y.size()); }

  bool on_line(const Point& p, int stride = 1) const {
    const int i = line_at(X, p.x()), j = line_at(Y, p.y());
    return (i >= 0 && i % stride == 0) || (j >= 0 && j % stride == 0);
  }

  // Appends the crossings of segment a->b with the grid lines (strictly inside the segment, in
  // order), then b itself if it lies on a line.
  void append_segment(const Point& a, const Point& b, Poly& out) const {
    std::vector<std::pair<FT, Point>> hits;
    auto add_axis = [&](const std::vector<FT>& lines, const FT& a_c, const FT& b_c, bool is_x) {
      if (a_c == b_c) return;
      const FT lo = CGAL::min(a_c, b_c), hi = CGAL::max(a_c, b_c);
      for (auto it = std::upper_bound(lines.begin(), lines.end(), lo);
           it != lines.end() && *it < hi; ++it) {
        const FT s = (*it - a_c) / (b_c - a_c);
        hits.push_back({s, is_x ? Point(*it, a.y() + s * (b.y() - a.y()))
                                : Point(a.x() + s * (b.x() - a.x()), *it)});
      }
    };
    add_axis(X, a.x(), b.x(), true);
    add_axis(Y, a.y(), b.y(), false);
    std::sort(hits.begin(), hits.end(),
              [](const auto& u, const auto& v) { return u.first < v.first; });
    for (const auto& h : hits)
      if (out.empty() || out.back() != h.second) out.push_back(h.second);
    if (on_line(b) && (out.empty() || out.back() != b)) out.push_back(b);
  }

  Poly snap_open(const Polyline2& pts) const {
    Poly out{exact(pts.front())};
    if (!on_line(out.front()))
      throw std::logic_error("crease end " + format_point(pts.front()) + " is not on a grid line");
    for (size_t i = 0; i + 1 < pts.size(); ++i)
      append_segment(exact(pts[i]), exact(pts[i + 1]), out);
    return out;
  }

  // Crossings of a closed curve, starting at its first crossing with a line of index divisible
  // by `stride`. Empty when the curve crosses no such line.
  Poly snap_closed(const Polyline2& pts, int stride) const {
    Poly out;
    for (size_t i = 0; i < pts.size(); ++i)
      append_segment(exact(pts[i]), exact(pts[(i + 1) % pts.size()]), out);
    if (out.size() > 1 && out.front() == out.back()) out.pop_back();
    auto start =
        std::find_if(out.begin(), out.end(), [&](const Point& p) { return on_line(p, stride); });
    if (start == out.end()) return {};
    std::rotate(out.begin(), start, out.end());
    return out;
  }

  Point cell_centre(int i, int j) const {
    return Point((X[i] + X[i + 1]) / 2, (Y[j] + Y[j + 1]) / 2);
  }

  GridEdgePoint edge_point(const Point& p) const {
    const int i = line_at(X, p.x()), j = line_at(Y, p.y());
    GridEdgePoint e;
    if (i >= 0 && j >= 0) {
      e.i0 = e.i1 = i;
      e.j0 = e.j1 = j;
      e.t = 1;
    } else if (i >= 0) {
      const int r = interval_at(Y, p.y());
      e.i0 = e.i1 = i;
      e.j0 = r;
      e.j1 = r + 1;
      e.t = CGAL::to_double((Y[r + 1] - p.y()) / (Y[r + 1] - Y[r]));
    } else if (j >= 0) {
      const int c = interval_at(X, p.x());
      e.j0 = e.j1 = j;
      e.i0 = c;
      e.i1 = c + 1;
      e.t = CGAL::to_double((X[c + 1] - p.x()) / (X[c + 1] - X[c]));
    } else {
      throw std::logic_error("crease point " + format_point(approx(p)) + " is not on the grid");
    }
    return e;
  }
};

// Splits a convex polygon by the line through p and q into its left and right parts (points on
// the line go to both).
void split_convex(const Poly& poly, const Point& p, const Point& q, Poly& left, Poly& right) {
  const size_t n = poly.size();
  for (size_t k = 0; k < n; ++k) {
    const Point& u = poly[k];
    const Point& v = poly[(k + 1) % n];
    const auto ou = CGAL::orientation(p, q, u);
    const auto ov = CGAL::orientation(p, q, v);
    if (ou != CGAL::RIGHT_TURN) left.push_back(u);
    if (ou != CGAL::LEFT_TURN) right.push_back(u);
    if ((ou == CGAL::LEFT_TURN && ov == CGAL::RIGHT_TURN) ||
        (ou == CGAL::RIGHT_TURN && ov == CGAL::LEFT_TURN)) {
      const FT dx = q.x() - p.x(), dy = q.y() - p.y();
      const FT t =
          cross(dx, dy, p.x() - u.x(), p.y() - u.y()) / cross(dx, dy, v.x() - u.x(), v.y() - u.y());
      const Point x(u.x() + t * (v.x() - u.x()), u.y() + t * (v.y() - u.y()));
      left.push_back(x);
      right.push_back(x);
    }
  }
}

bool has_area(const Poly& poly) {
  if (poly.size() < 3) return false;
  for (size_t k = 2; k < poly.size(); ++k)
    if (CGAL::orientation(poly[0], poly[1], poly[k]) != CGAL::COLLINEAR) return true;
  return false;
}

Point vertex_average(const Poly& poly) {
  FT x = 0, y = 0;
  for (const auto& p : poly) x += p.x(), y += p.y();
  return Point(x / FT(static_cast<int>(poly.size())), y / FT(static_cast<int>(poly.size())));
}

// Even-odd test of a point that is not on the polygon.
bool inside_loop(const Point& p, const Poly& loop) {
  bool inside = false;
  for (size_t k = 0, n = loop.size(); k < n; ++k) {
    const Point& a = loop[k];
    const Point& b = loop[(k + 1) % n];
    if ((a.y() > p.y()) != (b.y() > p.y())) {
      const auto o = CGAL::orientation(a, b, p);
      if ((b.y() > a.y()) ? o == CGAL::LEFT_TURN : o == CGAL::RIGHT_TURN) inside = !inside;
    }
  }
  return inside;
}

template <class Handle>
const void* key_of(const Handle& h) {
  return static_cast<const void*>(&*h);
}

std::vector<Arrangement::Face_const_handle> locate_faces(const Arrangement& arr,
                                                         const std::vector<Point>& queries) {
  std::vector<std::pair<Point, LocateResult>> results;
  CGAL::locate(arr, queries.begin(), queries.end(), std::back_inserter(results));
  std::map<Point, Arrangement::Face_const_handle> by_point;
  for (const auto& r : results) {
    const auto* f = boost::get<Arrangement::Face_const_handle>(&r.second);
    if (!f) throw std::logic_error("a cell sample point lies on a crease or the boundary");
    by_point.emplace(r.first, *f);
  }
  std::vector<Arrangement::Face_const_handle> out;
  out.reserve(queries.size());
  for (const auto& q : queries) out.push_back(by_point.at(q));
  return out;
}

void insert_polyline(std::vector<Traits::Curve_2>& segs, const Poly& pts, bool closed) {
  const size_t n = pts.size();
  for (size_t k = 0; k + 1 < n + (closed ? 1 : 0); ++k) {
    const Point& a = pts[k];
    const Point& b = pts[(k + 1) % n];
    if (a != b) segs.emplace_back(a, b);
  }
}

// Snaps the sheet's boundary loops (outer first, then the holes) to the grid. Throws UsageError
// when one falls inside a single grid cell.
std::vector<Poly> snap_boundary(const CleanPattern& pattern, const Grid& grid) {
  std::vector<Poly> loops;
  std::vector<Polyline2> rings{pattern.sheet.outer};
  rings.insert(rings.end(), pattern.sheet.holes.begin(), pattern.sheet.holes.end());
  for (size_t l = 0; l < rings.size(); ++l) {
    Poly loop = grid.snap_closed(rings[l], 1);
    if (loop.size() < 3 || !has_area(loop))
      throw UsageError(pattern.source + ": at resolution " + std::to_string(grid.nx()) + "x" +
                       std::to_string(grid.ny()) + " " +
                       (l == 0 ? std::string("the sheet") : "hole " + std::to_string(l)) +
                       " falls inside a single grid cell; use a higher resolution");
    loops.push_back(std::move(loop));
  }
  return loops;
}

// Snaps the creases to the grid (closed ones start on a line of index divisible by `stride`).
// Throws UsageError when one falls inside a single grid cell.
std::vector<Poly> snap_creases(const CleanPattern& pattern, const Grid& grid, int stride) {
  std::vector<Poly> creases;
  for (size_t k = 0; k < pattern.creases.size(); ++k) {
    const Crease& c = pattern.creases[k];
    Poly snapped = c.closed ? grid.snap_closed(c.points, stride) : grid.snap_open(c.points);
    if (snapped.size() < 2 || (c.closed && snapped.size() < 3))
      throw UsageError(c.origin + ": at resolution " + std::to_string(grid.nx()) + "x" +
                       std::to_string(grid.ny()) + " crease " + std::to_string(k) +
                       " falls inside a single grid cell; use a higher resolution");
    creases.push_back(std::move(snapped));
  }
  return creases;
}

// Where the snapped segments lie in the grid: straight chords through cells, and the grid edges
// that segments run along (which block the flood fill of uncut cells).
struct CellCuts {
  std::vector<std::vector<std::pair<Point, Point>>> chords;  ///< per cell j * ncx + i
  std::vector<char> vblocked;  ///< vertical edge on line i, row j: i * ncy + j
  std::vector<char> hblocked;  ///< horizontal edge on line j, column i: j * ncx + i
};

CellCuts cut_cells(const Grid& grid, const std::vector<Traits::Curve_2>& segs) {
  const int nx = grid.nx(), ny = grid.ny();
  const int ncx = nx - 1, ncy = ny - 1;
  CellCuts cuts;
  cuts.chords.resize(static_cast<size_t>(ncx) * ncy);
  cuts.vblocked.assign(static_cast<size_t>(nx) * ncy, 0);
  cuts.hblocked.assign(static_cast<size_t>(ny) * ncx, 0);
  for (const auto& s : segs) {
    const Point a = s.source(), b = s.target();
    if (a.x() == b.x() && line_at(grid.X, a.x()) >= 0) {
      const int i = line_at(grid.X, a.x());
      const FT lo = CGAL::min(a.y(), b.y()), hi = CGAL::max(a.y(), b.y());
      for (int j = interval_at(grid.Y, lo); j < ncy && grid.Y[j] < hi; ++j)
        cuts.vblocked[static_cast<size_t>(i) * ncy + j] = 1;
    } else if (a.y() == b.y() && line_at(grid.Y, a.y()) >= 0) {
      const int j = line_at(grid.Y, a.y());
      const FT lo = CGAL::min(a.x(), b.x()), hi = CGAL::max(a.x(), b.x());
      for (int i = interval_at(grid.X, lo); i < ncx && grid.X[i] < hi; ++i)
        cuts.hblocked[static_cast<size_t>(j) * ncx + i] = 1;
    } else {
      const Point mid((a.x() + b.x()) / 2, (a.y() + b.y()) / 2);
      const int i = interval_at(grid.X, mid.x()), j = interval_at(grid.Y, mid.y());
      cuts.chords[static_cast<size_t>(j) * ncx + i].push_back({a, b});
    }
  }
  return cuts;
}

// The convex pieces into which the chords split cell (i, j), counter-clockwise, sorted by the
// position of their vertex average: by y, then x.
std::vector<Poly> cell_pieces(const Grid& grid, int i, int j,
                              const std::vector<std::pair<Point, Point>>& chords) {
  std::vector<Poly> pieces{{Point(grid.X[i], grid.Y[j]), Point(grid.X[i + 1], grid.Y[j]),
                            Point(grid.X[i + 1], grid.Y[j + 1]), Point(grid.X[i], grid.Y[j + 1])}};
  for (const auto& [p, q] : chords) {
    std::vector<Poly> next;
    for (const auto& piece : pieces) {
      Poly left, right;
      split_convex(piece, p, q, left, right);
      if (has_area(left)) next.push_back(std::move(left));
      if (has_area(right)) next.push_back(std::move(right));
    }
    pieces = std::move(next);
  }
  std::vector<std::pair<Point, Poly>> sorted;
  for (auto& piece : pieces) sorted.emplace_back(vertex_average(piece), std::move(piece));
  std::sort(sorted.begin(), sorted.end(), [](const auto& a, const auto& b) {
    const Point &u = a.first, &v = b.first;
    return u.y() < v.y() || (u.y() == v.y() && u.x() < v.x());
  });
  pieces.clear();
  for (auto& s : sorted) pieces.push_back(std::move(s.second));
  return pieces;
}

// A piece in cell coordinates (PatchLayout::CellPiece).
std::vector<Eigen::Vector2d> cell_coordinates(const Grid& grid, int i, int j, const Poly& piece) {
  std::vector<Eigen::Vector2d> uv;
  const FT w = grid.X[i + 1] - grid.X[i], h = grid.Y[j + 1] - grid.Y[j];
  for (const auto& p : piece)
    uv.emplace_back(CGAL::to_double((p.x() - grid.X[i]) / w),
                    CGAL::to_double((p.y() - grid.Y[j]) / h));
  return uv;
}

// Gives component `id` to the uncut cells reachable from `cell` without crossing a snapped curve.
void flood_fill(int cell, int id, int ncx, int ncy, const CellCuts& cuts,
                std::vector<int>& component) {
  component[cell] = id;
  std::vector<int> stack(1, cell);
  while (!stack.empty()) {
    const int c = stack.back();
    stack.pop_back();
    const int ci = c % ncx, cj = c / ncx;
    auto visit = [&](int ni, int nj, bool blocked) {
      if (ni < 0 || nj < 0 || ni >= ncx || nj >= ncy || blocked) return;
      const int nc = nj * ncx + ni;
      if (component[nc] >= 0 || !cuts.chords[nc].empty()) return;
      component[nc] = id;
      stack.push_back(nc);
    };
    visit(ci - 1, cj, cuts.vblocked[static_cast<size_t>(ci) * ncy + cj]);
    visit(ci + 1, cj, cuts.vblocked[static_cast<size_t>(ci + 1) * ncy + cj]);
    visit(ci, cj - 1, cuts.hblocked[static_cast<size_t>(cj) * ncx + ci]);
    visit(ci, cj + 1, cuts.hblocked[static_cast<size_t>(cj + 1) * ncx + ci]);
  }
}

// The points to locate in the arrangement: one per piece of a cut cell, one per connected region
// (component) of uncut cells.
struct CellQueries {
  std::vector<Point> points;
  std::vector<int> of_component;            ///< query of each component
  std::vector<int> component;               ///< component of each uncut cell, else -1
  std::vector<std::vector<int>> of_pieces;  ///< queries of the pieces of each cut cell
  std::vector<std::vector<Poly>> pieces;    ///< the pieces of each cut cell
};

CellQueries cell_queries(const Grid& grid, const CellCuts& cuts) {
  const int ncx = grid.nx() - 1, ncy = grid.ny() - 1;
  CellQueries q;
  q.component.assign(static_cast<size_t>(ncx) * ncy, -1);
  q.of_pieces.resize(static_cast<size_t>(ncx) * ncy);
  q.pieces.resize(static_cast<size_t>(ncx) * ncy);
  for (int j = 0; j < ncy; ++j) {
    for (int i = 0; i < ncx; ++i) {
      const int cell = j * ncx + i;
      if (!cuts.chords[cell].empty()) {
        q.pieces[cell] = cell_pieces(grid, i, j, cuts.chords[cell]);
        for (const auto& piece : q.pieces[cell]) {
          q.of_pieces[cell].push_back(static_cast<int>(q.points.size()));
          q.points.push_back(vertex_average(piece));
        }
        continue;
      }
      if (q.component[cell] >= 0) continue;
      const int id = static_cast<int>(q.of_component.size());
      q.of_component.push_back(static_cast<int>(q.points.size()));
      q.points.push_back(grid.cell_centre(i, j));
      flood_fill(cell, id, ncx, ncy, cuts, q.component);
    }
  }
  return q;
}

// Patch id of each arrangement face met so far (by face address); -1 for faces in holes.
using FacePatches = std::unordered_map<const void*, int>;

// Locates the queries and fills the owners of every cell; faces inside the sheet become patches
// in the order in which the cells meet them. Returns the patch of each face met.
FacePatches assign_cells(const Arrangement& arr, const Grid& grid, const CellCuts& cuts,
                         const CellQueries& q, const std::vector<Poly>& loops,
                         PatchLayout& layout) {
  const auto faces = locate_faces(arr, q.points);
  FacePatches patch_of_face;
  auto patch_of_query = [&](int query) {
    const auto& f = faces[query];
    if (f->is_unbounded()) return -1;
    auto it = patch_of_face.find(key_of(f));
    if (it != patch_of_face.end()) return it->second;
    bool hole = false;
    for (size_t l = 1; l < loops.size() && !hole; ++l)
      hole = inside_loop(q.points[query], loops[l]);
    const int id = hole ? -1 : layout.patch_count++;
    patch_of_face.emplace(key_of(f), id);
    return id;
  };
  layout.cell_offsets.assign(1, 0);
  std::vector<int> component_patch(q.of_component.size(), -2);
  for (int cell = 0; cell < layout.cell_count(); ++cell) {
    std::vector<int> owners;
    if (!cuts.chords[cell].empty()) {
      const int ncx = layout.nx() - 1;
      for (size_t k = 0; k < q.of_pieces[cell].size(); ++k) {
        const int p = patch_of_query(q.of_pieces[cell][k]);
        if (p < 0) continue;
        owners.push_back(p);
        layout.pieces.push_back(
            {cell, p, cell_coordinates(grid, cell % ncx, cell / ncx, q.pieces[cell][k])});
      }
    } else {
      int& p = component_patch[q.component[cell]];
      if (p == -2) p = patch_of_query(q.of_component[q.component[cell]]);
      if (p >= 0) owners.push_back(p);
    }
    std::sort(owners.begin(), owners.end());
    owners.erase(std::unique(owners.begin(), owners.end()), owners.end());
    layout.cell_patches.insert(layout.cell_patches.end(), owners.begin(), owners.end());
    layout.cell_offsets.push_back(static_cast<int>(layout.cell_patches.size()));
  }
  return patch_of_face;
}

// Final patch order: by owned cells, lexicographically (see the header).
void sort_patches(PatchLayout& layout, FacePatches& patch_of_face) {
  std::vector<std::vector<int>> cells_of(layout.patch_count);
  for (int cell = 0; cell < layout.cell_count(); ++cell)
    for (int k = 0; k < layout.owner_count(cell); ++k)
      cells_of[layout.owners(cell)[k]].push_back(cell);
  std::vector<int> order(layout.patch_count);
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](int a, int b) { return cells_of[a] < cells_of[b]; });
  std::vector<int> new_id(layout.patch_count);
  for (int k = 0; k < layout.patch_count; ++k) new_id[order[k]] = k;
  for (auto& [face, id] : patch_of_face)
    if (id >= 0) id = new_id[id];
  renumber_patches(layout, new_id);
}

// Patches of the faces around an arrangement vertex, ascending.
std::vector<int> patches_around(const Arrangement::Vertex_const_handle& v,
                                const FacePatches& patch_of_face) {
  std::vector<int> patches;
  auto circ = v->incident_halfedges();
  const auto first = circ;
  do {
    auto it = patch_of_face.find(key_of(circ->face()));
    if (it != patch_of_face.end() && it->second >= 0) patches.push_back(it->second);
  } while (++circ != first);
  std::sort(patches.begin(), patches.end());
  patches.erase(std::unique(patches.begin(), patches.end()), patches.end());
  return patches;
}

// Crease points: the unique snapped points (numbered in curve order) with their grid edges and
// the patches around them, and the curves as lists of those points.
void add_crease_points(PatchLayout& layout, const Arrangement& arr, const Grid& grid,
                       const CleanPattern& pattern, const std::vector<Poly>& creases,
                       const FacePatches& patch_of_face) {
  std::map<Point, int> point_index;
  std::vector<Point> unique_points;
  for (size_t k = 0; k < creases.size(); ++k) {
    PatchLayout::Curve curve;
    curve.closed = pattern.creases[k].closed;
    curve.slit = pattern.creases[k].kind == CurveKind::kSlit;
    for (const auto& p : creases[k]) {
      auto [it, added] = point_index.emplace(p, static_cast<int>(unique_points.size()));
      if (added) unique_points.push_back(p);
      curve.points.push_back(it->second);
    }
    layout.curves.push_back(std::move(curve));
  }
  std::vector<std::pair<Point, LocateResult>> located;
  CGAL::locate(arr, unique_points.begin(), unique_points.end(), std::back_inserter(located));
  layout.points.resize(unique_points.size());
  for (const auto& [p, result] : located) {
    const auto* v = boost::get<Arrangement::Vertex_const_handle>(&result);
    if (!v) throw std::logic_error("a snapped crease point is not an arrangement vertex");
    PatchLayout::CreasePoint& cp = layout.points[point_index.at(p)];
    cp.position = approx(p);
    cp.edge = grid.edge_point(p);
    cp.patches = patches_around(*v, patch_of_face);
  }
}

}  // namespace

PatchLayout build_patch_layout(const CleanPattern& pattern, const AxisLayout& xl,
                               const AxisLayout& yl, int closed_start_stride) {
  const Grid grid(xl, yl);
  PatchLayout layout;
  for (const auto& v : grid.X) layout.xs.push_back(CGAL::to_double(v));
  for (const auto& v : grid.Y) layout.ys.push_back(CGAL::to_double(v));
  const std::vector<Poly> loops = snap_boundary(pattern, grid);
  const std::vector<Poly> creases = snap_creases(pattern, grid, closed_start_stride);

  // The arrangement of the snapped curves; its bounded faces inside the sheet are the patches.
  std::vector<Traits::Curve_2> segs;
  for (const auto& l : loops) insert_polyline(segs, l, true);
  for (size_t k = 0; k < creases.size(); ++k)
    insert_polyline(segs, creases[k], pattern.creases[k].closed);
  Arrangement arr;
  CGAL::insert(arr, segs.begin(), segs.end());

  const CellCuts cuts = cut_cells(grid, segs);
  const CellQueries queries = cell_queries(grid, cuts);
  FacePatches patch_of_face = assign_cells(arr, grid, cuts, queries, loops, layout);
  sort_patches(layout, patch_of_face);
  add_crease_points(layout, arr, grid, pattern, creases, patch_of_face);
  for (const auto& l : loops) {
    Polyline2 ring;
    for (const auto& p : l) ring.push_back(approx(p));
    layout.boundary.push_back(std::move(ring));
  }
  return layout;
}

void renumber_patches(PatchLayout& layout, const std::vector<int>& new_id) {
  for (int c = 0; c < layout.cell_count(); ++c) {
    auto begin = layout.cell_patches.begin() + layout.cell_offsets[c];
    auto end = layout.cell_patches.begin() + layout.cell_offsets[c + 1];
    for (auto it = begin; it != end; ++it) *it = new_id[*it];
    std::sort(begin, end);
  }
  for (auto& p : layout.points) {
    for (auto& id : p.patches) id = new_id[id];
    std::sort(p.patches.begin(), p.patches.end());
  }
  for (auto& piece : layout.pieces) piece.patch = new_id[piece.patch];
}

}  // namespace sdog
