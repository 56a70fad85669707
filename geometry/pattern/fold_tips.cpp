#include "geometry/pattern/fold_tips.h"

#include <algorithm>
#include <cmath>

namespace sdog {
namespace {

// Where crease c touches the point q: 0 not at all, 1 one of its ends, 2 passes through (an inner
// vertex, or any vertex of a closed crease). `away` gets the unit direction from q along the
// crease.
int touch(const Crease& c, const Eigen::Vector2d& q, Eigen::Vector2d& away) {
  const auto& pts = c.points;
  const int n = static_cast<int>(pts.size());
  for (int i = 0; i < n; ++i) {
    if (pts[i] != q) continue;
    if (c.closed || (i > 0 && i < n - 1)) return 2;
    if (n < 2) return 0;
    const Eigen::Vector2d d = pts[i == 0 ? 1 : n - 2] - q;
    if (d.norm() == 0) return 0;
    away = d.normalized();
    return 1;
  }
  return 0;
}

}  // namespace

std::vector<FoldTip> fold_tips(const CleanPattern& pattern) {
  std::vector<FoldTip> tips;
  for (const Eigen::Vector2d& q : pattern.junctions) {
    std::vector<int> ends;
    std::vector<Eigen::Vector2d> dirs;
    bool passes = false;
    for (size_t k = 0; k < pattern.creases.size() && !passes; ++k) {
      Eigen::Vector2d away;
      const int t = touch(pattern.creases[k], q, away);
      passes = t == 2;
      if (t == 1) {
        ends.push_back(static_cast<int>(k));
        dirs.push_back(away);
      }
    }
    if (passes || ends.size() != 2) continue;
    if (pattern.creases[ends[0]].fold == Fold::kFlat &&
        pattern.creases[ends[1]].fold == Fold::kFlat)
      continue;
    const double angle = std::acos(std::clamp(dirs[0].dot(dirs[1]), -1.0, 1.0)) * 180 / M_PI;
    const bool seam_end = (pattern.creases[ends[0]].kind == CurveKind::kSeam) !=
                          (pattern.creases[ends[1]].kind == CurveKind::kSeam);
    if (angle >= 180 - kStraightCreaseDegrees && !seam_end) continue;
    tips.push_back({q, {ends[0], ends[1]}, angle});
  }
  return tips;
}

}  // namespace sdog
