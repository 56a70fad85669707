#include "geometry/input/internal/svg_style.h"

#include <algorithm>
#include <cmath>
#include <set>

#include "geometry/input/internal/svg_flatten.h"

namespace sdog::svg {

namespace {

struct NamedColour {
  const char* name;
  const char* hex;
};

// CSS Color Module Level 4 named colours.
constexpr NamedColour kNamedColors[] = {
    {"aliceblue", "f0f8ff"},
    {"antiquewhite", "faebd7"},
    {"aqua", "00ffff"},
    {"aquamarine", "7fffd4"},
    {"azure", "f0ffff"},
    {"beige", "f5f5dc"},
    {"bisque", "ffe4c4"},
    {"black", "000000"},
    {"blanchedalmond", "ffebcd"},
    {"blue", "0000ff"},
    {"blueviolet", "8a2be2"},
    {"brown", "a52a2a"},
    {"burlywood", "deb887"},
    {"cadetblue", "5f9ea0"},
    {"chartreuse", "7fff00"},
    {"chocolate", "d2691e"},
    {"coral", "ff7f50"},
    {"cornflowerblue", "6495ed"},
    {"cornsilk", "fff8dc"},
    {"crimson", "dc143c"},
    {"cyan", "00ffff"},
    {"darkblue", "00008b"},
    {"darkcyan", "008b8b"},
    {"darkgoldenrod", "b8860b"},
    {"darkgray", "a9a9a9"},
    {"darkgreen", "006400"},
    {"darkgrey", "a9a9a9"},
    {"darkkhaki", "bdb76b"},
    {"darkmagenta", "8b008b"},
    {"darkolivegreen", "556b2f"},
    {"darkorange", "ff8c00"},
    {"darkorchid", "9932cc"},
    {"darkred", "8b0000"},
    {"darksalmon", "e9967a"},
    {"darkseagreen", "8fbc8f"},
    {"darkslateblue", "483d8b"},
    {"darkslategray", "2f4f4f"},
    {"darkslategrey", "2f4f4f"},
    {"darkturquoise", "00ced1"},
    {"darkviolet", "9400d3"},
    {"deeppink", "ff1493"},
    {"deepskyblue", "00bfff"},
    {"dimgray", "696969"},
    {"dimgrey", "696969"},
    {"dodgerblue", "1e90ff"},
    {"firebrick", "b22222"},
    {"floralwhite", "fffaf0"},
    {"forestgreen", "228b22"},
    {"fuchsia", "ff00ff"},
    {"gainsboro", "dcdcdc"},
    {"ghostwhite", "f8f8ff"},
    {"gold", "ffd700"},
    {"goldenrod", "daa520"},
    {"gray", "808080"},
    {"grey", "808080"},
    {"green", "008000"},
    {"greenyellow", "adff2f"},
    {"honeydew", "f0fff0"},
    {"hotpink", "ff69b4"},
    {"indianred", "cd5c5c"},
    {"indigo", "4b0082"},
    {"ivory", "fffff0"},
    {"khaki", "f0e68c"},
    {"lavender", "e6e6fa"},
    {"lavenderblush", "fff0f5"},
    {"lawngreen", "7cfc00"},
    {"lemonchiffon", "fffacd"},
    {"lightblue", "add8e6"},
    {"lightcoral", "f08080"},
    {"lightcyan", "e0ffff"},
    {"lightgoldenrodyellow", "fafad2"},
    {"lightgray", "d3d3d3"},
    {"lightgreen", "90ee90"},
    {"lightgrey", "d3d3d3"},
    {"lightpink", "ffb6c1"},
    {"lightsalmon", "ffa07a"},
    {"lightseagreen", "20b2aa"},
    {"lightskyblue", "87cefa"},
    {"lightslategray", "778899"},
    {"lightslategrey", "778899"},
    {"lightsteelblue", "b0c4de"},
    {"lightyellow", "ffffe0"},
    {"lime", "00ff00"},
    {"limegreen", "32cd32"},
    {"linen", "faf0e6"},
    {"magenta", "ff00ff"},
    {"maroon", "800000"},
    {"mediumaquamarine", "66cdaa"},
    {"mediumblue", "0000cd"},
    {"mediumorchid", "ba55d3"},
    {"mediumpurple", "9370db"},
    {"mediumseagreen", "3cb371"},
    {"mediumslateblue", "7b68ee"},
    {"mediumspringgreen", "00fa9a"},
    {"mediumturquoise", "48d1cc"},
    {"mediumvioletred", "c71585"},
    {"midnightblue", "191970"},
    {"mintcream", "f5fffa"},
    {"mistyrose", "ffe4e1"},
    {"moccasin", "ffe4b5"},
    {"navajowhite", "ffdead"},
    {"navy", "000080"},
    {"oldlace", "fdf5e6"},
    {"olive", "808000"},
    {"olivedrab", "6b8e23"},
    {"orange", "ffa500"},
    {"orangered", "ff4500"},
    {"orchid", "da70d6"},
    {"palegoldenrod", "eee8aa"},
    {"palegreen", "98fb98"},
    {"paleturquoise", "afeeee"},
    {"palevioletred", "db7093"},
    {"papayawhip", "ffefd5"},
    {"peachpuff", "ffdab9"},
    {"peru", "cd853f"},
    {"pink", "ffc0cb"},
    {"plum", "dda0dd"},
    {"powderblue", "b0e0e6"},
    {"purple", "800080"},
    {"rebeccapurple", "663399"},
    {"red", "ff0000"},
    {"rosybrown", "bc8f8f"},
    {"royalblue", "4169e1"},
    {"saddlebrown", "8b4513"},
    {"salmon", "fa8072"},
    {"sandybrown", "f4a460"},
    {"seagreen", "2e8b57"},
    {"seashell", "fff5ee"},
    {"sienna", "a0522d"},
    {"silver", "c0c0c0"},
    {"skyblue", "87ceeb"},
    {"slateblue", "6a5acd"},
    {"slategray", "708090"},
    {"slategrey", "708090"},
    {"snow", "fffafa"},
    {"springgreen", "00ff7f"},
    {"steelblue", "4682b4"},
    {"tan", "d2b48c"},
    {"teal", "008080"},
    {"thistle", "d8bfd8"},
    {"tomato", "ff6347"},
    {"turquoise", "40e0d0"},
    {"violet", "ee82ee"},
    {"wheat", "f5deb3"},
    {"white", "ffffff"},
    {"whitesmoke", "f5f5f5"},
    {"yellow", "ffff00"},
    {"yellowgreen", "9acd32"},
};

bool is_hex(char c) {
  return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'f') || (c >= 'A' && c <= 'F');
}

bool starts_with(std::string_view text, std::string_view prefix) {
  return text.substr(0, prefix.size()) == prefix;
}

[[noreturn]] void bad_colour(std::string_view text) {
  throw ElementError("unrecognised colour '" + std::string(text) + "'");
}

std::string hex_colour(int r, int g, int b) {
  static const char digits[] = "0123456789abcdef";
  std::string out = "#";
  for (int v : {r, g, b}) {
    out += digits[(v >> 4) & 15];
    out += digits[v & 15];
  }
  return out;
}

/// "rgb(r, g, b)" / "rgba(r, g, b, a)" / "rgb(r g b / a)" with numbers or percentages.
std::string parse_rgb(std::string_view original, std::string_view lowered) {
  const std::size_t open = lowered.find('(');
  if (lowered.back() != ')') bad_colour(original);
  const std::string_view inner = lowered.substr(open + 1, lowered.size() - open - 2);
  std::vector<double> channels;
  std::size_t pos = 0;
  skip_wsp(inner, pos);
  while (pos < inner.size()) {
    double v = 0;
    if (scan_number(inner, pos, v) != NumberScan::kOk) bad_colour(original);
    if (pos < inner.size() && inner[pos] == '%') {
      v = v * 255 / 100;  // not v * 2.55: 50% must give exactly 127.5, rounded to 128
      ++pos;
    }
    channels.push_back(v);
    skip_wsp(inner, pos);
    if (pos < inner.size() && (inner[pos] == ',' || inner[pos] == '/')) {
      ++pos;
      skip_wsp(inner, pos);
      if (pos == inner.size()) bad_colour(original);
    }
  }
  if (channels.size() != 3 && channels.size() != 4) bad_colour(original);
  int rgb[3];
  for (int i = 0; i < 3; ++i)
    rgb[i] = static_cast<int>(std::lround(std::clamp(channels[i], 0.0, 255.0)));
  return hex_colour(rgb[0], rgb[1], rgb[2]);
}

[[noreturn]] void transform_error(const std::string& what, std::string_view text, std::size_t pos) {
  throw ElementError(what + " " + position_note(text, pos));
}

Affine make_transform(std::string_view name, const std::vector<double>& v, std::string_view text,
                      std::size_t pos) {
  auto arity_error = [&](const char* expected) {
    transform_error(
        std::string(name) + " takes " + expected + " numbers, got " + std::to_string(v.size()),
        text, pos);
  };
  Affine t;
  if (name == "matrix") {
    if (v.size() != 6) arity_error("6");
    t = Affine{v[0], v[1], v[2], v[3], v[4], v[5]};
  } else if (name == "translate") {
    if (v.size() != 1 && v.size() != 2) arity_error("1 or 2");
    t.e = v[0];
    t.f = v.size() == 2 ? v[1] : 0.0;
  } else if (name == "scale") {
    if (v.size() != 1 && v.size() != 2) arity_error("1 or 2");
    t.a = v[0];
    t.d = v.size() == 2 ? v[1] : v[0];
  } else if (name == "rotate") {
    if (v.size() != 1 && v.size() != 3) arity_error("1 or 3");
    double c, s;
    cos_sin_degrees(v[0], c, s);
    t = Affine{c, s, -s, c, 0, 0};
    if (v.size() == 3) {
      // translate(cx, cy) rotate(a) translate(-cx, -cy)
      t = Affine{1, 0, 0, 1, v[1], v[2]} * t * Affine{1, 0, 0, 1, -v[1], -v[2]};
    }
  } else if (name == "skewX" || name == "skewY") {
    if (v.size() != 1) arity_error("1");
    double c, s;
    cos_sin_degrees(v[0], c, s);
    const double tangent = s / c;  // skew(90) divides by 0: caught as a non-finite transform
    if (name == "skewX")
      t.c = tangent;
    else
      t.b = tangent;
  } else {
    transform_error("unknown transform '" + std::string(name) +
                        "' (expected matrix, translate, scale, rotate, skewX or skewY)",
                    text, pos);
  }
  return t;
}

}  // namespace

