#pragma once
// Lookup tables of the scalar and categorical layers.
#include <vtkLookupTable.h>
#include <vtkSmartPointer.h>

#include <vector>

#include "ui/vis/palette.h"

namespace sdog::vis {

/// 256 colours from dark purple (low) over teal and green to yellow (high), interpolated in Lab,
/// over [low, high]; NaN grey. The surface scalar layers (dog-residual, bending, edge-strain).
vtkSmartPointer<vtkLookupTable> sequential_lut(double low, double high);

/// The dog-residual layer: sequential_lut over the log10 of the residual from -10 to -2 (1e-10, the
/// floor of log10_residuals in scene_state.h, to 1e-2).
vtkSmartPointer<vtkLookupTable> dog_residual_lut();

/// 256 colours from pale orange (low) to dark red (high) over [low, high]: the stitch-gap
/// glyphs, told apart from a surface layer's colours.
vtkSmartPointer<vtkLookupTable> heat_lut(double low, double high);

/// One colour per value 0 .. count-1 (patch_color), indexed lookup: patches.
vtkSmartPointer<vtkLookupTable> categorical_lut(int count);

/// [0, max(values)], or [0, 1] when every value is 0 (or there are none): the stitch-gap glyphs.
std::array<double, 2> zero_based_range(const std::vector<double>& values);

/// [0, q] with q the 95th percentile of the values (the largest value if that is 0; [0, 1] when
/// all are 0): the linear surface layers (bending, edge strain), whose few extreme values would
/// otherwise leave everything else in the bottom colour. Larger values take the top colour.
std::array<double, 2> robust_range(std::vector<double> values);

}  // namespace sdog::vis
