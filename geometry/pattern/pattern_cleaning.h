#pragma once
// Pattern cleaning: makes a drawn crease pattern exact enough to mesh. Tolerances are fractions of
// L = max(sheet width, height); the defaults are those of the reference implementation.
//
//  0. Crease segments drawn along the sheet boundary, along an earlier crease or along the
//     crease's own earlier segments (within 1e-6 L) are removed, with a warning; the crease is
//     split where they were.
//  1. Crease ends that touch (within 1e-6 L) alone in the sheet's interior are joined into one
//     crease first (a curve drawn as many short pieces); a crease end within L/1000 of a boundary
//     vertex moves onto it. Then crease ends closer than L/1000, and then than merge_tol = L/100,
//     are merged (to the cluster mean; a cluster some of whose ends lie farther than the tolerance
//     from its mean is a dense drawing and stays), step 0 runs again (a crease drawn twice with
//     small offsets now coincides with itself), and two crease ends that meet alone in the
//     interior are joined into one crease.
//  2. Creases are clipped to the sheet: parts outside (or in holes) are dropped, and the points
//     where a crease leaves the sheet become crease ends, inserted into the boundary as vertices.
//  3. Crossings and contacts between creases become junctions: crossings closer than merge_tol
//     (and crease ends that close) merge into one junction at their mean, and every crease through
//     it is rerouted through that exact point.
//  4. A crease end that is still free snaps, within snap_tol = L/50, to the nearest crease vertex
//     (junction or boundary end of another crease), else onto the boundary, else onto another
//     crease (a T junction). An end farther than that from everything is an error, unless every
//     cleaning without seams failed: then it ends inside the sheet, and a seam (crease_pattern.h)
//     continues it straight to the first crease or boundary it meets (onto a vertex there within
//     merge_tol), with a warning.
//  5. Crease ends on slanted boundary edges whose x (or y) coordinates all lie within L/1000 move,
//     with their boundary vertices, to their mean. Junction x and y coordinates closer than
//     snap_tol are aligned (to the boundary end's value when one is in the group, else to the
//     mean), so the grid does not get needlessly thin rows. A group is left as it is when it holds
//     two boundary ends, and a junction stays where its move would make its creases cross
//     another; junction coordinates within L/1000 of each other are then aligned among
//     themselves, so that no grid row or column is a hair wide.
// After cleaning, creases meet each other and the boundary only at shared polyline vertices.
#include <string>
#include <vector>

#include "geometry/pattern/crease_pattern.h"

namespace sdog {

struct CleaningOptions {
  double merge_fraction = 0.01;  ///< L/100: merging crease ends and nearby crossings
  double snap_fraction = 0.02;   ///< L/50: snapping free ends, aligning junction coordinates
  /// When cleaning with these tolerances fails, retry with both divided by kFinerFactor, up to
  /// kFinerAttempts times (dense drawings: tessellations, many flaps); the first that cleans is
  /// used, with a warning naming both tolerances and the first failure, else the first failure is
  /// reported. Off when the user chose the tolerances.
  bool adapt = true;
  /// A free end farther than snap_tol from everything ends inside the sheet and gets a seam, when
  /// cleaning without seams fails (with the tolerances above, and finer ones when adapting): a
  /// drawing that cleans as drawn is not given seams.
  bool seams = true;
  static constexpr double kFinerFactor = 10;
  static constexpr int kFinerAttempts = 2;
  /// Empty when valid, else a message naming the bad field.
  std::string validate() const;
};

struct CleanPattern {
  std::string source;
  Sheet sheet;                  ///< crease ends on the boundary are boundary vertices
  std::vector<Crease> creases;  ///< cleaned creases (a crease cut by a hole becomes several)
  std::vector<Eigen::Vector2d> junctions;  ///< interior points where creases meet or cross
  /// Points that must be grid vertices: junctions, and crease ends on parts of the boundary that
  /// are not on the sheet's bounding box (those lie on a grid line already).
  std::vector<Eigen::Vector2d> pins;
  std::vector<std::string> changes;  ///< what cleaning changed, one line each
  /// What reading and cleaning dropped or merged from the drawing, one line each: facet lines,
  /// creases drawn along the boundary or twice.
  std::vector<std::string> warnings;
  double size() const { return std::max(sheet.bbox.width(), sheet.bbox.height()); }
};

/// Cleans the pattern (see above): without seams, with the options' tolerances and then finer ones
/// (CleaningOptions::adapt), then with seams in the same order; the first that succeeds is
/// returned. Throws InputError for creases that overlap along a stretch, for crossings it cannot
/// resolve, and (without seams) for a crease that ends inside the sheet ("crease 3 (FILE:12:
/// <path>) ends at (12.5, 40.1), 9.8 units from the sheet boundary and 20 from the nearest
/// crease; creases must end on the boundary or on another crease"); with seams allowed, the
/// error of the first attempt with seams.
CleanPattern clean_pattern(const CreasePattern& pattern, const CleaningOptions& options = {});

}  // namespace sdog