std::string_view trim(std::string_view text) {
  std::size_t begin = 0, end = text.size();
  while (begin < end && is_wsp(text[begin])) ++begin;
  while (end > begin && is_wsp(text[end - 1])) --end;
  return text.substr(begin, end - begin);
}

std::string to_lower(std::string_view text) {
  std::string out(text);
  for (char& c : out)
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
  return out;
}

Point Affine::apply(const Point& p) const {
  if (is_identity()) return p;
  return Point(a * p.x() + c * p.y() + e, b * p.x() + d * p.y() + f);
}

bool Affine::is_identity() const {
  return a == 1 && b == 0 && c == 0 && d == 1 && e == 0 && f == 0;
}

bool Affine::is_finite() const {
  return std::isfinite(a) && std::isfinite(b) && std::isfinite(c) && std::isfinite(d) &&
         std::isfinite(e) && std::isfinite(f);
}

double Affine::max_stretch() const {
  const double E = (a + d) / 2, F = (a - d) / 2, G = (b + c) / 2, H = (b - c) / 2;
  return std::hypot(E, H) + std::hypot(F, G);
}

Affine operator*(const Affine& l, const Affine& r) {
  return Affine{l.a * r.a + l.c * r.b, l.b * r.a + l.d * r.b,       l.a * r.c + l.c * r.d,
                l.b * r.c + l.d * r.d, l.a * r.e + l.c * r.f + l.e, l.b * r.e + l.d * r.f + l.f};
}

