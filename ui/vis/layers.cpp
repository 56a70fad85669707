#include "ui/vis/layers.h"

#include <algorithm>
#include <optional>
#include <sstream>

#include "base/errors.h"

namespace sdog::vis {
namespace {

struct LayerInfo {
  Layer layer;
  const char* description;
  bool colour;
};

const LayerInfo kLayers[] = {
    {Layer::kVertexTypes,
     "vertices coloured by their type in the fine/coarse map (link green, I light blue, X purple, "
     "coarse-only "
     "red), crease points pink; on the fine and the coarse mesh",
     true},
    {Layer::kLinks, "a line from every fine link vertex to its coarse twin", false},
    {Layer::kPatches, "faces coloured by patch", true},
    {Layer::kDogResidual,
     "DOG constraint residual per vertex (largest |c| of its rows), log10 scale from 1e-10 to 1e-2",
     true},
    {Layer::kEdgeStrain,
     "per quad the largest |length / rest length - 1| of its edges (colours from 0 to the 95th "
     "percentile)",
     true},
    {Layer::kStitchGap,
     "per crease point the largest distance between its copies, as sphere size and colour", false},
    {Layer::kBending,
     "bending energy per vertex (|r|^2 of its bending block; colours from 0 to the 95th "
     "percentile)",
     true},
    {Layer::kHandles,
     "position handles (orange), their targets (dark blue) and residual lines (red); "
     "angle-constraint sites "
     "(cyan)",
     false},
    {Layer::kCreaseCurves,
     "crease polylines through the crease points coloured by assignment (mountain red, valley "
     "blue, flat light "
     "grey, unassigned grey), crease points pink",
     false},
    {Layer::kWireframe, "the quad edges", false},
    {Layer::kFullCells,
     "every quad drawn whole, overhanging its patch's creases (the DOG as the solver sees it), "
     "instead of the "
     "trimmed surface, where each patch ends at its creases",
     false},
};

const LayerInfo& info(Layer layer) {
  return kLayers[static_cast<int>(layer)];
}

}  // namespace

const char* layer_description(Layer layer) {
  return info(layer).description;
}
bool is_colour_layer(Layer layer) {
  return info(layer).colour;
}

std::string known_colour_layers() {
  std::string out;
  for (const Layer layer : enum_values<Layer>())
    if (is_colour_layer(layer)) out += (out.empty() ? "" : ", ") + std::string(enum_name(layer));
  return out;
}

Layer parse_colour_layer(const std::string& name, const std::string& context) {
  if (const auto layer = find_enum<Layer>(name); layer && is_colour_layer(*layer)) return *layer;
  throw UsageError(context + "'" + name +
                   "' is not a colour layer (known: " + known_colour_layers() + ")");
}

std::vector<Layer> parse_layers(const std::string& text) {
  const std::vector<Layer> out = parse_enum_list<Layer>(text);
  std::optional<Layer> colour;
  for (const Layer layer : out) {
    if (!is_colour_layer(layer)) continue;
    if (colour)
      throw UsageError(std::string("overlays '") + enum_name(*colour) + "' and '" +
                       enum_name(layer) + "' both colour the mesh; pick one of them");
    colour = layer;
  }
  return out;
}

}  // namespace sdog::vis
