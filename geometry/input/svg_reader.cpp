#include "geometry/input/svg_reader.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <pugixml.hpp>

#include "base/errors.h"
#include "base/text_file.h"
#include "geometry/input/internal/svg_flatten.h"
#include "geometry/input/internal/svg_path_data.h"
#include "geometry/input/internal/svg_style.h"

namespace sdog {

namespace {

using svg::Affine;
using svg::ElementError;
using svg::PathSegment;
using svg::PathSubpath;
using svg::Point;
using svg::SegmentKind;

/// Guards memory and time against pathological drawings (tiny flatness, huge curves).
constexpr std::size_t kMaxTotalPoints = 5'000'000;
/// The element walk recurses; deeper nesting than any editor produces is refused.
constexpr int kMaxNesting = 256;

/// Properties resolved with precedence and inheritance (see svg_reader.h).
struct InheritedStyle {
  std::optional<std::string> stroke, fill, dasharray, colour, stroke_opacity, data_fold, data_angle;
  std::optional<double> opacity;    ///< product of the opacity of the element and its groups
  Affine ctm;                       ///< maps the element's user space to the root's
  std::vector<std::string> groups;  ///< names of the enclosing groups, outermost first
};

/// An element's geometry before flattening, in its own user space.
struct Shape {
  SvgCurve meta;      ///< everything but the points
  std::string where;  ///< "FILE:LINE: <path id=\"x\">" for messages
  Affine ctm;
  std::vector<PathSubpath> subpaths;  ///< all elements but circles and ellipses
  bool is_ellipse = false;
  Point center = Point::Zero();
  double rx = 0, ry = 0;
};

std::string local_name(const pugi::xml_node& node) {
  std::string name = node.name();
  if (name.compare(0, 4, "svg:") == 0) name.erase(0, 4);
  return name;
}

bool is_shape(const std::string& name) {
  return name == "path" || name == "polyline" || name == "polygon" || name == "line" ||
         name == "rect" || name == "circle" || name == "ellipse";
}

bool is_container(const std::string& name) {
  return name == "g" || name == "a" || name == "switch" || name == "svg";
}

/// Messages are one line even when they quote CSS text or ids containing line breaks.
std::string one_line(std::string message) {
  for (char& c : message)
    if (static_cast<unsigned char>(c) < 0x20) c = ' ';
  return message;
}

bool finite(const Point& p) {
  return std::isfinite(p.x()) && std::isfinite(p.y());
}

/// The dash lengths of a dash array (repeated to an even count, as SVG does) at even positions;
/// empty for "none", an unparsable value or one whose values are all zero (renders solid).
/// An unparsable value other than "none" gives {1}: dashed.
std::vector<double> dash_lengths(const std::optional<std::string>& dasharray) {
  if (!dasharray) return {};
  const std::string_view value = svg::trim(*dasharray);
  if (value.empty() || svg::to_lower(value) == "none") return {};
  std::vector<double> values;
  std::size_t pos = 0;
  while (pos < value.size()) {
    double v = 0;
    if (svg::scan_number(value, pos, v) != svg::NumberScan::kOk) return {1};
    values.push_back(std::abs(v));
    while (pos < value.size() && ((value[pos] >= 'a' && value[pos] <= 'z') || value[pos] == '%'))
      ++pos;  // unit
    svg::skip_comma_wsp(value, pos);
  }
  if (std::all_of(values.begin(), values.end(), [](double v) { return v == 0; })) return {};
  if (values.size() % 2 == 1) values.insert(values.end(), values.begin(), values.end());
  std::vector<double> dashes;
  for (std::size_t k = 0; k < values.size(); k += 2) dashes.push_back(values[k]);
  return dashes;
}

/// Dash-dot: the longest dash is at least twice the shortest (a dot may have length 0).
bool is_dash_dot(const std::vector<double>& dashes) {
  if (dashes.size() < 2) return false;
  const auto [shortest, longest] = std::minmax_element(dashes.begin(), dashes.end());
  return *longest >= 2 * *shortest && *longest > 0;
}

void add_line_subpath(std::vector<PathSubpath>& subpaths, const std::vector<Point>& points,
                      bool closed) {
  if (points.empty()) return;
  PathSubpath subpath;
  subpath.start = points.front();
  subpath.closed = closed;
  for (std::size_t i = 1; i < points.size(); ++i) {
    PathSegment segment;
    segment.from = points[i - 1];
    segment.to = points[i];
    subpath.segments.push_back(segment);
  }
  subpaths.push_back(std::move(subpath));
}

class Reader {
 public:
  Reader(const std::string& text, const std::string& source, const SvgReadOptions& options)
      : text_(text), source_(source), options_(options) {
    for (std::size_t i = 0; i < text.size(); ++i)
      if (text[i] == '\n') newlines_.push_back(i);
  }