Affine parse_transform(std::string_view text) {
  Affine result;
  std::size_t pos = 0;
  skip_wsp(text, pos);
  while (pos < text.size()) {
    const std::size_t name_begin = pos;
    while (pos < text.size() &&
           ((text[pos] >= 'a' && text[pos] <= 'z') || (text[pos] >= 'A' && text[pos] <= 'Z')))
      ++pos;
    if (pos == name_begin)
      transform_error("expected a transform name (matrix, translate, scale, rotate, skewX, skewY)",
                      text, pos);
    const std::string_view name = text.substr(name_begin, pos - name_begin);
    skip_wsp(text, pos);
    if (pos == text.size() || text[pos] != '(')
      transform_error("expected '(' after '" + std::string(name) + "'", text, pos);
    ++pos;
    std::vector<double> args;
    skip_wsp(text, pos);
    while (pos == text.size() || text[pos] != ')') {
      if (!args.empty()) skip_comma_wsp(text, pos);
      double v = 0;
      const std::size_t at = pos;
      const NumberScan scan = pos < text.size() ? scan_number(text, pos, v) : NumberScan::kAbsent;
      if (scan == NumberScan::kNotFinite)
        transform_error("coordinate is not a finite number", text, at);
      if (scan == NumberScan::kAbsent)
        transform_error("expected a number or ')' in '" + std::string(name) + "(...)'", text, at);
      args.push_back(v);
      skip_wsp(text, pos);
    }
    ++pos;  // ')'
    result = result * make_transform(name, args, text, name_begin);
    skip_comma_wsp(text, pos);
  }
  return result;
}

