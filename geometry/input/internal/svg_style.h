#pragma once
// Internal to the SVG reader: values of presentation attributes and CSS.
//  - colours: "#rgb", "#rrggbb" (and "#rgba"/"#rrggbbaa", alpha ignored), the CSS named colours,
//    "rgb(r, g, b)"/"rgba(...)" with numbers 0..255 or percentages (clamped, rounded), also the
//    space-separated CSS 4 form "rgb(255 0 0 / 50%)";
//  - paints: a colour, "none"/"transparent", "currentColor", "url(#id) fallback" (the fallback);
//  - declarations "prop: value; ..." of style="..." and of CSS blocks ("!important" is dropped);
//  - style sheets: rules whose selector is a single class (".st0"), possibly in a list
//    (".a, .b {...}"); other selectors and @-rules are ignored, comments are allowed;
//  - lengths with units (px = user unit; mm, cm, in, pt, pc, Q at 96 dpi);
//  - transform lists (SVG 1.1 7.6).
#include "geometry/input/internal/svg_path_data.h"

#include <map>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace sdog::svg {

/// 2D affine map (x, y) -> (a x + c y + e, b x + d y + f), SVG's matrix(a b c d e f).
struct Affine {
  double a = 1, b = 0, c = 0, d = 1, e = 0, f = 0;

  /// Identity maps return p itself, so untransformed coordinates stay bit-identical.
  Point apply(const Point& p) const;
  bool is_identity() const;
  bool is_finite() const;
  /// Largest singular value of the linear part [a c; b d]: with E = (a+d)/2, F = (a-d)/2,
  /// G = (b+c)/2, H = (b-c)/2 it is hypot(E, H) + hypot(F, G). Lengths grow by at most this.
  double max_stretch() const;
};

/// Composition: (l * r).apply(p) == l.apply(r.apply(p)).
Affine operator*(const Affine& l, const Affine& r);

/// translate(tx [ty]), scale(sx [sy]), rotate(deg [cx cy]), skewX(deg), skewY(deg),
/// matrix(a b c d e f), separated by white space and/or commas; "A B" means A ∘ B.
/// Blank text is the identity. Throws ElementError.
Affine parse_transform(std::string_view text);

/// "#rrggbb" in lower case. Throws ElementError for anything that is not a colour.
std::string parse_colour(std::string_view text);

struct Paint {
  enum class Kind { kNone, kColour, kCurrentColour } kind = Kind::kNone;
  std::string colour;  ///< "#rrggbb" when kind == color
};
Paint parse_paint(std::string_view text);

using Declarations = std::vector<std::pair<std::string, std::string>>;

/// "stroke:#f00; fill : none" -> {{"stroke", "#f00"}, {"fill", "none"}}; property names are
/// lower-cased, values trimmed. Malformed declarations are skipped, as CSS does.
Declarations parse_declarations(std::string_view text);

class Stylesheet {
 public:
  /// Adds the rules of one <style> element; later rules win over earlier ones.
  void add(std::string_view css);
  /// Overwrites `properties` with the declarations of the rules matching any class in
  /// `class_attribute` (white-space separated), in stylesheet order.
  void apply(std::string_view class_attribute,
             std::map<std::string, std::string>& properties) const;
  bool empty() const { return rules_.empty(); }

 private:
  struct Rule {
    std::string class_name;
    Declarations declarations;
  };
  std::vector<Rule> rules_;
};

/// A length in user units: a number with an optional unit (px, mm, cm, in, pt, pc, Q).
/// Throws ElementError for percentages, em/ex and anything else.
double parse_length(std::string_view text);

/// An opacity: a number (clamped to [0, 1]) or a percentage. Throws ElementError otherwise.
double parse_opacity(std::string_view text);

std::string_view trim(std::string_view text);
std::string to_lower(std::string_view text);

}  // namespace sdog::svg
