#include "ui/vis/paper_style.h"

#include <vtkLightKit.h>
#include <vtkSmartPointer.h>

#include <sstream>

#include "base/errors.h"

namespace sdog::vis {
namespace {

// Ambient occlusion: hemisphere radius and depth bias as fractions of the scene's size, and the
// number of samples (more: smoother, slower).
constexpr double kOcclusionRadius = 0.04, kOcclusionBias = 0.002;
constexpr unsigned kOcclusionSamples = 128;

}  // namespace

PaperEffects parse_paper_effects(const std::string& text) {
  PaperEffects effects{false, false};
  if (text == "none") return effects;
  std::stringstream in(text);
  std::string name;
  while (std::getline(in, name, ',')) {
    if (name == "ambient-occlusion")
      effects.ambient_occlusion = true;
    else if (name == "shadows")
      effects.shadows = true;
    else
      throw UsageError("unknown render effect '" + name +
                       "' (known: ambient-occlusion, shadows, or none)");
  }
  if (effects.ambient_occlusion && effects.shadows)
    throw UsageError(
        "render effects: ambient-occlusion or shadows, not both (VTK 9.1's renderer draws one of "
        "them)");
  return effects;
}

void apply_paper_lighting(vtkRenderer* renderer, double scene_size, const PaperEffects& effects) {
  renderer->RemoveAllLights();
  auto kit = vtkSmartPointer<vtkLightKit>::New();
  kit->SetKeyLightIntensity(0.9);
  kit->SetKeyToFillRatio(2.5);
  kit->SetKeyToHeadRatio(4);
  kit->SetKeyToBackRatio(3);
  kit->AddLightsToRenderer(renderer);
  renderer->UseFXAAOn();
  if (effects.ambient_occlusion) {
    renderer->UseSSAOOn();
    renderer->SetSSAORadius(kOcclusionRadius * scene_size);
    renderer->SetSSAOBias(kOcclusionBias * scene_size);
    renderer->SetSSAOKernelSize(kOcclusionSamples);
    renderer->SSAOBlurOn();
  }
  renderer->SetUseShadows(effects.shadows);
}

}  // namespace sdog::vis
