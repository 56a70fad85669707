#include "solver/patch_term.h"

namespace sdog {

PatchTerm::PatchTerm(const Term& term, int begin, int end) : term_(term) {
  std::vector<int> local;
  for (int b = 0; b < term.block_count(); ++b) {
    local.clear();
    for (int j = 0; j < term.block_size(b); ++j) {
      const int v = term.block_vertices(b)[j];
      if (v < begin || v >= end) break;
      local.push_back(v - begin);
    }
    if (static_cast<int>(local.size()) != term.block_size(b)) continue;
    add_block(local.data(), static_cast<int>(local.size()), term.residual_count(b));
    source_.push_back(b);
  }
}

}  // namespace sdog