  SvgDrawing read() {
    if (!(options_.flatness > 0) || !std::isfinite(options_.flatness))
      throw UsageError("flatness must be a positive finite number (got " +
                       std::to_string(options_.flatness) + ")");
    pugi::xml_document document;
    const pugi::xml_parse_result parsed =
        document.load_buffer(text_.data(), text_.size(), pugi::parse_default);
    if (!parsed) {
      throw InputError(source_ + ":" + std::to_string(line_of(parsed.offset)) +
                       ": not an XML file: " + parsed.description() + " at byte " +
                       std::to_string(parsed.offset));
    }
    const pugi::xml_node root = document.document_element();
    if (local_name(root) != "svg")
      throw InputError(source_ + ": the root element is <" + std::string(root.name()) +
                       ">, expected <svg>");

    SvgDrawing drawing;
    drawing.source = source_;
    read_viewbox(root, drawing);
    collect_stylesheets(document);

    InheritedStyle style;
    if (!apply_element_style(root, style)) return drawing;  // display:none on the root
    walk(root, style, 0);

    flatten_all(drawing);
    return drawing;
  }

 private:
  int line_of(std::ptrdiff_t offset) const {
    if (offset < 0) return 0;
    return 1 + static_cast<int>(std::lower_bound(newlines_.begin(), newlines_.end(),
                                                 static_cast<std::size_t>(offset)) -
                                newlines_.begin());
  }

  std::string where(const pugi::xml_node& node) const {
    std::string out = source_;
    const int line = line_of(node.offset_debug());
    if (line > 0) out += ":" + std::to_string(line);
    out += ": <" + local_name(node);
    const pugi::xml_attribute id = node.attribute("id");
    if (id) out += " id=\"" + std::string(id.value()) + "\"";
    return out + ">";
  }

  [[noreturn]] void fail(const pugi::xml_node& node, const std::string& what) const {
    throw InputError(one_line(where(node) + ": " + what));
  }

  /// Runs `parse`, turning its ElementError into an InputError naming the element and `what`.
  template <class Parse>
  auto guarded(const pugi::xml_node& node, const std::string& what, Parse&& parse) const {
    try {
      return parse();
    } catch (const ElementError& error) {
      fail(node, what + ": " + error.what());
    }
  }

  void read_viewbox(const pugi::xml_node& root, SvgDrawing& drawing) const {
    double x = 0, y = 0, w = 0, h = 0;
    const pugi::xml_attribute viewbox = root.attribute("viewBox");
    if (viewbox && !svg::trim(viewbox.value()).empty()) {
      const std::vector<double> v =
          guarded(root, "viewBox", [&] { return svg::parse_number_list(viewbox.value()); });
      if (v.size() != 4)
        fail(root, "viewBox: expected 4 numbers \"min-x min-y width height\", found " +
                       std::to_string(v.size()));
      x = v[0], y = v[1], w = v[2], h = v[3];
    } else {
      const std::optional<double> width = root_length(root, "width");
      const std::optional<double> height = root_length(root, "height");
      if (!width || !height) return;
      w = *width, h = *height;
    }
    // -v + 0.0 turns -0 into +0 and is exact otherwise.
    drawing.has_viewbox = true;
    drawing.viewbox.xmin = x;
    drawing.viewbox.xmax = x + w;
    drawing.viewbox.ymin = -(y + h) + 0.0;
    drawing.viewbox.ymax = -y + 0.0;
    if (!std::isfinite(drawing.viewbox.xmax) || !std::isfinite(drawing.viewbox.ymin))
      fail(root, "viewBox: coordinate is not a finite number (min + size overflows)");
  }

  /// width/height of the root; percentages (a share of an unknown viewport) and "auto" count as
  /// absent.
  std::optional<double> root_length(const pugi::xml_node& root, const char* name) const {
    const pugi::xml_attribute attribute = root.attribute(name);
    if (!attribute) return std::nullopt;
    const std::string_view value = svg::trim(attribute.value());
    if (value.empty() || value.back() == '%' || svg::to_lower(value) == "auto") return std::nullopt;
    return guarded(root, name, [&] { return svg::parse_length(value); });
  }

