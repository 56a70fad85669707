#include "ui/vis/colour_maps.h"

#include <vtkColorTransferFunction.h>

#include <algorithm>

namespace sdog::vis {
namespace {

struct Stop {
  double at;
  Rgb colour;
};

vtkSmartPointer<vtkLookupTable> lut_from_stops(const std::vector<Stop>& stops, double low,
                                               double high) {
  auto ctf = vtkSmartPointer<vtkColorTransferFunction>::New();
  ctf->SetColorSpaceToLab();
  for (const auto& s : stops) ctf->AddRGBPoint(s.at, s.colour[0], s.colour[1], s.colour[2]);
  constexpr int n = 256;
  auto lut = vtkSmartPointer<vtkLookupTable>::New();
  lut->SetNumberOfTableValues(n);
  for (int i = 0; i < n; ++i) {
    double rgb[3];
    ctf->GetColor(static_cast<double>(i) / (n - 1), rgb);
    lut->SetTableValue(i, rgb[0], rgb[1], rgb[2], 1);
  }
  lut->SetTableRange(low, high);
  lut->SetNanColor(0.6, 0.6, 0.6, 1);
  return lut;
}

}  // namespace

vtkSmartPointer<vtkLookupTable> sequential_lut(double low, double high) {
  return lut_from_stops({{0.0, {0.20, 0.05, 0.36}},
                         {0.35, {0.14, 0.42, 0.56}},
                         {0.70, {0.35, 0.74, 0.38}},
                         {1.0, {0.99, 0.90, 0.20}}},
                        low, high);
}

vtkSmartPointer<vtkLookupTable> dog_residual_lut() {
  return sequential_lut(-10, -2);
}

vtkSmartPointer<vtkLookupTable> heat_lut(double low, double high) {
  return lut_from_stops(
      {{0.0, {1.00, 0.82, 0.55}}, {0.5, {0.93, 0.42, 0.14}}, {1.0, {0.55, 0.00, 0.05}}}, low, high);
}

vtkSmartPointer<vtkLookupTable> categorical_lut(int count) {
  auto lut = vtkSmartPointer<vtkLookupTable>::New();
  lut->IndexedLookupOn();
  lut->SetNumberOfTableValues(std::max(count, 1));
  for (int k = 0; k < count; ++k) {
    const Rgb c = patch_colour(k);
    lut->SetTableValue(k, c[0], c[1], c[2], 1);
    lut->SetAnnotation(vtkVariant(k), ("patch " + std::to_string(k)).c_str());
  }
  return lut;
}

std::array<double, 2> zero_based_range(const std::vector<double>& values) {
  double high = 0;
  for (double v : values)
    if (v > high) high = v;  // NaN never is
  return {0.0, high > 0 ? high : 1.0};
}

std::array<double, 2> robust_range(std::vector<double> values) {
  if (values.empty()) return {0.0, 1.0};
  const size_t k = (values.size() - 1) * 95 / 100;
  std::nth_element(values.begin(), values.begin() + k, values.end());
  const double q = values[k];
  return q > 0 ? std::array<double, 2>{0.0, q} : zero_based_range(values);
}

}  // namespace sdog::vis
