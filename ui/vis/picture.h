#pragma once
// A scene rendered offscreen to PNG in one call: what `sdog render` and the rendering tests draw.
#include <optional>
#include <string>
#include <vector>

#include "geometry/mesh/dog_model.h"
#include "ui/vis/camera.h"
#include "ui/vis/layers.h"
#include "ui/vis/offscreen.h"
#include "ui/vis/paper_style.h"
#include "ui/vis/scene.h"
#include "ui/vis/scene_state.h"

namespace sdog::vis {

struct PictureOptions {
  std::vector<Layer> layers{Layer::kVertexTypes, Layer::kCreaseCurves, Layer::kWireframe};
  SceneOptions scene{View::kSideBySide, false, 0};  ///< font_size 0: from the image height
  ImageSize size;
  bool transparent = false;  ///< transparent background (RGBA PNG)
  std::string caption;       ///< top-left text (empty: none)
  std::optional<CameraPose>
      camera;            ///< instead of the view's default camera (dots keep the default's size)
  bool frame = false;    ///< with `camera`: looking its way, framing the drawing (Scene::frame_all)
  bool paper = false;    ///< the paper style (paper_style.h); no caption
  PaperEffects effects;  ///< of the paper style
};

/// Font size of a picture's legends and titles: the image height / 32, between 10 and 40.
int picture_font_size(const ImageSize& size);

/// Draws the state with the layers (at most one colour layer: UsageError otherwise), in the
/// paper style if asked, on a white background with the view's default camera (or the given one)
/// and writes the PNG to `path` (needs an X display, see offscreen.h; OutputError when the file
/// cannot be written).
void render_picture(const DogModel& model, const SceneState& state, const PictureOptions& options,
                    const std::string& path);

}  // namespace sdog::vis
