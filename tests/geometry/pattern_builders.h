#pragma once
// Crease patterns built in code for tests (no SVG involved).
#include "geometry/pattern/crease_pattern.h"

namespace sdog::test {

inline CreasePattern rectangle_pattern(double w, double h, std::vector<Polyline2> creases = {},
                                       std::vector<bool> closed = {}) {
  CreasePattern p;
  p.source = "test";
  p.sheet.outer = {{0, 0}, {w, 0}, {w, h}, {0, h}};
  p.sheet.bbox = {0, 0, w, h};
  p.sheet.from_viewbox = true;
  for (size_t k = 0; k < creases.size(); ++k) {
    Crease c;
    c.points = creases[k];
    c.closed = k < closed.size() && closed[k];
    c.origin = "test crease " + std::to_string(k);
    p.creases.push_back(c);
  }
  return p;
}

}  // namespace sdog::test
