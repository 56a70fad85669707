#pragma once
// Per-vertex quad topology of a DOG mesh: neighbours along quad edges in cyclic order and the
// vertex classes that decide the DOG constraints.
//   star: 4 quads around the vertex (interior): 3 angle constraints
//   bnd3: 3 neighbours (straight boundary): 1 constraint
//   bnd2: 2 neighbours (convex corner): none
//   bnd4: 4 neighbours but fewer than 4 quads (reflex staircase corner): none
#include <array>
#include <string>
#include <vector>

#include "base/enum_names.h"
#include "geometry/mesh/dog_mesh.h"

namespace sdog {

enum class VertexClass : int { kStar = 0, kBnd3 = 1, kBnd2 = 2, kBnd4 = 3 };
template <>
struct EnumNames<VertexClass> {
  static constexpr const char* noun = "vertex class";
  static constexpr EnumName<VertexClass> rows[] = {
      {VertexClass::kStar, "star"},
      {VertexClass::kBnd3, "bnd3"},
      {VertexClass::kBnd2, "bnd2"},
      {VertexClass::kBnd4, "bnd4"},
  };
};

/// Neighbour slots, in cyclic (counter-clockwise) order, so that 0/2 and 1/3 are opposite.
enum Direction : int { kXForward = 0, kYForward = 1, kXBackward = 2, kYBackward = 3 };

struct QuadTopology {
  std::vector<std::array<int, 4>> neighbors;  ///< per vertex, by Direction; -1 when no quad edge
  std::vector<int> quads_around;              ///< number of incident quads
  std::vector<VertexClass> vertex_class;
  std::vector<std::array<int, 2>> edges;  ///< unique quad edges, (smaller, larger) index
  int count(VertexClass c) const;
};

QuadTopology quad_topology(const DogMesh& mesh);

}  // namespace sdog