  void collect_stylesheets(const pugi::xml_document& document) {
    struct Collector : pugi::xml_tree_walker {
      svg::Stylesheet* sheet;
      bool for_each(pugi::xml_node& node) override {
        if (node.type() != pugi::node_element || local_name(node) != "style") return true;
        std::string css;
        for (pugi::xml_node child = node.first_child(); child; child = child.next_sibling())
          if (child.type() == pugi::node_pcdata || child.type() == pugi::node_cdata)
            css += child.value();
        sheet->add(css);
        return true;
      }
    } collector;
    collector.sheet = &stylesheet_;
    const_cast<pugi::xml_document&>(document).traverse(collector);
  }

  /// Resolves the element's own style (inline style > class rules > attributes) into `style`,
  /// which holds the parent's values on entry, and composes its transform.
  /// Returns false for display:none.
  bool apply_element_style(const pugi::xml_node& node, InheritedStyle& style) const {
    static const char* const kProperties[] = {
        "stroke", "fill", "stroke-dasharray", "color", "display", "stroke-opacity", "opacity"};
    std::map<std::string, std::string> own;
    for (const char* name : kProperties)
      if (const pugi::xml_attribute attribute = node.attribute(name)) own[name] = attribute.value();
    if (const pugi::xml_attribute classes = node.attribute("class"))
      stylesheet_.apply(classes.value(), own);
    if (const pugi::xml_attribute inline_style = node.attribute("style"))
      for (auto& [name, value] : svg::parse_declarations(inline_style.value())) own[name] = value;

    auto inherit = [&](const char* name, std::optional<std::string>& slot) {
      const auto it = own.find(name);
      if (it == own.end()) return;
      const std::string value(svg::trim(it->second));
      if (svg::to_lower(value) == "inherit") return;
      slot = value;
    };
    const auto display = own.find("display");
    if (display != own.end() && svg::to_lower(svg::trim(display->second)) == "none") return false;
    inherit("stroke", style.stroke);
    inherit("fill", style.fill);
    inherit("stroke-dasharray", style.dasharray);
    inherit("color", style.colour);
    inherit("stroke-opacity", style.stroke_opacity);
    const auto opacity = own.find("opacity");
    if (opacity != own.end()) {
      const double value =
          guarded(node, "opacity", [&] { return svg::parse_opacity(opacity->second); });
      style.opacity = style.opacity.value_or(1.0) * value;
    }
    for (auto [name, slot] :
         {std::pair{"data-fold", &style.data_fold}, std::pair{"data-angle", &style.data_angle}})
      if (const pugi::xml_attribute attribute = node.attribute(name)) *slot = attribute.value();

    if (const pugi::xml_attribute transform = node.attribute("transform")) {
      const Affine local =
          guarded(node, "transform", [&] { return svg::parse_transform(transform.value()); });
      style.ctm = style.ctm * local;
      if (!style.ctm.is_finite())
        fail(node, "transform: the transform is not finite (a skew of 90 degrees or an overflow)");
    }
    return true;
  }

  void walk(const pugi::xml_node& parent, const InheritedStyle& inherited, int depth) {
    for (pugi::xml_node child = parent.first_child(); child; child = child.next_sibling()) {
      if (child.type() != pugi::node_element) continue;
      const std::string name = local_name(child);
      const bool container = is_container(name);
      // Everything else (defs, metadata, clipPath, mask, symbol, pattern, marker, style, text,
      // image, ...) draws nothing that belongs to the crease pattern or is not drawn at all.
      if (!container && !is_shape(name) && name != "use") continue;
      InheritedStyle style = inherited;
      if (!apply_element_style(child, style)) continue;
      if (name == "use") fail(child, "<use> is not supported; ungroup/expand it in your editor");
      if (container) {
        if (depth >= kMaxNesting)
          fail(child,
               "elements are nested more than " + std::to_string(kMaxNesting) + " levels deep");
        if (name == "svg") enter_nested_svg(child, style);
        if (const std::string group = group_name(child); !group.empty())
          style.groups.push_back(group);
        walk(child, style, depth + 1);
      } else {
        add_shape(child, name, style);
      }
    }
  }

  /// A group's name as editors show it: Inkscape's layer label, else its id.
  static std::string group_name(const pugi::xml_node& node) {
    if (const pugi::xml_attribute label = node.attribute("inkscape:label")) return label.value();
    return node.attribute("id").value();
  }

  /// A nested <svg> only translates by (x, y); its own viewport scaling is not supported.
  void enter_nested_svg(const pugi::xml_node& node, InheritedStyle& style) const {
    if (node.attribute("viewBox"))
      fail(node, "a nested <svg> with a viewBox is not supported; ungroup it in your editor");
    const double x = length(node, "x", 0), y = length(node, "y", 0);
    style.ctm = style.ctm * Affine{1, 0, 0, 1, x, y};
  }

