#pragma once
// The paper style of a picture (`sdog render --style paper`): a figure for a publication rather
// than a debugging view. The scene (SceneOptions::paper) drops its legends, titles and crease-point
// dots, draws the trimmed surface in a paper colour with a darker back side, and crease curves as
// lines coloured by assignment; the renderer gets a light kit (key, fill and back lights that show
// the folds), FXAA antialiasing, and optionally screen-space ambient occlusion or shadow maps,
// VTK 9.1's render passes (one of the two: with shadows on, its renderer skips the occlusion).
#include <vtkRenderer.h>

#include <string>

namespace sdog::vis {

struct PaperEffects {
  bool ambient_occlusion = true;  ///< SSAO: darkens creases and the insides of folds
  bool shadows = false;           ///< shadow maps of the key light (hard shadows)
};

/// Parses "ambient-occlusion", "shadows" or "none". Throws UsageError naming a bad name and the
/// known ones, or for both effects at once (VTK 9.1's renderer draws one of them).
PaperEffects parse_paper_effects(const std::string& text);

/// Lights, antialiasing and the chosen effects of the paper style on `renderer`. `scene_size`
/// (the diagonal of what is drawn, mesh units) scales the ambient occlusion's radius.
void apply_paper_lighting(vtkRenderer* renderer, double scene_size, const PaperEffects& effects);

}  // namespace sdog::vis
