#pragma once
// Internal to pattern cleaning (pattern_cleaning.cpp and cleaning_*.cpp): the Cleaner that runs
// the steps of pattern_cleaning.h on one pattern, and the polyline helpers its steps share. Each
// step lives in the file named after it: cleaning_clipping.cpp (step 2), cleaning_junctions.cpp
// (steps 3 and 5), cleaning_snapping.cpp and cleaning_seams.cpp (step 4), cleaning_overlaps.cpp
// (step 0);
// pattern_cleaning.cpp has the pipeline, step 1 and the final check.
#include <cmath>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "geometry/pattern/pattern_cleaning.h"

namespace sdog::cleaning {

using Vec2 = Eigen::Vector2d;

/// Points this close (fraction of L) are drawn at the same place: the ends of pieces of one crease
/// drawn end to end, a segment drawn along another.
constexpr double kTouchFraction = 1e-6;
/// A crease end this close (fraction of L) to a boundary vertex is meant to end on it.
constexpr double kCornerFraction = 1e-3;
/// Junction coordinates this close (fraction of L) align even where their group within snap_tol
/// does not, as do crease ends on the boundary: each would pin its own grid line, and the column
/// between two such lines is about a tenth of a cell wide at 81x81 (grid columns much narrower than
/// their neighbours make the solver stretch them, then fail).
constexpr double kHairFraction = 2.5e-3;

/// A point to insert into a polyline: `param` along segment `seg`.
struct Insertion {
  int seg;
  double param;
  Vec2 point;
};

/// Inserts points into polyline segments (point `param` along segment `seg`), skipping points
/// equal to a neighbouring vertex.
Polyline2 with_insertions(const Polyline2& pts, bool closed, std::vector<Insertion> ins);

/// Parameter in [0, 1] of the projection of p onto segment [a, b] (0 for a zero-length segment).
double param_on(const Vec2& p, const Vec2& a, const Vec2& b);

/// Single-linkage clusters of points closer than tol (bucket hashing, union-find), sorted.
std::vector<std::vector<int>> cluster_points(const std::vector<Vec2>& pts, double tol);

/// Mean of the distinct points (a point listed twice counts once).
Vec2 mean_of_distinct(const std::vector<Vec2>& pts);

/// The contact point of two intersecting segments [a0,a1] and [b0,b1] (not collinear).
Vec2 contact_point(const Vec2& a0, const Vec2& a1, const Vec2& b0, const Vec2& b1);

/// Do the segments [a0,a1] and [b0,b1] overlap along a stretch (not just at a shared end)?
bool collinear_overlap(const Vec2& a0, const Vec2& a1, const Vec2& b0, const Vec2& b1);

/// A crossing of two creases (one event per crease) or a free end of a crease, for step 3.
struct CreaseEvent {
  Vec2 point;
  int crease;
  double g;  ///< global parameter: segment index + parameter on the segment
  bool is_end;
};

/// One pass of a crease through a junction: its part between the global parameters gmin and
/// gmax is replaced by the junction point.
struct JunctionPass {
  double gmin, gmax;
  Vec2 junction;
};

/// One coordinate in junction alignment: of junction `junction` (>= 0) or of the fixed boundary
/// end -1 - `junction` (< 0).
struct AxisValue {
  double value;
  int junction;
};

/// The nearest point found for a free crease end on a polyline (a boundary loop or a crease).
struct SnapCandidate {
  double distance = INFINITY;
  int polyline = -1, seg = -1;
  double param = 0;  ///< parameter of `point` along segment `seg`
  Vec2 point;
};

/// How often each point occurs as a crease vertex, by (x, y).
using VertexCounts = std::map<std::pair<double, double>, int>;

class Cleaner {
 public:
  Cleaner(const CreasePattern& pattern, const CleaningOptions& options);
  CleanPattern run();

