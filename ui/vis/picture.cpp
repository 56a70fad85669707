#include "ui/vis/picture.h"

#include <vtkRenderer.h>

#include <algorithm>
#include <cmath>

#include "base/errors.h"

namespace sdog::vis {

int picture_font_size(const ImageSize& size) {
  return std::clamp(size.height / 32, 10, 40);
}

void render_picture(const DogModel& model, const SceneState& state, const PictureOptions& options,
                    const std::string& path) {
  int colour_layers = 0;
  for (Layer l : options.layers) colour_layers += is_colour_layer(l);
  if (colour_layers > 1)
    throw UsageError(
        "a picture shows at most one of the overlays that colour the mesh (vertex-types, patches, "
        "dog-residual, edge-strain, bending)");
  auto window = offscreen_window(options.size);
  auto renderer = vtkSmartPointer<vtkRenderer>::New();
  // The scene's 2D actors measure themselves against the camera as they are added: without one VTK
  // logs an error for each.
  renderer->GetActiveCamera();
  renderer->SetBackground(1, 1, 1);
  if (options.transparent) renderer->SetBackgroundAlpha(0);
  window->AddRenderer(renderer);

  SceneOptions scene_options = options.scene;
  if (scene_options.font_size <= 0) scene_options.font_size = picture_font_size(options.size);
  scene_options.paper = options.paper;
  Scene scene(model, renderer, scene_options);
  scene.update(state);
  for (Layer l : options.layers) scene.set_layer(l, true);
  if (!options.paper) scene.set_caption(options.caption);
  scene.reset_camera();
  if (options.camera) {
    apply_camera_pose(*options.camera, renderer->GetActiveCamera());
    renderer->ResetCameraClippingRange();
    if (options.frame) scene.frame_all();
  }
  if (options.paper) {
    double b[6];
    renderer->ComputeVisiblePropBounds(b);
    const double diagonal =
        std::sqrt((b[1] - b[0]) * (b[1] - b[0]) + (b[3] - b[2]) * (b[3] - b[2]) +
                  (b[5] - b[4]) * (b[5] - b[4]));
    apply_paper_lighting(renderer, diagonal, options.effects);
  }
  save_png(window, path, options.transparent);
}

}  // namespace sdog::vis
