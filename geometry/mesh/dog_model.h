#pragma once
// From a crease pattern and a resolution to the fine DOG, its coarse twin and the map between
// them: the whole geometry pipeline in one call.
#include <optional>

#include "base/enum_names.h"

#include "geometry/mesh/dog_mesh.h"
#include "geometry/mesh/fine_coarse_map.h"
#include "geometry/mesh/grid.h"
#include "geometry/mesh/quad_topology.h"
#include "geometry/pattern/crease_pattern.h"
#include "geometry/pattern/pattern_cleaning.h"

namespace sdog {

/// How the coarse DOG is made: meshed from the crease pattern on the coarse grid (standard), or
/// the fine DOG without every second grid row and column (alt, alt_coarse.h).
enum class CoarseKind { kStandard, kAlt };
template <>
struct EnumNames<CoarseKind> {
  static constexpr const char* noun = "coarse DOG";
  static constexpr EnumName<CoarseKind> rows[] = {
      {CoarseKind::kStandard, "standard"},
      {CoarseKind::kAlt, "alt"},
  };
};

struct MeshOptions {
  CleaningOptions cleaning;
  bool build_coarse = true;  ///< also build the coarse DOG and the map (needs odd resolutions)
  CoarseKind coarse = CoarseKind::kStandard;
};

struct DogModel {
  CreasePattern pattern;  ///< as drawn
  CleanPattern clean;     ///< after cleaning
  int expected_patches = 0;
  Resolution fine_res;
  DogMesh fine;
  QuadTopology fine_topology;
  std::vector<Polyline2> fine_boundary;  ///< snapped sheet boundary, mesh units
  bool has_coarse = false;
  CoarseKind coarse_kind = CoarseKind::kStandard;
  Resolution coarse_res;
  DogMesh coarse;
  QuadTopology coarse_topology;
  int coarse_cover_cells = 0;  ///< coarse cells added so that coarse patches cover fine ones
  FineCoarseMap map;
};

/// Cleans the pattern, lays out the grid (nested for odd resolutions), builds the meshes, their
/// topology, the stitching and the map. Crease points that lie on slits only are not stitched
/// (the slit's two sides are free). Throws UsageError for resolutions that cannot work
/// (range, parity, too low for the pattern) and InputError for patterns that cannot be meshed.
DogModel build_dog_model(const CreasePattern& pattern, const Resolution& res,
                         const MeshOptions& options = {});

/// What a user of the model should know: the warnings of reading and cleaning the pattern, then
/// the grid's (cell_shape_warning) and the creases that cross no grid edge (no fold site), one
/// line each.
std::vector<std::string> model_warnings(const DogModel& model);

/// The lowest resolution above `from` at which the pattern meshes, found by trying: each side
/// grows by kResolutionStep per attempt (odd when a coarse mesh is built), up to kResolutionReach
/// times `from` (and kMaxResolution), and the first step that meshes is narrowed down by halving
/// towards the step before; unset when none of them meshes.
constexpr double kResolutionStep = 1.25;
constexpr double kResolutionReach = 4;
std::optional<Resolution> lowest_meshing_resolution(const CreasePattern& pattern,
                                                    const Resolution& from,
                                                    const MeshOptions& options = {});

}  // namespace sdog