  double length(const pugi::xml_node& node, const char* name, double fallback) const {
    const pugi::xml_attribute attribute = node.attribute(name);
    if (!attribute) return fallback;
    return guarded(node, name, [&] { return svg::parse_length(attribute.value()); });
  }

  std::string resolve_colour(const pugi::xml_node& node, const InheritedStyle& style) const {
    auto colour_property = [&] {
      if (!style.colour) return std::string("#000000");
      return guarded(node, "color", [&] { return svg::parse_colour(*style.colour); });
    };
    if (style.stroke) {
      const svg::Paint stroke =
          guarded(node, "stroke", [&] { return svg::parse_paint(*style.stroke); });
      if (stroke.kind == svg::Paint::Kind::kColour) return stroke.colour;
      if (stroke.kind == svg::Paint::Kind::kCurrentColour) return colour_property();
    }
    if (style.fill) {
      const svg::Paint fill = guarded(node, "fill", [&] { return svg::parse_paint(*style.fill); });
      if (fill.kind == svg::Paint::Kind::kColour) return fill.colour;
      if (fill.kind == svg::Paint::Kind::kCurrentColour) return colour_property();
    }
    return "#000000";  // SVG's initial fill; also what an unpainted line is taken to be
  }

  void add_shape(const pugi::xml_node& node, const std::string& name, const InheritedStyle& style) {
    Shape shape;
    shape.where = one_line(where(node));
    shape.ctm = style.ctm;
    shape.meta.element = name;
    shape.meta.id = node.attribute("id").value();
    shape.meta.line = line_of(node.offset_debug());
    shape.meta.colour = resolve_colour(node, style);
    shape.meta.is_boundary = shape.meta.colour == "#000000";
    const std::vector<double> dashes = dash_lengths(style.dasharray);
    shape.meta.dashed = !dashes.empty();
    shape.meta.dash_dot = is_dash_dot(dashes);
    if (style.opacity || style.stroke_opacity) {
      const double stroke_opacity =
          style.stroke_opacity ? guarded(node, "stroke-opacity",
                                         [&] { return svg::parse_opacity(*style.stroke_opacity); })
                               : 1.0;
      shape.meta.opacity = style.opacity.value_or(1.0) * stroke_opacity;
    }
    shape.meta.data_fold = style.data_fold;
    shape.meta.data_angle = style.data_angle;
    shape.meta.groups = style.groups;

    if (name == "path") {
      const char* d = node.attribute("d").value();
      shape.subpaths = guarded(node, "path data", [&] { return svg::parse_path_data(d); });
    } else if (name == "polyline" || name == "polygon") {
      const char* text = node.attribute("points").value();
      const std::vector<Point> points =
          guarded(node, "points", [&] { return svg::parse_points(text); });
      add_line_subpath(shape.subpaths, points, name == "polygon");
    } else if (name == "line") {
      add_line_subpath(shape.subpaths,
                       {Point(length(node, "x1", 0), length(node, "y1", 0)),
                        Point(length(node, "x2", 0), length(node, "y2", 0))},
                       false);
    } else if (name == "rect") {
      const double x = length(node, "x", 0), y = length(node, "y", 0);
      const double w = length(node, "width", 0), h = length(node, "height", 0);
      if (w < 0 || h < 0) fail(node, "negative width or height");
      if (w == 0 || h == 0) return;  // SVG: disables rendering
      const Point corner(x + w, y + h);
      if (!finite(corner)) fail(node, "coordinate is not a finite number (x + width overflows)");
      add_line_subpath(shape.subpaths,
                       {Point(x, y), Point(corner.x(), y), corner, Point(x, corner.y())}, true);
    } else {  // circle, ellipse
      shape.is_ellipse = true;
      shape.meta.closed = true;
      shape.center = Point(length(node, "cx", 0), length(node, "cy", 0));
      if (name == "circle") {
        shape.rx = shape.ry = length(node, "r", 0);
      } else {
        // SVG 2: a missing radius is "auto", i.e. the other one.
        const bool has_rx = node.attribute("rx"), has_ry = node.attribute("ry");
        shape.rx = length(node, "rx", 0);
        shape.ry = length(node, "ry", 0);
        if (has_rx && !has_ry) shape.ry = shape.rx;
        if (has_ry && !has_rx) shape.rx = shape.ry;
      }
      if (shape.rx < 0 || shape.ry < 0) fail(node, "negative radius");
      if (shape.rx == 0 || shape.ry == 0) return;  // SVG: disables rendering
    }
    shapes_.push_back(std::move(shape));
  }

