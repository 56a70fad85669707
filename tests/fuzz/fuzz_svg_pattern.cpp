// libFuzzer target: SVG text -> reader -> crease pattern -> cleaning -> patch count, plus a small
// mesh (pattern_fuzzing.h).
#include <cstddef>
#include <cstdint>
#include <string>

#include "geometry/input/svg_pattern.h"
#include "geometry/pattern/crease_pattern.h"
#include "tests/fuzz/pattern_fuzzing.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  return sdog::fuzz::exercise_pattern(
      [&] { return sdog::crease_pattern_from_svg(sdog::parse_svg(text, "fuzz.svg")); });
}
