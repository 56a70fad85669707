#include "ui/vis/layers.h"

#include <algorithm>
#include <optional>
#include <sstream>

#include "base/errors.h"

namespace sdog::vis {
namespace {

struct LayerInfo {
  Layer layer;
  const char* name;
  const char* description;
  bool colour;
};

const LayerInfo kLayers[] = {
    {Layer::VertexTypes, "vertex-types",
     "vertices coloured by their type in the fine/coarse map (link green, I light blue, X purple, coarse-only "
     "red), crease points pink; on the fine and the coarse mesh",
     true},
    {Layer::Links, "links", "a line from every fine link vertex to its coarse twin", false},
    {Layer::Patches, "patches", "faces coloured by patch", true},
    {Layer::DogResidual, "dog-residual",
     "DOG constraint residual per vertex (largest |c| of its rows), log10 scale from 1e-10 to 1e-2", true},
    {Layer::EdgeStrain, "edge-strain", "per quad the largest |length / rest length - 1| of its edges (colours from 0 to the 95th percentile)", true},
    {Layer::StitchGap, "stitch-gap",
     "per crease point the largest distance between its copies, as sphere size and colour", false},
    {Layer::Bending, "bending", "bending energy per vertex (|r|^2 of its bending block; colours from 0 to the 95th percentile)", true},
    {Layer::Handles, "handles",
     "position handles (orange), their targets (dark blue) and residual lines (red); angle-constraint sites "
     "(cyan)",
     false},
    {Layer::CreaseCurves, "crease-curves",
     "crease polylines through the crease points coloured by assignment (mountain red, valley blue, flat light "
     "grey, unassigned grey), crease points pink",
     false},
    {Layer::Wireframe, "wireframe", "the quad edges", false},
    {Layer::FullCells, "full-cells",
     "every quad drawn whole, overhanging its patch's creases (the DOG as the solver sees it), instead of the "
     "trimmed surface, where each patch ends at its creases",
     false},
};

const LayerInfo& info(Layer layer) { return kLayers[static_cast<int>(layer)]; }

std::string layer_names(bool colour_only) {
  std::string out;
  for (const auto& l : kLayers)
    if (l.colour || !colour_only) out += (out.empty() ? "" : ", ") + std::string(l.name);
  return out;
}

}  // namespace

const std::vector<Layer>& all_layers() {
  static const std::vector<Layer> layers = [] {
    std::vector<Layer> out;
    for (const auto& l : kLayers) out.push_back(l.layer);
    return out;
  }();
  return layers;
}

const char* layer_name(Layer layer) { return info(layer).name; }
const char* layer_description(Layer layer) { return info(layer).description; }
bool is_colour_layer(Layer layer) { return info(layer).colour; }

std::string known_layers() { return layer_names(false); }
std::string known_colour_layers() { return layer_names(true); }

Layer parse_colour_layer(const std::string& name, const std::string& context) {
  for (const auto& l : kLayers)
    if (l.colour && name == l.name) return l.layer;
  throw UsageError(context + "'" + name + "' is not a colour layer (known: " + known_colour_layers() + ")");
}

std::vector<Layer> parse_layers(const std::string& text) {
  std::vector<Layer> out;
  std::stringstream in(text);
  std::string name;
  std::optional<Layer> colour;
  while (std::getline(in, name, ',')) {
    const auto it = std::find_if(std::begin(kLayers), std::end(kLayers),
                                 [&](const LayerInfo& l) { return name == l.name; });
    if (it == std::end(kLayers))
      throw UsageError("unknown overlay '" + name + "' (known: " + known_layers() + ")");
    if (std::find(out.begin(), out.end(), it->layer) != out.end())
      throw UsageError("overlay '" + name + "' is listed twice");
    out.push_back(it->layer);
    if (it->colour) {
      if (colour)
        throw UsageError(std::string("overlays '") + layer_name(*colour) + "' and '" + name +
                         "' both colour the mesh; pick one of them");
      colour = it->layer;
    }
  }
  if (out.empty()) throw UsageError("no overlay given (known: " + known_layers() + ")");
  return out;
}

}  // namespace sdog::vis
