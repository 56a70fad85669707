#pragma once
// Rendering regression: compares a freshly rendered PNG with BASELINES/NAME.png using
// vtkImageDifference. On a mismatch (or a missing baseline) the new image is kept next to the
// baseline as NAME.new.png, and the difference as NAME.diff.png, for review; a match removes
// both. SDOG_UPDATE_BASELINES=1 replaces the baseline instead (see tests/baselines/README.md).
#include <gtest/gtest.h>
#include <vtkImageData.h>
#include <vtkImageDifference.h>
#include <vtkPNGReader.h>
#include <vtkPNGWriter.h>
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
      for (int k = 0; k < 3; ++k)
        d += std::abs(img->GetScalarComponentAsDouble(x, y, 0, k) - 255 * c[k]);
      count += d < 12;
    }
  return count;
}

/// How images are compared. vtkImageDifference takes, per pixel and channel, the smallest
/// difference (0-255) to the baseline's pixels within a shift of one pixel (also of 3x3
/// averages), subtracts `pixel_threshold` and clamps at 0; its thresholded error is the sum over
/// the pixels of the mean of the three channels / 255, so about the number of pixels that differ
/// completely. It must stay at or below `max_error_fraction` x the number of pixels. With 10 and
/// 5e-4 (115 at 640x360) a picture passes rounding noise and one-pixel shifts but fails when a
/// thin layer is missing (crease lines alone: about 340) or a colour layer is another (1500).
struct ImageTolerance {
  int pixel_threshold = 10;
  double max_error_fraction = 5e-4;
};

/// Pixels with a channel that differs by more than `level` (0-255) between two images (-1 when
/// their sizes or channels differ).
inline long differing_pixels(vtkImageData* a, vtkImageData* b, int level = 0) {
  int da[3], db[3];
  a->GetDimensions(da);
  b->GetDimensions(db);
  const int channels = a->GetNumberOfScalarComponents();
  if (da[0] != db[0] || da[1] != db[1] || channels != b->GetNumberOfScalarComponents()) return -1;
  long count = 0;
  for (int y = 0; y < da[1]; ++y)
    for (int x = 0; x < da[0]; ++x) {
      bool same = true;
      for (int k = 0; k < channels; ++k)
        same = same && std::abs(a->GetScalarComponentAsDouble(x, y, 0, k) -
                                b->GetScalarComponentAsDouble(x, y, 0, k)) <= level;
      count += !same;
    }
  return count;
}

/// Returns an empty string when the image matches baselines_dir/NAME.png within the tolerance,
/// else a message saying where the new image and the difference are kept.
inline std::string compare_with_baseline(const std::string& image, const std::string& name,
                                         const ImageTolerance& tolerance = {},
                                         const std::string& baselines_dir = SDOG_BASELINES_DIR) {
  namespace fs = std::filesystem;
  const std::string baseline = baselines_dir + "/" + name + ".png";
  const std::string kept = baselines_dir + "/" + name + ".new.png";
  const std::string diff_path = baselines_dir + "/" + name + ".diff.png";
  const char* update = std::getenv("SDOG_UPDATE_BASELINES");
  if (update && std::string(update) == "1") {
    fs::copy_file(image, baseline, fs::copy_options::overwrite_existing);
    return "";
  }
  fs::remove(diff_path);
  if (!fs::exists(baseline)) {
    fs::copy_file(image, kept, fs::copy_options::overwrite_existing);
    return "no baseline " + baseline + "; the new image is kept as " + kept;
  }
  auto actual = read_png(image), expected = read_png(baseline);
  int a[3], e[3];
  actual->GetDimensions(a);
  expected->GetDimensions(e);
  if (a[0] != e[0] || a[1] != e[1]) {
    fs::copy_file(image, kept, fs::copy_options::overwrite_existing);
    return "image is " + std::to_string(a[0]) + "x" + std::to_string(a[1]) + ", " + baseline + " " +
           std::to_string(e[0]) + "x" + std::to_string(e[1]) + "; the new image is kept as " + kept;
  }
  auto diff = vtkSmartPointer<vtkImageDifference>::New();
  diff->SetInputData(actual);
  diff->SetImageData(expected);
  diff->SetThreshold(tolerance.pixel_threshold);
  diff->Update();
  const double error = diff->GetThresholdedError();
  const double limit = tolerance.max_error_fraction * a[0] * a[1];
  if (error <= limit) {
    fs::remove(kept);
    return "";
  }
  fs::copy_file(image, kept, fs::copy_options::overwrite_existing);
  auto writer = vtkSmartPointer<vtkPNGWriter>::New();
  writer->SetFileName(diff_path.c_str());
  writer->SetInputConnection(diff->GetOutputPort());
  writer->Write();
  return "image differs from " + baseline + " (thresholded error " + std::to_string(error) + " > " +
         std::to_string(limit) + "); the new image is kept as " + kept + ", the difference as " +
         diff_path;
}

}  // namespace sdog::test