std::string parse_colour(std::string_view text) {
  const std::string_view value = trim(text);
  if (value.empty()) bad_colour(text);
  const std::string lowered = to_lower(value);
  if (lowered[0] == '#') {
    const std::string_view hex = std::string_view(lowered).substr(1);
    if (!std::all_of(hex.begin(), hex.end(), is_hex)) bad_colour(value);
    if (hex.size() == 3 || hex.size() == 4)
      return std::string{'#', hex[0], hex[0], hex[1], hex[1], hex[2], hex[2]};
    if (hex.size() == 6 || hex.size() == 8) return "#" + std::string(hex.substr(0, 6));
    bad_colour(value);
  }
  if (starts_with(lowered, "rgb(") || starts_with(lowered, "rgba("))
    return parse_rgb(value, lowered);
  for (const NamedColour& named : kNamedColors)
    if (lowered == named.name) return std::string("#") + named.hex;
  bad_colour(value);
}

Paint parse_paint(std::string_view text) {
  const std::string_view value = trim(text);
  const std::string lowered = to_lower(value);
  Paint paint;
  if (lowered == "none" || lowered == "transparent") return paint;
  if (lowered == "currentcolor") {
    paint.kind = Paint::Kind::kCurrentColour;
    return paint;
  }
  if (starts_with(lowered, "url(")) {
    const std::size_t close = value.find(')');
    const std::string_view fallback =
        close == std::string_view::npos ? std::string_view() : trim(value.substr(close + 1));
    if (fallback.empty())
      throw ElementError("paint servers (gradients, patterns) are not supported: '" +
                         std::string(value) + "'; use a plain colour");
    return parse_paint(fallback);
  }
  paint.kind = Paint::Kind::kColour;
  paint.colour = parse_colour(value);
  return paint;
}

Declarations parse_declarations(std::string_view text) {
  Declarations out;
  std::size_t begin = 0;
  while (begin <= text.size()) {
    // A ';' inside parentheses or quotes (url("a;b")) does not end the declaration.
    std::size_t end = begin;
    int depth = 0;
    char quote = 0;
    for (; end < text.size(); ++end) {
      const char c = text[end];
      if (quote) {
        if (c == quote) quote = 0;
      } else if (c == '"' || c == '\'') {
        quote = c;
      } else if (c == '(') {
        ++depth;
      } else if (c == ')') {
        depth = std::max(0, depth - 1);
      } else if (c == ';' && depth == 0) {
        break;
      }
    }
    const std::string_view declaration = text.substr(begin, end - begin);
    const std::size_t colon = declaration.find(':');
    if (colon != std::string_view::npos) {
      const std::string name = to_lower(trim(declaration.substr(0, colon)));
      std::string_view value = trim(declaration.substr(colon + 1));
      const std::string lowered = to_lower(value);
      const std::size_t important = lowered.rfind("!important");
      if (important != std::string::npos && trim(lowered.substr(important + 10)).empty())
        value = trim(value.substr(0, important));
      if (!name.empty()) out.emplace_back(name, std::string(value));
    }
    begin = end + 1;
  }
  return out;
}

