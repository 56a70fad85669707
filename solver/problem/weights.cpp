#include "solver/problem/weights.h"

namespace sdog {

const OptionTable<Weights>& weights_option_table() {
  using W = Weights;
  static const OptionTable<W> table = {
      real_option("bending", &W::bending, Bounds::at_least(0), "weight of the bending energy"),
      real_option("isometry", &W::isometry, Bounds::at_least(0),
                  "weight of the isometry energy, divided by the number of quad edges"),
      real_option("stitching", &W::stitching, Bounds::at_least(0),
                  "weight of the stitching term (the two copies of a crease point)"),
      real_option("positions", &W::positions, Bounds::at_least(0),
                  "weight of the position targets (handles)"),
      real_option("edge_points", &W::edge_points, Bounds::at_least(0),
                  "weight of targets on points inside grid edges"),
      real_option("angles", &W::angles, Bounds::at_least(0),
                  "weight of the dihedral angle targets"),
      real_option("fold_bias", &W::fold_bias, Bounds::at_least(0),
                  "base weight of the fold bias, which keeps folded creases folded"),
      real_option("link", &W::link, Bounds::at_least(0),
                  "weight of the link targets between fine and coarse twins (coarse modes)"),
  };
  return table;
}

std::string Weights::validate() const {
  const std::string m = check_option_bounds(weights_option_table(), *this);
  return m.empty() ? m : "weight " + m;
}

}  // namespace sdog
