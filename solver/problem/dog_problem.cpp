#include "solver/problem/dog_problem.h"

#include <algorithm>

namespace sdog {

const char* term_name(int index) {
  static const char* names[kTermCount] = {"bending",   "isometry", "positions", "edge_points",
                                          "stitching", "angles",   "fold_bias", "link"};
  return names[index];
}

DogProblem::DogProblem(const DogMesh& mesh, const QuadTopology& topology, const Weights& w,
                       double fold_sharpness)
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
  // A vertex lies on the paper when its cell corner lies in its patch: every corner of a cell
  // wholly in the patch, and the corners a cut cell's piece keeps. An edge between two such
  // vertices is paper unless a crease crosses it.
  std::vector<char> on_paper(mesh.vertex_count(), 0), cut(mesh.F.rows(), 0);
  const Eigen::Vector2d corners[4] = {
      {0, 0}, {1, 0}, {1, 1}, {0, 1}};  // of F(q, 0..3) in cell coordinates
  for (const auto& piece : mesh.quad_pieces) {
    cut[piece.quad] = 1;
    for (int k = 0; k < 4; ++k)
      for (const auto& uv : piece.uv)
        if ((uv - corners[k]).norm() < 1e-9) on_paper[mesh.F(piece.quad, k)] = 1;
  }
  for (int q = 0; q < mesh.F.rows(); ++q)
    for (int k = 0; k < 4 && !cut[q]; ++k) on_paper[mesh.F(q, k)] = 1;
  auto edge = [](int a, int b) { return std::pair<int, int>(std::min(a, b), std::max(a, b)); };
  std::vector<std::pair<int, int>> crossed;
  for (const auto& point : mesh.stitching.points)
    for (const EdgePoint& e : point.copies) crossed.push_back(edge(e.v1, e.v2));
  std::sort(crossed.begin(), crossed.end());
  for (int b = 0; b < isometry.block_count(); ++b) {
    const int* v = isometry.block_vertices(b);
    sheet_edges.push_back(on_paper[v[0]] && on_paper[v[1]] &&
                          !std::binary_search(crossed.begin(), crossed.end(), edge(v[0], v[1])));
  }
  for (const auto& pair : mesh.stitching.pairs) {
    const auto& p = mesh.stitching.points[pair.point];
    const EdgePoint& a = p.copies[pair.a];
    const EdgePoint& b = p.copies[pair.b];
    stitching.add({{a.v1, a.t}, {a.v2, 1 - a.t}, {b.v1, -b.t}, {b.v2, -(1 - b.t)}});
  }
}

double DogProblem::effective_weight(int index) const {
  switch (index) {
    case kBending:
      return weights.bending;
    case kIsometry:
      return weights.isometry / std::max(1, isometry.edge_count());
    case kPositions:
      return weights.positions;
    case kEdgePoints:
      return weights.edge_points;
    case kStitching:
      return weights.stitching;
    case kAngles:
      return weights.angles;
    case kFoldBias:
      return weights.fold_bias;
    case kLink:
      return weights.link;
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
  const Term* terms[kTermCount] = {&bending,   &isometry, &positions, &edge_points,
                                   &stitching, &angles,   &fold_bias, &link};
  std::vector<WeightedTerm> out;
  for (int k = 0; k < kTermCount; ++k)
    out.push_back({terms[k], effective_weight(k), k == kIsometry});
  return out;
}

}  // namespace sdog
