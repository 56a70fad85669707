#include "solver/problem/dog_problem.h"

#include <algorithm>

namespace sdog {

const char* term_name(int index) {
  static const char* names[kTermCount] = {"bending", "isometry", "positions", "edge_points",
                                          "stitching", "angles", "fold_bias", "link"};
  return names[index];
}

DogProblem::DogProblem(const DogMesh& mesh, const QuadTopology& topology, const Weights& w, double fold_sharpness)
    : weights(w),
      isometry(topology, to_dofs(mesh.V)),
      sites(fold_sites(mesh)),
      free_sites(sites),
      fold_bias(mesh, free_sites, fold_sharpness),
      fold_angles(mesh),
      dog(topology),
      mesh_(mesh),
      topology_(topology),
      rest_(to_dofs(mesh.V)),
      fold_sharpness_(fold_sharpness) {
  bending = make_bending_term(topology, rest_);
  for (const auto& pair : mesh.stitching.pairs) {
    const auto& p = mesh.stitching.points[pair.point];
    const EdgePoint& a = p.copies[pair.a];
    const EdgePoint& b = p.copies[pair.b];
    stitching.add({{a.v1, a.t}, {a.v2, 1 - a.t}, {b.v1, -b.t}, {b.v2, -(1 - b.t)}});
  }
}

double DogProblem::effective_weight(int index) const {
  switch (index) {
    case kBending: return weights.bending;
    case kIsometry: return weights.isometry / std::max(1, isometry.edge_count());
    case kPositions: return weights.positions;
    case kEdgePoints: return weights.edge_points;
    case kStitching: return weights.stitching;
    case kAngles: return weights.angles;
    case kFoldBias: return weights.fold_bias;
    case kLink: return weights.link;
  }
  return 0;
}

void DogProblem::update_free_sites() {
  std::vector<char> targeted(mesh_.stitching.points.size(), 0);
  for (int b = 0; b < angles.block_count(); ++b) targeted[angles.point(b)] = 1;
  free_sites.clear();
  for (const auto& site : sites)
    if (!targeted[site.point]) free_sites.push_back(site);
  fold_bias = FoldBiasTerm(mesh_, free_sites, fold_sharpness_);
}

std::vector<WeightedTerm> DogProblem::objective_terms() const {
  const Term* terms[kTermCount] = {&bending, &isometry, &positions, &edge_points,
                                   &stitching, &angles, &fold_bias, &link};
  std::vector<WeightedTerm> out;
  for (int k = 0; k < kTermCount; ++k) out.push_back({terms[k], effective_weight(k), k == kIsometry});
  return out;
}

}  // namespace sdog