void Stylesheet::add(std::string_view css) {
  // Comments and the HTML comment tokens "<!--"/"-->" are not part of any rule.
  std::string text;
  text.reserve(css.size());
  for (std::size_t i = 0; i < css.size();) {
    if (css.compare(i, 2, "/*") == 0) {
      const std::size_t end = css.find("*/", i + 2);
      if (end == std::string_view::npos) break;
      i = end + 2;
      text += ' ';
    } else if (css.compare(i, 4, "<!--") == 0) {
      i += 4;
      text += ' ';
    } else if (css.compare(i, 3, "-->") == 0) {
      i += 3;
      text += ' ';
    } else {
      text += css[i++];
    }
  }
  std::size_t pos = 0;
  while (pos < text.size()) {
    const std::size_t open = text.find('{', pos);
    if (open == std::string::npos) break;
    // Find the matching '}' (blocks of @media etc. nest).
    std::size_t close = open + 1;
    for (int depth = 1; close < text.size(); ++close) {
      if (text[close] == '{') ++depth;
      if (text[close] == '}' && --depth == 0) break;
    }
    std::string_view selector = std::string_view(text).substr(pos, open - pos);
    // Statements such as "@import url(x);" and stray '}' end before the selector.
    const std::size_t cut = selector.find_last_of(";}");
    if (cut != std::string_view::npos) selector = selector.substr(cut + 1);
    selector = trim(selector);
    const std::string_view body =
        std::string_view(text).substr(open + 1, std::min(close, text.size()) - open - 1);
    pos = close + 1;
    if (selector.empty() || selector[0] == '@') continue;
    Declarations declarations;
    bool parsed = false;
    std::size_t begin = 0;
    while (begin <= selector.size()) {
      std::size_t comma = selector.find(',', begin);
      if (comma == std::string_view::npos) comma = selector.size();
      const std::string_view one = trim(selector.substr(begin, comma - begin));
      begin = comma + 1;
      // Only a single class selector: compound or descendant selectors are ignored.
      if (one.size() < 2 || one[0] != '.' ||
          one.find_first_of(" \t\r\n\f.#:[]>+~*()", 1) != std::string_view::npos)
        continue;
      if (!parsed) {
        declarations = parse_declarations(body);
        parsed = true;
      }
      rules_.push_back(Rule{std::string(one.substr(1)), declarations});
    }
  }
}

void Stylesheet::apply(std::string_view class_attribute,
                       std::map<std::string, std::string>& properties) const {
  std::set<std::string_view> classes;
  std::size_t pos = 0;
  while (true) {
    skip_wsp(class_attribute, pos);
    if (pos == class_attribute.size()) break;
    const std::size_t begin = pos;
    while (pos < class_attribute.size() && !is_wsp(class_attribute[pos])) ++pos;
    classes.insert(class_attribute.substr(begin, pos - begin));
  }
  if (classes.empty()) return;
  for (const Rule& rule : rules_)
    if (classes.count(rule.class_name))
      for (const auto& [name, value] : rule.declarations) properties[name] = value;
}

double parse_opacity(std::string_view text) {
  const std::string_view value = trim(text);
  std::size_t pos = 0;
  double v = 0;
  if (scan_number(value, pos, v) != NumberScan::kOk)
    throw ElementError("expected an opacity (a number from 0 to 1), found '" + std::string(value) +
                       "'");
  const std::string_view rest = trim(value.substr(pos));
  if (rest == "%")
    v /= 100;
  else if (!rest.empty())
    throw ElementError("expected an opacity (a number from 0 to 1), found '" + std::string(value) +
                       "'");
  return std::clamp(v, 0.0, 1.0);
}

double parse_length(std::string_view text) {
  const std::string_view value = trim(text);
  std::size_t pos = 0;
  double v = 0;
  switch (scan_number(value, pos, v)) {
    case NumberScan::kOk:
      break;
    case NumberScan::kNotFinite:
      throw ElementError("coordinate is not a finite number ('" + std::string(value) + "')");
    case NumberScan::kAbsent:
      throw ElementError("expected a length, found '" + std::string(value) + "'");
  }
  const std::string unit = to_lower(trim(value.substr(pos)));
  double scale = 0;
  if (unit.empty() || unit == "px")
    scale = 1;
  else if (unit == "mm")
    scale = 96 / 25.4;
  else if (unit == "cm")
    scale = 96 / 2.54;
  else if (unit == "in")
    scale = 96;
  else if (unit == "pt")
    scale = 96.0 / 72.0;
  else if (unit == "pc")
    scale = 16;
  else if (unit == "q")
    scale = 96 / 101.6;
  else if (unit == "%")
    throw ElementError("percentage lengths are not supported ('" + std::string(value) + "')");
  else
    throw ElementError("unsupported unit '" + unit + "' in '" + std::string(value) +
                       "' (use px, mm, cm, in, pt or pc)");
  const double length = v * scale;
  if (!std::isfinite(length))
    throw ElementError("coordinate is not a finite number ('" + std::string(value) + "')");
  return length;
}

}  // namespace sdog::svg
