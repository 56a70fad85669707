#include "geometry/input/fold_writer.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <map>
#include <nlohmann/json.hpp>
#include <utility>
#include <vector>

namespace sdog {
namespace {

// FOLD's letter of a curve: a slit's is C (cut), a seam's J (join: the faces on its two sides are
// one), a crease's the initial of its assignment's name (M, V, F, U).
std::string letter(const Crease& c) {
  if (c.kind == CurveKind::kSlit) return "C";
  if (c.kind == CurveKind::kSeam) return "J";
  return std::string(1, static_cast<char>(std::toupper(enum_name(c.fold)[0])));
}

// The FOLD arrays under construction: vertices numbered in order of first use.
class FoldArrays {
 public:
  int vertex(const Eigen::Vector2d& p) {
    const auto [it, added] = index_.emplace(std::make_pair(p.x(), p.y()), coords_.size());
    if (added) coords_.push_back({p.x(), p.y() == 0 ? 0.0 : -p.y()});
    return static_cast<int>(it->second);
  }

  void edge(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const std::string& assignment,
            nlohmann::json angle) {
    edges_.push_back({vertex(a), vertex(b)});
    assignments_.push_back(assignment);
    angles_.push_back(std::move(angle));
  }

  void polyline(const Polyline2& points, bool closed, const std::string& assignment,
                const nlohmann::json& angle) {
    const size_t n = points.size();
    for (size_t i = 0; i + 1 < n + (closed ? 1 : 0); ++i)
      edge(points[i], points[(i + 1) % n], assignment, angle);
  }

  nlohmann::ordered_json frame(const std::string& source) const {
    nlohmann::ordered_json j;
    j["file_spec"] = 1.2;
    j["file_creator"] = "Scalable DOGs";
    j["file_title"] = source;
    j["file_classes"] = {"singleModel"};
    j["frame_title"] = "crease pattern as read";
    j["frame_classes"] = {"creasePattern"};
    const auto has = [&](const char* a) {
      return std::find(assignments_.begin(), assignments_.end(), a) != assignments_.end();
    };
    j["frame_attributes"] = {"2D", has("C") ? "cuts" : "noCuts", has("J") ? "joins" : "noJoins"};
    j["vertices_coords"] = coords_;
    j["edges_vertices"] = edges_;
    j["edges_assignment"] = assignments_;
    j["edges_foldAngle"] = angles_;
    return j;
  }

 private:
  std::map<std::pair<double, double>, size_t> index_;
  std::vector<std::array<double, 2>> coords_;
  std::vector<std::array<int, 2>> edges_;
  std::vector<std::string> assignments_;
  std::vector<nlohmann::json> angles_;
};

}  // namespace

std::string fold_text(const CleanPattern& pattern) {
  FoldArrays fold;
  fold.polyline(pattern.sheet.outer, true, "B", nullptr);
  for (const auto& hole : pattern.sheet.holes) fold.polyline(hole, true, "B", nullptr);
  for (const auto& c : pattern.creases) {
    nlohmann::json angle = nullptr;
    if (c.fold == Fold::kFlat && c.kind != CurveKind::kSlit) angle = 0.0;
    if (c.angle && (c.fold == Fold::kMountain || c.fold == Fold::kValley))
      angle = fold_sign(c.fold) * *c.angle;
    fold.polyline(c.points, c.closed, letter(c), angle);
  }
  // One line per key, and per element of the arrays of arrays (vertices, edges).
  const nlohmann::ordered_json frame = fold.frame(pattern.source);
  std::string text = "{";
  for (auto it = frame.begin(); it != frame.end(); ++it) {
    text += std::string(it == frame.begin() ? "" : ",") + "\n  " + nlohmann::json(it.key()).dump() +
            ": ";
    const bool rows = it->is_array() && !it->empty() && it->front().is_array();
    if (!rows) {
      text += it->dump();
      continue;
    }
    text += "[";
    for (size_t i = 0; i < it->size(); ++i)
      text += std::string(i == 0 ? "" : ",") + "\n    " + (*it)[i].dump();
    text += "\n  ]";
  }
  return text + "\n}\n";
}

}  // namespace sdog
