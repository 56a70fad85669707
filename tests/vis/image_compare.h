#pragma once
// Rendering regression: compares a freshly rendered PNG with tests/baselines/NAME.png using
// vtkImageDifference. On a mismatch (or a missing baseline) the new image is kept next to the
// baseline as NAME.new.png for review; SDOG_UPDATE_BASELINES=1 replaces the baseline instead.
#include <gtest/gtest.h>
#include <vtkImageData.h>
#include <vtkImageDifference.h>
#include <vtkPNGReader.h>
#include <vtkSmartPointer.h>

#include <array>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>

namespace sdog::test {

inline vtkSmartPointer<vtkImageData> read_png(const std::string& path) {
  auto r = vtkSmartPointer<vtkPNGReader>::New();
  r->SetFileName(path.c_str());
  r->Update();
  return r->GetOutput();
}

/// Number of pixels within a small distance (sum of channel differences below 12) of an RGB
/// colour with components in [0, 1].
inline int pixels_near(vtkImageData* img, const std::array<double, 3>& c) {
  int dims[3];
  img->GetDimensions(dims);
  int count = 0;
  for (int y = 0; y < dims[1]; ++y)
    for (int x = 0; x < dims[0]; ++x) {
      double d = 0;
      for (int k = 0; k < 3; ++k) d += std::abs(img->GetScalarComponentAsDouble(x, y, 0, k) - 255 * c[k]);
      count += d < 12;
    }
  return count;
}

/// Returns an empty string when the image matches its baseline within `threshold` (mean
/// per-pixel error reported by vtkImageDifference), else a message.
inline std::string compare_with_baseline(const std::string& image, const std::string& name,
                                         double threshold = 10.0) {
  namespace fs = std::filesystem;
  const std::string baseline = std::string(SDOG_BASELINES_DIR) + "/" + name + ".png";
  const std::string kept = std::string(SDOG_BASELINES_DIR) + "/" + name + ".new.png";
  const char* update = std::getenv("SDOG_UPDATE_BASELINES");
  if (update && std::string(update) == "1") {
    fs::copy_file(image, baseline, fs::copy_options::overwrite_existing);
    return "";
  }
  if (!fs::exists(baseline)) {
    fs::copy_file(image, kept, fs::copy_options::overwrite_existing);
    return "no baseline " + baseline + "; the new image is kept as " + kept;
  }
  auto diff = vtkSmartPointer<vtkImageDifference>::New();
  diff->SetInputData(read_png(image));
  diff->SetImageData(read_png(baseline));
  diff->Update();
  const double error = diff->GetThresholdedError();
  if (error <= threshold) {
    fs::remove(kept);
    return "";
  }
  fs::copy_file(image, kept, fs::copy_options::overwrite_existing);
  return "image differs from " + baseline + " (thresholded error " + std::to_string(error) + " > " +
         std::to_string(threshold) + "); the new image is kept as " + kept;
}

}  // namespace sdog::test
