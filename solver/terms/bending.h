#pragma once
// Bending energy of a flat DOG (Rabinovich et al.): at every star vertex the residual
//   r = sum_{k in xf, yf, xb, yb} (p0 - p_k) / L_k          (3 rows),
// at every bnd3 vertex, along the straight boundary only,
//   r = 2 (p0 - p_b1) / L_b1 + 2 (p0 - p_b2) / L_b2,
// with L the rest lengths. For a flat rest state this is |L(x) - L(x0)|^2 of the thesis, a
// quadratic energy with a constant Hessian.
#include "geometry/mesh/quad_topology.h"
#include "solver/terms/linear_point_term.h"

namespace sdog {

/// The bending term of a mesh with the given topology and rest positions.
LinearPointTerm make_bending_term(const QuadTopology& topology, const Dofs& rest);

}  // namespace sdog
