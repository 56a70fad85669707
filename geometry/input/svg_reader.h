#pragma once
// SVG crease-pattern reader: turns the drawing into flattened polylines in sheet units.
//
// Supported elements: <path> (all commands M L H V C S Q T A Z, absolute and relative),
// <polyline>, <polygon>, <line>, <rect> (rx/ry ignored), <circle>, <ellipse>.
// Transforms (matrix, translate, scale, rotate, skewX, skewY) on <g> and on elements compose as
// in SVG. The stroke colour is resolved with SVG precedence: inline style="stroke:..." over CSS
// class rules from <style> (".st0{stroke:#EF4545}") over the stroke="..." attribute, inherited
// from enclosing <g> elements. An element without a stroke uses its fill colour (Illustrator
// exports sometimes do this), and SVG's default fill is black.
// A stroke-dasharray other than "none" marks the curve as dashed, and dash-dot when its dashes
// differ in length; opacity, stroke-opacity and the data-fold and data-angle attributes are
// passed on, as are the names of the enclosing groups (geometry/input/fold_conventions.h reads
// the fold assignment from them).
//
// Coordinates: y points up. A point (x, y) of the SVG user space becomes (x, -y): the SVG y axis
// is negated exactly, so the viewBox "x0 y0 w h" covers [x0, x0+w] x [-(y0+h), -y0].
// Curves (Bézier, arcs, circles, ellipses) are flattened adaptively so that no chord deviates
// from the true curve by more than `flatness * max(viewBox width, height)`.
//
// Details of the contract:
//  - Document order is curve order. Every subpath of a <path> (each M/m, or drawing after Z) is
//    its own SvgCurve; `subpath` counts the curves returned for that element (0, 1, 2, ...).
//    Curves with fewer than 2 distinct points (a lone M, zero-length lines, rect/circle of size
//    0, empty d="") are dropped. Line segments keep exactly their vertices.
//  - End points are exact: a relative command's end point is previous + delta in double and the
//    last flattened point of a segment is that end point itself. Untransformed coordinates are
//    copied bit for bit; -0 is never output (+0 instead).
//  - Not drawn: <defs>, <metadata>, <clipPath>, <mask>, <symbol>, <pattern>, <marker>, <text>,
//    <image> and other non-shape elements, and display="none" (attribute, style or class).
//    <g>, <a>, <switch> (all children) and nested <svg> (x/y only; a viewBox is an error) are
//    walked. <use> is an InputError, as clones must be expanded in the editor.
//  - Colour: each of stroke, fill, stroke-dasharray and color resolves as inline style > class
//    rule (the later rule of the style sheets wins, whatever the order in class="...") >
//    presentation attribute on the element itself, else ("inherit" too) the parent's value.
//    The curve colour is the stroke if it is a colour; else the fill if it is a colour; else
//    black. "none"/"transparent" are not colours; "currentColor" takes `color` (default black);
//    "url(#id) fallback" takes the fallback, a bare url() is an error, as is an unknown colour.
//    Only single-class selectors (".a", ".a, .b") of <style> elements anywhere in the file count.
//  - Dashed: the resolved stroke-dasharray is set, not "none" and not all zeros.
//  - viewBox "min-x min-y width height" (white space and/or commas). Without it, width and
//    height of the root (px or mm/cm/in/pt/pc at 96 dpi) give "0 0 width height"; otherwise
//    has_viewbox is false. A zero or negative size is accepted (reported by later stages).
//    The root's viewBox-to-viewport scaling is not applied: coordinates are user units.
//    A transform attribute on the root is applied like one on a <g> (SVG 2).
//  - Tolerance tol = flatness * max(viewBox width, height); without a (positive) viewBox,
//    flatness * the larger side of the box of all control points (1 if that is 0). Elements
//    with transform T are flattened in their own space with tol / σmax(T), σmax being the
//    largest singular value of T's linear part, and then transformed.
//  - At most 5 million flattened points in total ("too many points after flattening").
//  - Errors are one line: "FILE:LINE: <TAG id="ID">: what is wrong", e.g.
//    "pattern.svg:12: <path id="c3">: path data: expected a number after 'C' at character 27
//    ("M 0 0 C 10 …")", "FILE:LINE: not an XML file: <reason> at byte N",
//    "FILE: the root element is <html>, expected <svg>", "FILE: cannot open file (<strerror>)".
//    NaN, infinite or overflowing numbers, also after relative sums and transforms, give
//    "coordinate is not a finite number". A flatness that is not positive is a UsageError.
#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "geometry/pattern/plane_geometry.h"

namespace sdog {

struct SvgCurve {
  std::vector<Eigen::Vector2d> points;  ///< flattened, y up; consecutive duplicates removed
  bool closed = false;       ///< closed by Z, or a polygon/rect/circle/ellipse (last != first)
  std::string colour;        ///< resolved stroke (or fill) colour as "#rrggbb" in lower case
  bool is_boundary = false;  ///< colour is exactly black (#000000)
  bool dashed = false;       ///< stroke-dasharray set and not "none"
  /// Dashed, with dashes of different lengths (the longest at least twice the shortest).
  bool dash_dot = false;
  /// opacity (the product over the element and its groups) times stroke-opacity (inherited);
  /// unset when neither is given anywhere.
  std::optional<double> opacity;
  /// data-fold and data-angle of the element or its nearest group that has them.
  std::optional<std::string> data_fold, data_angle;
  /// The names of the enclosing groups (<g>, <a>, <switch>, nested <svg>), outermost first: a
  /// group's inkscape:label, else its id; groups with neither are left out.
  std::vector<std::string> groups;
  std::string element;  ///< tag name, e.g. "path"
  std::string id;       ///< the element's id attribute, or empty
  int line = 0;         ///< line of the element in the file (1-based), 0 if unknown
  int subpath = 0;      ///< index of the subpath inside a <path> (each M starts a new one)
};

struct SvgDrawing {
  std::string source;  ///< file name used in messages
  bool has_viewbox = false;
  Box2 viewbox;                  ///< in y-up coordinates (see above)
  std::vector<SvgCurve> curves;  ///< document order
};

struct SvgReadOptions {
  /// Maximal chord deviation of flattened curves, relative to max(viewBox width, height).
  double flatness = 1e-5;
};

/// Reads and flattens an SVG file. Throws InputError ("FILE:LINE: <path id="c1">: path data:
/// expected a number after 'L' at character 17") for a missing/unreadable file, malformed XML, a
/// root that is not <svg>, a bad viewBox, path-data syntax errors, bad numbers and NaN or
/// infinite coordinates (also after transforms).
SvgDrawing read_svg_file(const std::string& path, const SvgReadOptions& options = {});

/// Same as read_svg_file, from text already in memory; `source` names it in messages.
SvgDrawing parse_svg(const std::string& text, const std::string& source,
                     const SvgReadOptions& options = {});

}  // namespace sdog
