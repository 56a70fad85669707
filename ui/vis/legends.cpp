#include "ui/vis/legends.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkUnsignedCharArray.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkTextProperty.h>

#include <algorithm>
#include <cmath>
#include <cstring>

namespace sdog::vis {
namespace {

constexpr double kColumnWidth = 0.99 - kLegendColumnLeft;
constexpr double kTop = 0.97;

void style_text(vtkTextProperty* p, int font, bool bold = false) {
  p->SetColor(kTextColor[0], kTextColor[1], kTextColor[2]);
  p->SetFontSize(font);
  p->SetBold(bold);
  p->SetItalic(false);
  p->SetShadow(false);
}

// A square symbol carrying its colour as cell scalars: the legend box then draws the label in
// the entry colour (the text colour) and the square in its own.
vtkSmartPointer<vtkPolyData> colored_square(const Rgb& c) {
  auto square = vtkSmartPointer<vtkPolyData>::New();
  auto pts = vtkSmartPointer<vtkPoints>::New();
  for (const auto& [x, y] : {std::pair{0, 0}, {1, 0}, {1, 1}, {0, 1}}) pts->InsertNextPoint(x, y, 0);
  auto polys = vtkSmartPointer<vtkCellArray>::New();
  const vtkIdType ids[4] = {0, 1, 2, 3};
  polys->InsertNextCell(4, ids);
  square->SetPoints(pts);
  square->SetPolys(polys);
  auto rgb = vtkSmartPointer<vtkUnsignedCharArray>::New();
  rgb->SetNumberOfComponents(3);
  rgb->InsertNextTuple3(std::lround(255 * c[0]), std::lround(255 * c[1]), std::lround(255 * c[2]));
  square->GetCellData()->SetScalars(rgb);
  return square;
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
  l.box_ = vtkSmartPointer<vtkLegendBoxActor>::New();
  l.box_->SetNumberOfEntries(static_cast<int>(entries.size()));
  for (size_t k = 0; k < entries.size(); ++k) {
    double text[3] = {kTextColor[0], kTextColor[1], kTextColor[2]};
    // The box draws the symbol over the start of its label: a leading space keeps the letter free.
    const std::string label = " " + entries[k].label;
    l.box_->SetEntry(static_cast<int>(k), colored_square(entries[k].color), label.c_str(), text);
  }
  l.box_->ScalarVisibilityOn();
  l.box_->BorderOff();
  l.box_->SetPadding(1);
  l.box_->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
  l.box_->GetPosition2Coordinate()->SetCoordinateSystemToNormalizedViewport();
  l.entries_ = static_cast<int>(entries.size());
  return l;
}

void Legend::add_to(vtkRenderer* renderer) const {
  if (bar_) renderer->AddActor2D(bar_);
  if (title_) renderer->AddActor2D(title_);
  if (box_) renderer->AddActor2D(box_);
}

void Legend::remove_from(vtkRenderer* renderer) const {
  if (bar_) renderer->RemoveActor2D(bar_);
  if (title_) renderer->RemoveActor2D(title_);
  if (box_) renderer->RemoveActor2D(box_);
}

void Legend::set_visible(bool visible) const {
  if (bar_) bar_->SetVisibility(visible);
  if (title_) title_->SetVisibility(visible);
  if (box_) box_->SetVisibility(visible);
}

bool Legend::visible() const { return bar_ ? bar_->GetVisibility() : box_->GetVisibility(); }

double Legend::height_pixels(int font) const {
  if (bar_) return 12.0 * font;
  return 1.6 * font + 1.3 * font * entries_;
}

void Legend::place(double top, int viewport_height, int font) const {
  const double h = height_pixels(font) / viewport_height;
  if (bar_) {
    style_text(bar_->GetTitleTextProperty(), font, true);
    style_text(bar_->GetLabelTextProperty(), static_cast<int>(0.85 * font));
    bar_->GetPositionCoordinate()->SetValue(kLegendColumnLeft, top - h);
    bar_->GetPosition2Coordinate()->SetValue(kColumnWidth, h);
    return;
  }
  style_text(title_->GetTextProperty(), font, true);
  title_->SetPosition(kLegendColumnLeft + 0.005, top);
  const double title_h = 1.6 * font / viewport_height;
  style_text(box_->GetEntryTextProperty(), font);
  // The box scales its text to fit; entries 1.3 em high in the whole column width make the height
  // decide (the same text size in every legend) unless a label is long.
  box_->GetPositionCoordinate()->SetValue(kLegendColumnLeft, top - h);
  box_->GetPosition2Coordinate()->SetValue(kColumnWidth, h - title_h);
}

double Legend::title_width_pixels(int font) const {
  const char* text = bar_ ? bar_->GetTitle() : title_->GetInput();
  return 0.62 * font * (text ? std::strlen(text) : 0);
}

void stack_legends(const std::vector<const Legend*>& legends, int viewport_width, int viewport_height, int font) {
  double total = 0, widest = 0;
  for (const Legend* l : legends)
    if (l->visible()) {
      total += l->height_pixels(font) + 0.8 * font;
      widest = std::max(widest, l->title_width_pixels(font));
    }
  const double room = (kTop - 0.02) * viewport_height, column = kColumnWidth * viewport_width;
  const double scale = std::min({1.0, total > 0 ? room / total : 1.0, widest > 0 ? column / widest : 1.0});
  const int f = scale < 1 ? std::max(6, static_cast<int>(font * scale)) : font;
  double top = kTop;
  for (const Legend* l : legends) {
    if (!l->visible()) continue;
    l->place(top, viewport_height, f);
    top -= (l->height_pixels(f) + 0.8 * f) / viewport_height;
  }
}

}  // namespace sdog::vis
