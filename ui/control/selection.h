#pragma once
// What is picked in the studio: vertices (a click, the rubber band) or creases (a click on a
// crease with the crease-curves overlay on), and what a click at a screen position picks.
#include <Eigen/Core>
#include <string>
#include <vector>

#include "geometry/mesh/dog_mesh.h"

namespace sdog::control {

/// What a click picked, and the status line that says so.
struct ClickPick {
  int crease = -1;  ///< the crease picked (then crease_point is where), else -1
  int crease_point = -1;
  int vertex = -1;  ///< the vertex picked when no crease was, else -1
  std::string message;
};

/// A click at display position (x, y): the crease through the nearest crease point within 8
/// pixels when `crease_points` (the display coordinates of the fine mesh's crease points, in
/// order) is not empty; otherwise, or when there is none, the nearest vertex of `vertices` (display
/// coordinates of the fine vertices) within 12 pixels.
ClickPick pick_at(const DogMesh& fine, const Eigen::MatrixX3d& crease_points,
                  const Eigen::MatrixX3d& vertices, double x, double y);

class Selection {
 public:
  /// The selection becomes `vertices` (with `add`: they are added, each once); the creases are
  /// dropped unless `add`.
  void select_vertices(const std::vector<int>& vertices, bool add = false);
  /// The crease selection becomes those of `creases` below `crease_count` (with `add`: they are
  /// added, each once); the vertices are dropped unless `add`.
  void select_creases(const std::vector<int>& creases, int crease_count, bool add = false);
  /// What a click picked becomes the selection.
  void apply(const ClickPick& pick, int crease_count);
  /// Nothing selected (a new model).
  void clear();

  const std::vector<int>& vertices() const { return vertices_; }
  const std::vector<int>& creases() const { return creases_; }
  /// The one selected vertex, -1 when none or several are.
  int vertex() const { return vertices_.size() == 1 ? vertices_.front() : -1; }
  /// The crease point of the last crease picked by a click (-1: none).
  int picked_crease_point() const { return picked_crease_point_; }

 private:
  std::vector<int> vertices_, creases_;
  int picked_crease_point_ = -1;
};

}  // namespace sdog::control
