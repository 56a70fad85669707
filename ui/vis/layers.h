#pragma once
// The overlays of a scene: named layers switched on and off (the command line spells them in
// kebab-case, `sdog render --overlay dog-residual,handles`). A colour layer colours the meshes
// (their vertices or their faces); at most one is on at a time, as one colour quantity dominates
// a Polyscope surface.
#include <string>
#include <vector>

#include "base/enum_names.h"

namespace sdog::vis {

enum class Layer : int {
  kVertexTypes,   ///< vertices coloured link / I / X / coarse-only, crease points pink (colour
                  ///< layer)
  kLinks,         ///< lines from each fine link vertex to its coarse twin
  kPatches,       ///< faces coloured by patch (colour layer)
  kDogResidual,   ///< DOG constraint residual per vertex, log10 scale (colour layer)
  kEdgeStrain,    ///< largest |length / rest length - 1| of a quad's edges (colour layer)
  kStitchGap,     ///< per crease point: distance between its copies, as glyph size and colour
  kBending,       ///< bending energy |r|^2 per vertex (colour layer)
  kHandles,       ///< position handles, their targets and residual lines; angle-constraint sites
  kCreaseCurves,  ///< crease polylines coloured by assignment, crease points pink
  kWireframe,     ///< the quad edges
  kFullCells,  ///< every quad whole instead of the trimmed surface (the DOG as the solver sees it)
};

}  // namespace sdog::vis

namespace sdog {
/// The layers by name, in the order above (the order of the documentation).
template <>
struct EnumNames<vis::Layer> {
  static constexpr const char* noun = "overlay";
  static constexpr EnumName<vis::Layer> rows[] = {
      {vis::Layer::kVertexTypes, "vertex-types"},
      {vis::Layer::kLinks, "links"},
      {vis::Layer::kPatches, "patches"},
      {vis::Layer::kDogResidual, "dog-residual"},
      {vis::Layer::kEdgeStrain, "edge-strain"},
      {vis::Layer::kStitchGap, "stitch-gap"},
      {vis::Layer::kBending, "bending"},
      {vis::Layer::kHandles, "handles"},
      {vis::Layer::kCreaseCurves, "crease-curves"},
      {vis::Layer::kWireframe, "wireframe"},
      {vis::Layer::kFullCells, "full-cells"},
  };
};
}  // namespace sdog

namespace sdog::vis {

/// One line saying what the layer shows (help texts).
const char* layer_description(Layer layer);
/// True for the layers that colour the meshes: vertex-types, patches, dog-residual, edge-strain,
/// bending.
bool is_colour_layer(Layer layer);

/// The names of the colour layers, comma separated.
std::string known_colour_layers();
/// Parses the name of one colour layer ("bending"). Throws UsageError, `context` followed by the
/// bad name and the colour layers.
Layer parse_colour_layer(const std::string& name, const std::string& context = "");

/// Parses "dog-residual,handles" (comma separated, no duplicates, at most one colour layer).
/// Throws UsageError naming the bad name and the known ones.
std::vector<Layer> parse_layers(const std::string& text);

}  // namespace sdog::vis
