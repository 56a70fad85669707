#pragma once
// The overlays of a scene: named layers switched on and off (the command line spells them in
// kebab-case, `sdog render --overlay dog-residual,handles`). A colour layer colours the meshes
// (their vertices or their faces); at most one is on at a time, as one colour quantity dominates
// a Polyscope surface.
#include <string>
#include <vector>

namespace sdog::vis {

enum class Layer : int {
  VertexTypes,   ///< vertices coloured link / I / X / coarse-only, crease points pink (colour layer)
  Links,         ///< lines from each fine link vertex to its coarse twin
  Patches,       ///< faces coloured by patch (colour layer)
  DogResidual,   ///< DOG constraint residual per vertex, log10 scale (colour layer)
  EdgeStrain,    ///< largest |length / rest length - 1| of a quad's edges (colour layer)
  StitchGap,     ///< per crease point: distance between its copies, as glyph size and colour
  Bending,       ///< bending energy |r|^2 per vertex (colour layer)
  Handles,       ///< position handles, their targets and residual lines; angle-constraint sites
  CreaseCurves,  ///< crease polylines coloured by assignment, crease points pink
  Wireframe,     ///< the quad edges
  FullCells,     ///< every quad whole instead of the trimmed surface (the DOG as the solver sees it)
};

/// Every layer, in the order above (the order of the documentation).
const std::vector<Layer>& all_layers();
/// "vertex-types", "links", ... (kebab-case).
const char* layer_name(Layer layer);
/// One line saying what the layer shows (help texts).
const char* layer_description(Layer layer);
/// The layer names, comma separated.
std::string known_layers();
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