 private:
  // Shared helpers (pattern_cleaning.cpp).
  int sheet_side(const Vec2& p) const;  // +1 inside, 0 on the boundary, -1 outside or in a hole
  std::string name(int k) const;
  static Vec2& end_point(Crease& c, int end) {
    return end == 0 ? c.points.front() : c.points.back();
  }
  void log(const std::string& s) { changes_.push_back(s); }
  /// A change the user should hear about (a part of the drawing dropped or merged).
  void warn(const std::string& s) { warnings_.push_back(s); }
  VertexCounts vertex_counts() const;
  void replace_vertex(const Vec2& from, const Vec2& to);

  // Step 1 (pattern_cleaning.cpp).
  // Step 0 (cleaning_overlaps.cpp).
  void drop_overlapping_segments(double fraction);
  void merge_crease_ends(double tol);
  void move_ends_onto_boundary_corners();
  std::set<std::pair<double, double>> touching_pieces() const;
  void join_continuing_creases(const std::optional<std::set<std::pair<double, double>>>& only);
  bool on_other_crease(const Vec2& p, int a, int b) const;

  // Step 2 (cleaning_clipping.cpp).
  void clip_to_sheet();
  std::vector<std::vector<Insertion>> cut_at_boundary();
  void clip_crease(int k, const std::vector<Insertion>& events, std::vector<Crease>& kept);
  void keep_inside_pieces(int k, const Polyline2& pts,
                          const std::set<std::pair<double, double>>& cuts,
                          std::vector<Crease>& kept);

  // Step 3 (cleaning_junctions.cpp).
  void make_junctions();
  std::vector<CreaseEvent> crossing_events() const;
  void add_free_end_events(std::vector<CreaseEvent>& events) const;
  void merge_into_junction(const std::vector<int>& cluster, const std::vector<CreaseEvent>& events,
                           const std::vector<std::vector<double>>& arc,
                           std::vector<std::vector<JunctionPass>>& passes);
  void reroute_through_junctions(int k, std::vector<JunctionPass> passes);
  void merge_shared_segments();
  void drop_degenerate_creases();

  // Step 4 (cleaning_snapping.cpp).
  void snap_free_ends();
  void snap_end(int k, int e, const VertexCounts& counts);
  bool snap_to_crease_vertex(int k, int e, const Vec2& p, const VertexCounts& counts);
  SnapCandidate nearest_boundary_point(const Vec2& p) const;
  SnapCandidate nearest_crease_point(int k, int e, const Vec2& p) const;
  bool trim_near_end(int e, Vec2& a, Vec2& b, double& along) const;
  bool is_boundary_end(const Vec2& q, int except) const;
  // cleaning_seams.cpp (step 4, ends inside the sheet)
  void add_seam(int k, int e);
  SnapCandidate first_hit(const Vec2& p, const Vec2& direction, int k) const;

  // Step 5 (cleaning_junctions.cpp).
  void align_junctions();
  void align_boundary_ends(int axis);
  void move_boundary_end(const Vec2& end, int axis, double target);
  std::vector<Vec2> collect_junctions();
  void align_axis(int axis, std::vector<Vec2>& fixed, double tol);
  void align_group(const std::vector<AxisValue>& group, int axis, std::vector<Vec2>& fixed);
  bool can_align_junction(int j, int axis, double target) const;
  bool align_junction(int j, int axis, double target);
  bool move_keeps_creases_apart(const Vec2& from, const Vec2& to) const;

  // Step 6 (pattern_cleaning.cpp).
  void verify() const;

  std::string source_;
  Sheet sheet_;
  std::vector<Crease> creases_;
  std::vector<Polyline2> loops_;  ///< outer boundary, then the holes
  double size_ = 0;               ///< L
  double merge_tol_ = 0, snap_tol_ = 0;
  double snap_fraction_ = 0;  ///< snap_tol_ / L, for messages
  bool seams_ = false;        ///< free ends farther than snap_tol from everything get a seam
  std::vector<Vec2> junctions_, pins_;
  std::vector<std::string> changes_, warnings_;
};

}  // namespace sdog::cleaning
