#include "ui/vis/legends.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCoordinate.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper2D.h>
#include <vtkTextProperty.h>
#include <vtkUnsignedCharArray.h>

#include <algorithm>
#include <cmath>
#include <cstring>

namespace sdog::vis {
namespace {

constexpr double kColumnWidth = 0.99 - kLegendColumnLeft;
constexpr double kTop = 0.97;

void style_text(vtkTextProperty* p, int font, bool bold = false) {
  p->SetColor(kTextColour[0], kTextColour[1], kTextColour[2]);
  p->SetFontSize(font);
  p->SetBold(bold);
  p->SetItalic(false);
  p->SetShadow(false);
}

}  // namespace

Legend Legend::scalar_bar(const std::string& title, vtkScalarsToColors* lut) {
  Legend l;
  l.bar_ = vtkSmartPointer<vtkScalarBarActor>::New();
  l.bar_->SetLookupTable(lut);
  l.bar_->SetTitle(title.c_str());
  l.bar_->SetNumberOfLabels(5);
  l.bar_->SetLabelFormat("%-#6.3g");
  l.bar_->UnconstrainedFontSizeOn();
  l.bar_->SetBarRatio(0.2);
  l.bar_->SetTextPad(4);
  l.bar_->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
  l.bar_->GetPosition2Coordinate()->SetCoordinateSystemToNormalizedViewport();
  return l;
}

Legend Legend::categories(const std::string& title, const std::vector<LegendEntry>& entries) {
  Legend l;
  l.title_ = vtkSmartPointer<vtkTextActor>::New();
  l.title_->SetInput(title.c_str());
  l.title_->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
  l.title_->GetTextProperty()->SetVerticalJustificationToTop();
  // The squares: one quad per entry (placed by place()), coloured by cell scalars.
  l.squares_ = vtkSmartPointer<vtkPolyData>::New();
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetNumberOfPoints(4 * static_cast<vtkIdType>(entries.size()));
  auto quads = vtkSmartPointer<vtkCellArray>::New();
  auto rgb = vtkSmartPointer<vtkUnsignedCharArray>::New();
  rgb->SetNumberOfComponents(3);
  for (size_t k = 0; k < entries.size(); ++k) {
    const vtkIdType first = 4 * static_cast<vtkIdType>(k);
    const vtkIdType ids[4] = {first, first + 1, first + 2, first + 3};
    quads->InsertNextCell(4, ids);
    const Rgb& c = entries[k].colour;
    rgb->InsertNextTuple3(std::lround(255 * c[0]), std::lround(255 * c[1]),
                          std::lround(255 * c[2]));
    auto label = vtkSmartPointer<vtkTextActor>::New();
    label->SetInput(entries[k].label.c_str());
    label->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
    label->GetTextProperty()->SetVerticalJustificationToCentered();
    l.labels_.push_back(label);
  }
  l.squares_->SetPoints(points);
  l.squares_->SetPolys(quads);
  l.squares_->GetCellData()->SetScalars(rgb);
  auto coordinate = vtkSmartPointer<vtkCoordinate>::New();
  coordinate->SetCoordinateSystemToNormalizedViewport();
  auto mapper = vtkSmartPointer<vtkPolyDataMapper2D>::New();
  mapper->SetInputData(l.squares_);
  mapper->SetTransformCoordinate(coordinate);
  mapper->SetColorModeToDirectScalars();
  mapper->SetScalarModeToUseCellData();
  l.squares_actor_ = vtkSmartPointer<vtkActor2D>::New();
  l.squares_actor_->SetMapper(mapper);
  return l;
}

void Legend::add_to(vtkRenderer* renderer) const {
  if (bar_) renderer->AddActor2D(bar_);
  if (title_) renderer->AddActor2D(title_);
  if (squares_actor_) renderer->AddActor2D(squares_actor_);
  for (vtkTextActor* label : labels_) renderer->AddActor2D(label);
}

void Legend::remove_from(vtkRenderer* renderer) const {
  if (bar_) renderer->RemoveActor2D(bar_);
  if (title_) renderer->RemoveActor2D(title_);
  if (squares_actor_) renderer->RemoveActor2D(squares_actor_);
  for (vtkTextActor* label : labels_) renderer->RemoveActor2D(label);
}

void Legend::set_visible(bool visible) const {
  if (bar_) bar_->SetVisibility(visible);
  if (title_) title_->SetVisibility(visible);
  if (squares_actor_) squares_actor_->SetVisibility(visible);
  for (vtkTextActor* label : labels_) label->SetVisibility(visible);
}

bool Legend::visible() const {
  return bar_ ? bar_->GetVisibility() : title_->GetVisibility();
}

double Legend::height_pixels(int font) const {
  if (bar_) return 12.0 * font;
  return 1.6 * font + 1.3 * font * static_cast<double>(labels_.size());
}

void Legend::place(double top, int viewport_width, int viewport_height, int font) const {
  const double h = height_pixels(font) / viewport_height;
  const int label_font = std::max(6, static_cast<int>(std::lround(kLabelScale * font)));
  if (bar_) {
    style_text(bar_->GetTitleTextProperty(), font, true);
    style_text(bar_->GetLabelTextProperty(), label_font);
    bar_->GetPositionCoordinate()->SetValue(kLegendColumnLeft, top - h);
    bar_->GetPosition2Coordinate()->SetValue(kColumnWidth, h);
    return;
  }
  style_text(title_->GetTextProperty(), font, true);
  title_->SetPosition(kLegendColumnLeft + 0.005, top);
  // Rows 1.3 em high under the title: a square of 0.8 em, then the label.
  const double row = 1.3 * font / viewport_height;
  const double side_x = 0.8 * font / viewport_width, side_y = 0.8 * font / viewport_height;
  const double x0 = kLegendColumnLeft + 0.008;
  vtkPoints* points = squares_->GetPoints();
  for (size_t k = 0; k < labels_.size(); ++k) {
    const double y = top - 1.6 * font / viewport_height -
                     (static_cast<double>(k) + 0.5) * row;  // the row's middle
    const vtkIdType first = 4 * static_cast<vtkIdType>(k);
    points->SetPoint(first, x0, y - side_y / 2, 0);
    points->SetPoint(first + 1, x0 + side_x, y - side_y / 2, 0);
    points->SetPoint(first + 2, x0 + side_x, y + side_y / 2, 0);
    points->SetPoint(first + 3, x0, y + side_y / 2, 0);
    style_text(labels_[k]->GetTextProperty(), label_font);
    labels_[k]->SetPosition(x0 + 1.5 * side_x, y);
  }
  points->Modified();
}

double Legend::title_width_pixels(int font) const {
  const char* text = bar_ ? bar_->GetTitle() : title_->GetInput();
  return 0.62 * font * (text ? std::strlen(text) : 0);
}

double Legend::entry_width_pixels(int font) const {
  size_t longest = 0;
  for (vtkTextActor* label : labels_) longest = std::max(longest, std::strlen(label->GetInput()));
  // The square and the gap after it (1.2 em), then the label.
  return labels_.empty() ? 0.0
                         : 1.2 * font + 0.55 * static_cast<double>(longest) * kLabelScale * font;
}

std::vector<LegendEntry> crease_legend_entries(const CreaseStitching& stitching) {
  std::vector<LegendEntry> entries = {{"mountain", fold_colour(Fold::kMountain)},
                                      {"valley", fold_colour(Fold::kValley)},
                                      {"flat", fold_colour(Fold::kFlat)},
                                      {"unassigned", fold_colour(Fold::kUnassigned)}};
  if (stitching.has(CurveKind::kSeam)) entries[2].label = "flat, seam";
  if (stitching.has(CurveKind::kSlit)) entries.push_back({"slit", kSlitColour});
  entries.push_back({"crease point", kCreasePointColour});
  return entries;
}

std::vector<LegendEntry> patch_legend_entries(int patch_count) {
  std::vector<LegendEntry> entries;
  if (patch_count <= kPatchColours) {
    for (int p = 0; p < patch_count; ++p)
      entries.push_back({"patch " + std::to_string(p), patch_colour(p)});
    return entries;
  }
  constexpr int kNamed = 3;  // patch numbers named per colour before "..."
  for (int c = 0; c < kPatchColours; ++c) {
    std::string numbers;
    int named = 0;
    for (int p = c; p < patch_count; p += kPatchColours) {
      if (named == kNamed) {
        numbers += ", ...";
        break;
      }
      numbers += (named ? ", " : "") + std::to_string(p);
      ++named;
    }
    entries.push_back({(named == 1 ? "patch " : "patches ") + numbers, patch_colour(c)});
  }
  return entries;
}

void stack_legends(const std::vector<const Legend*>& legends, int viewport_width,
                   int viewport_height, int font) {
  double total = 0, widest = 0;
  for (const Legend* l : legends)
    if (l->visible()) {
      total += l->height_pixels(font) + 0.8 * font;
      widest = std::max({widest, l->title_width_pixels(font), l->entry_width_pixels(font)});
    }
  const double room = (kTop - 0.02) * viewport_height, column = kColumnWidth * viewport_width;
  const double scale =
      std::min({1.0, total > 0 ? room / total : 1.0, widest > 0 ? column / widest : 1.0});
  const int f = scale < 1 ? std::max(6, static_cast<int>(font * scale)) : font;
  double top = kTop;
  for (const Legend* l : legends) {
    if (!l->visible()) continue;
    l->place(top, viewport_width, viewport_height, f);
    top -= (l->height_pixels(f) + 0.8 * f) / viewport_height;
  }
}

}  // namespace sdog::vis