  /// Box of all control points in root coordinates, for the tolerance without a viewBox.
  double control_point_extent() const {
    Eigen::AlignedBox2d box;
    for (const Shape& shape : shapes_) {
      auto add = [&](const Point& p) {
        const Point q = shape.ctm.apply(p);
        if (finite(q)) box.extend(q);
      };
      if (shape.is_ellipse) {
        for (const Point& offset :
             {Point(shape.rx, 0), Point(-shape.rx, 0), Point(0, shape.ry), Point(0, -shape.ry)})
          add(shape.center + offset);
        continue;
      }
      for (const PathSubpath& subpath : shape.subpaths) {
        add(subpath.start);
        for (const PathSegment& segment : subpath.segments) {
          add(segment.to);
          if (segment.kind == SegmentKind::kQuadratic || segment.kind == SegmentKind::kCubic)
            add(segment.c1);
          if (segment.kind == SegmentKind::kCubic) add(segment.c2);
          if (segment.kind == SegmentKind::kArc) {
            svg::ArcCenter arc;
            try {
              if (!svg::arc_center(segment.from, segment.rx, segment.ry, segment.rotation_deg,
                                   segment.large_arc, segment.sweep, segment.to, arc))
                continue;
            } catch (const ElementError&) {
              continue;  // reported with the element when flattening
            }
            const double r = std::max(arc.rx, arc.ry);
            for (const Point& offset : {Point(r, 0), Point(-r, 0), Point(0, r), Point(0, -r)})
              add(arc.center + offset);
          }
        }
      }
    }
    if (box.isEmpty()) return 0;
    return box.sizes().maxCoeff();
  }

  double tolerance(const SvgDrawing& drawing) const {
    if (drawing.has_viewbox) {
      const double size = std::max(drawing.viewbox.width(), drawing.viewbox.height());
      if (size > 0) return options_.flatness * size;
    }
    double extent = control_point_extent();
    if (!(extent > 0) || !std::isfinite(extent)) extent = 1;
    return options_.flatness * extent;
  }

  void flatten_all(SvgDrawing& drawing) {
    const double tol = tolerance(drawing);
    std::size_t total = 0;
    for (const Shape& shape : shapes_) {
      const double stretch = shape.ctm.max_stretch();
      const double local_tol = stretch > 0 && std::isfinite(stretch) ? tol / stretch : tol;
      int subpath_index = 0;
      auto emit = [&](std::vector<Point>& local, bool closed) {
        SvgCurve curve = shape.meta;
        curve.closed = closed;
        curve.subpath = subpath_index;
        curve.points.reserve(local.size());
        for (const Point& p : local) {
          const Point q = shape.ctm.apply(p);
          if (!finite(q))
            throw InputError(shape.where +
                             ": coordinate is not a finite number after applying the transform");
          const Point up(q.x(), -q.y() + 0.0);  // y up; + 0.0 avoids -0
          if (curve.points.empty() || curve.points.back() != up) curve.points.push_back(up);
        }
        if (closed)
          while (curve.points.size() > 1 && curve.points.back() == curve.points.front())
            curve.points.pop_back();
        if (curve.points.size() < 2) return;  // a lone moveto or a zero-length subpath
        total += curve.points.size();
        drawing.curves.push_back(std::move(curve));
        ++subpath_index;
      };
      try {
        std::vector<Point> local;
        if (shape.is_ellipse) {
          svg::PointSink sink(local, kMaxTotalPoints - total);
          svg::flatten_ellipse(shape.center, shape.rx, shape.ry, local_tol, sink);
          emit(local, true);
          continue;
        }
        for (const PathSubpath& subpath : shape.subpaths) {
          local.clear();
          svg::PointSink sink(local, kMaxTotalPoints - total);
          sink.push(subpath.start);
          for (const PathSegment& segment : subpath.segments)
            svg::flatten_segment(segment, local_tol, sink);
          emit(local, subpath.closed);
        }
      } catch (const ElementError& error) {
        throw InputError(one_line(shape.where + ": " + error.what()));
      }
    }
  }

  const std::string& text_;
  const std::string& source_;
  const SvgReadOptions& options_;
  std::vector<std::size_t> newlines_;
  svg::Stylesheet stylesheet_;
  std::vector<Shape> shapes_;
};

}  // namespace

SvgDrawing parse_svg(const std::string& text, const std::string& source,
                     const SvgReadOptions& options) {
  return Reader(text, source, options).read();
}

SvgDrawing read_svg_file(const std::string& path, const SvgReadOptions& options) {
  return parse_svg(read_text_file(path), path, options);
}

}  // namespace sdog
