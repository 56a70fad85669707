#pragma once
// What the fuzz targets do with a crease pattern once their reader has made it: cleaning, the patch
// count and a small mesh. Clear errors (InputError, UsageError) are expected; anything else is a
// bug: a crash, a sanitizer report, or another exception (which escapes and aborts the run).
#include "base/errors.h"
#include "geometry/mesh/dog_model.h"
#include "geometry/mesh/patch_layout.h"
#include "geometry/pattern/crease_pattern.h"
#include "geometry/pattern/pattern_faces.h"

namespace sdog::fuzz {

/// Runs read() (text -> CreasePattern) and the stages after it; returns 0 for libFuzzer.
template <class Read>
int exercise_pattern(Read read) {
  try {
    const CreasePattern pattern = read();
    const CleanPattern clean = clean_pattern(pattern);
    count_pattern_patches(clean);
    // Meshing at a small resolution exercises grid snapping and the exact patch layout, then the
    // alternative coarse DOG and its map.
    if (pattern.creases.size() <= 8) {
      build_dog_model(pattern, {9, 9});
      MeshOptions alt;
      alt.coarse = CoarseKind::kAlt;
      build_dog_model(pattern, {9, 9}, alt);
    }
  } catch (const InputError&) {
  } catch (const UsageError&) {
  }
  return 0;
}

}  // namespace sdog::fuzz
