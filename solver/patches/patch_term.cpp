#include "solver/patches/patch_term.h"

#include <algorithm>
#include <array>
#include <stdexcept>

namespace sdog {

const Dofs* PatchCoupling::frozen_for(const Term* term) const {
  return std::find(split.begin(), split.end(), term) != split.end() ? frozen : nullptr;
}

namespace {
// Split blocks are evaluated on the stack (the SQP assembly calls them every step): fold-bias
// blocks have 8 vertices and 1 row, angle blocks 4 vertices and 1 row.
constexpr int kMaxSplitVertices = 16, kMaxSplitRows = 8;
}  // namespace

PatchTerm::PatchTerm(const Term& term, int begin, int end, const Dofs* frozen)
    : term_(term), frozen_(frozen) {
  std::vector<int> local;
  for (int b = 0; b < term.block_count(); ++b) {
    local.clear();
    const int size = term.block_size(b);
    const size_t first_slot = inside_slots_.size();
    for (int j = 0; j < size; ++j) {
      const int v = term.block_vertices(b)[j];
      if (v < begin || v >= end) continue;
      local.push_back(v - begin);
      inside_slots_.push_back(j);
    }
    const bool whole = static_cast<int>(local.size()) == size;
    if (local.empty() || (!whole && !frozen)) {
      inside_slots_.resize(first_slot);
      continue;
    }
    if (!whole && (size > kMaxSplitVertices || term.residual_count(b) > kMaxSplitRows))
      throw std::logic_error(std::string("PatchTerm: a split block of ") + term.name() +
                             " is larger than supported");
    split_count_ += !whole;
    add_block(local.data(), static_cast<int>(local.size()), term.residual_count(b));
    source_.push_back(b);
    inside_offsets_.push_back(static_cast<int>(inside_slots_.size()));
  }
}

void PatchTerm::gather_full(int b, const Eigen::Vector3d* p, Eigen::Vector3d* full) const {
  const int s = source_[b];
  const int* vertices = term_.block_vertices(s);
  for (int j = 0; j < term_.block_size(s); ++j) full[j] = vertex_of(*frozen_, vertices[j]);
  for (int k = inside_offsets_[b]; k < inside_offsets_[b + 1]; ++k)
    full[inside_slots_[k]] = p[k - inside_offsets_[b]];
}

void PatchTerm::evaluate(int b, const Eigen::Vector3d* p, double* r, double* J) const {
  if (!is_split(b)) return term_.evaluate(source_[b], p, r, J);
  const int s = source_[b];
  const int size = term_.block_size(s), rows = term_.residual_count(s);
  std::array<Eigen::Vector3d, kMaxSplitVertices> full;
  gather_full(b, p, full.data());
  if (!J) return term_.evaluate(s, full.data(), r, nullptr);
  std::array<double, kMaxSplitRows * 3 * kMaxSplitVertices> full_J;
  term_.evaluate(s, full.data(), r, full_J.data());
  const int inside = inside_offsets_[b + 1] - inside_offsets_[b];
  for (int i = 0; i < rows; ++i)
    for (int k = 0; k < inside; ++k)
      for (int c = 0; c < 3; ++c)
        J[(i * inside + k) * 3 + c] =
            full_J[(i * size + inside_slots_[inside_offsets_[b] + k]) * 3 + c];
}

void PatchTerm::add_second_order(int b, const Eigen::Vector3d* p, const double* y,
                                 double* H) const {
  if (!is_split(b)) return term_.add_second_order(source_[b], p, y, H);
  const int s = source_[b];
  const int size = term_.block_size(s);
  std::array<Eigen::Vector3d, kMaxSplitVertices> full;
  gather_full(b, p, full.data());
  const int n = 3 * size;
  std::array<double, 9 * kMaxSplitVertices * kMaxSplitVertices> full_H;
  std::fill(full_H.begin(), full_H.begin() + n * n, 0.0);
  term_.add_second_order(s, full.data(), y, full_H.data());
  const int inside = inside_offsets_[b + 1] - inside_offsets_[b];
  const int m = 3 * inside;
  const int* slots = inside_slots_.data() + inside_offsets_[b];
  for (int k = 0; k < inside; ++k)
    for (int l = 0; l < inside; ++l)
      for (int c = 0; c < 3; ++c)
        for (int d = 0; d < 3; ++d)
          H[(3 * k + c) * m + 3 * l + d] += full_H[(3 * slots[k] + c) * n + 3 * slots[l] + d];
}

}  // namespace sdog
