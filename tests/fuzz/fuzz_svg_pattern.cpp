// libFuzzer target: SVG text -> reader -> crease pattern -> cleaning -> patch count, plus a small
// mesh. Clear errors (InputError, UsageError) are expected; anything else is a bug: a crash, a
// sanitizer report, or another exception (which escapes and aborts the run).
#include <cstddef>
#include <cstdint>
#include <string>

#include "geometry/dog_model.h"
#include "base/errors.h"
#include "geometry/patch_layout.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const sdog::CreasePattern pattern =
        sdog::crease_pattern_from_svg(sdog::parse_svg(text, "fuzz.svg"));
    const sdog::CleanPattern clean = sdog::clean_pattern(pattern);
    sdog::count_pattern_patches(clean);
    // Meshing at a small resolution exercises grid snapping and the exact patch layout.
    if (pattern.creases.size() <= 8) sdog::build_dog_model(pattern, {9, 9});
  } catch (const sdog::InputError&) {
  } catch (const sdog::UsageError&) {
  }
  return 0;
}
