#include "geometry/input/internal/svg_path_data.h"

#include <charconv>
#include <cmath>
#include <system_error>

namespace sdog::svg {

namespace {

bool is_digit(char c) {
  return c >= '0' && c <= '9';
}

char lower(char c) {
  return (c >= 'A' && c <= 'Z') ? static_cast<char>(c - 'A' + 'a') : c;
}

bool starts_with_ci(std::string_view text, std::size_t pos, std::string_view word) {
  if (text.size() - pos < word.size()) return false;
  for (std::size_t i = 0; i < word.size(); ++i)
    if (lower(text[pos + i]) != word[i]) return false;
  return true;
}

/// "nan"/"inf" (optionally signed) at pos: such text must be reported as a non-finite number
/// rather than as a stray letter.
bool spells_non_finite(std::string_view text, std::size_t pos) {
  if (pos < text.size() && (text[pos] == '+' || text[pos] == '-')) ++pos;
  return starts_with_ci(text, pos, "nan") || starts_with_ci(text, pos, "inf");
}

bool may_start_number(std::string_view text, std::size_t pos) {
  const char c = text[pos];
  return is_digit(c) || c == '.' || c == '+' || c == '-' || spells_non_finite(text, pos);
}

/// from_chars reports overflow and underflow alike; decide which from the decimal exponent k of
/// the leading significant digit (mantissa = d.ddd * 10^k).
bool overflows(std::string_view mantissa, long long exponent) {
  std::size_t point = mantissa.find('.');
  if (point == std::string_view::npos) point = mantissa.size();
  for (std::size_t i = 0; i < mantissa.size(); ++i) {
    if (mantissa[i] == '.' || mantissa[i] == '0') continue;
    const long long k =
        i < point ? static_cast<long long>(point - i - 1) : -static_cast<long long>(i - point);
    return k + exponent > 0;
  }
  return false;
}

}  // namespace

bool is_wsp(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f';
}

void skip_wsp(std::string_view text, std::size_t& pos) {
  while (pos < text.size() && is_wsp(text[pos])) ++pos;
}

bool skip_comma_wsp(std::string_view text, std::size_t& pos) {
  skip_wsp(text, pos);
  if (pos < text.size() && text[pos] == ',') {
    ++pos;
    skip_wsp(text, pos);
    return true;
  }
  return false;
}

NumberScan scan_number(std::string_view text, std::size_t& pos, double& value) {
  const std::size_t n = text.size();
  std::size_t i = pos;
  bool negative = false;
  if (i < n && (text[i] == '+' || text[i] == '-')) {
    negative = text[i] == '-';
    ++i;
  }
  const std::size_t mantissa_begin = i;
  while (i < n && is_digit(text[i])) ++i;
  const bool int_digits = i > mantissa_begin;
  if (i < n && text[i] == '.') {
    std::size_t j = i + 1;
    while (j < n && is_digit(text[j])) ++j;
    // "5." is a number, "." alone is not; a second '.' starts the next number ("1.5.5").
    if (int_digits || j > i + 1) i = j;
  }
  if (i == mantissa_begin)
    return spells_non_finite(text, pos) ? NumberScan::kNotFinite : NumberScan::kAbsent;
  const std::size_t mantissa_end = i;
  long long exponent = 0;
  if (i < n && (text[i] == 'e' || text[i] == 'E')) {
    std::size_t j = i + 1;
    bool exp_negative = false;
    if (j < n && (text[j] == '+' || text[j] == '-')) {
      exp_negative = text[j] == '-';
      ++j;
    }
    // Without digits the 'e' is not part of the number (it is then a syntax error upstream).
    if (j < n && is_digit(text[j])) {
      while (j < n && is_digit(text[j])) {
        if (exponent < 1000000) exponent = exponent * 10 + (text[j] - '0');
        ++j;
      }
      if (exp_negative) exponent = -exponent;
      i = j;
    }
  }
  double v = 0;
  const char* first = text.data() + mantissa_begin;
  const char* last = text.data() + i;
  const auto result = std::from_chars(first, last, v, std::chars_format::general);
  if (result.ec == std::errc::result_out_of_range) {
    if (overflows(text.substr(mantissa_begin, mantissa_end - mantissa_begin), exponent))
      return NumberScan::kNotFinite;
    v = 0;
  } else if (result.ec != std::errc() || result.ptr != last || !std::isfinite(v)) {
    return NumberScan::kNotFinite;
  }
  value = negative ? -v : v;
  pos = i;
  return NumberScan::kOk;
}

std::string position_note(std::string_view text, std::size_t pos) {
  constexpr std::size_t kBefore = 12, kLength = 28;
  std::size_t begin = pos > kBefore ? pos - kBefore : 0;
  // Never cut a UTF-8 sequence in the middle.
  while (begin > 0 && begin < text.size() &&
         (static_cast<unsigned char>(text[begin]) & 0xC0) == 0x80)
    --begin;
  std::size_t end = std::min(text.size(), begin + kLength);
  while (end < text.size() && (static_cast<unsigned char>(text[end]) & 0xC0) == 0x80) ++end;
  std::string excerpt;
  if (begin > 0) excerpt += "…";
  for (std::size_t i = begin; i < end; ++i) {
    const char c = text[i];
    excerpt += (static_cast<unsigned char>(c) < 0x20) ? ' ' : c;
  }
  if (end < text.size()) excerpt += "…";
  return "at character " + std::to_string(pos + 1) + " (\"" + excerpt + "\")";
}

std::vector<double> parse_number_list(std::string_view text) {
  std::vector<double> numbers;
  std::size_t pos = 0;
  skip_wsp(text, pos);
  while (pos < text.size()) {
    double v = 0;
    switch (scan_number(text, pos, v)) {
      case NumberScan::kOk:
        break;
      case NumberScan::kNotFinite:
        throw ElementError("coordinate is not a finite number " + position_note(text, pos));
      case NumberScan::kAbsent:
        throw ElementError("expected a number " + position_note(text, pos));
    }
    numbers.push_back(v);
    const bool comma = skip_comma_wsp(text, pos);
    if (comma && pos == text.size())
      throw ElementError("expected a number after ',' " + position_note(text, pos));
  }
  return numbers;
}

std::vector<Point> parse_points(std::string_view text) {
  const std::vector<double> numbers = parse_number_list(text);
  if (numbers.size() % 2 != 0)
    throw ElementError("odd number of coordinates (" + std::to_string(numbers.size()) +
                       "); expected x,y pairs");
  std::vector<Point> points;
  points.reserve(numbers.size() / 2);
  for (std::size_t i = 0; i < numbers.size(); i += 2)
    points.emplace_back(numbers[i], numbers[i + 1]);
  return points;
}

namespace {

bool is_command(char c) {
  switch (c) {
    case 'M':
    case 'm':
    case 'L':
    case 'l':
    case 'H':
    case 'h':
    case 'V':
    case 'v':
    case 'C':
    case 'c':
    case 'S':
    case 's':
    case 'Q':
    case 'q':
    case 'T':
    case 't':
    case 'A':
    case 'a':
    case 'Z':
    case 'z':
      return true;
    default:
      return false;
  }
}

class PathParser {
 public:
  explicit PathParser(std::string_view d) : d_(d) {}

  std::vector<PathSubpath> parse() {
    skip_wsp(d_, pos_);
    if (pos_ == d_.size()) return {};
    if (d_[pos_] != 'M' && d_[pos_] != 'm')
      fail("must start with 'M' or 'm', found '" + std::string(1, d_[pos_]) + "'", pos_);
    char command = 0;
    while (true) {
      skip_wsp(d_, pos_);
      if (pos_ == d_.size()) break;
      command_pos_ = pos_;
      const char c = d_[pos_];
      bool repeated = false;
      if (is_command(c)) {
        command = c;
        ++pos_;
        skip_wsp(d_, pos_);
      } else {
        // Implicit repetition of the previous command (after M/m: lineto).
        if (command == 'Z' || command == 'z') {
          if (may_start_number(d_, pos_))
            fail(std::string("unexpected number after '") + command + "'", pos_);
          fail(unexpected_character(), pos_);
        }
        if (c == ',') {
          ++pos_;
          skip_wsp(d_, pos_);
          if (pos_ == d_.size() || !may_start_number(d_, pos_))
            fail(expected_number(command), pos_);
        } else if (!may_start_number(d_, pos_)) {
          fail(unexpected_character(), pos_);
        }
        repeated = true;
      }
      execute(command, repeated);
    }
    return std::move(subpaths_);
  }

 private:
  [[noreturn]] void fail(const std::string& what, std::size_t at) const {
    throw ElementError(what + " " + position_note(d_, at));
  }

  std::string unexpected_character() const {
    const unsigned char c = static_cast<unsigned char>(d_[pos_]);
    if (c < 0x20 || c == 0x7f) {
      static const char digits[] = "0123456789ABCDEF";
      return std::string("unexpected control character U+00") + digits[c >> 4] + digits[c & 15];
    }
    // Quote a whole UTF-8 sequence, not its first byte.
    std::size_t end = pos_ + 1;
    while (end < d_.size() && (static_cast<unsigned char>(d_[end]) & 0xC0) == 0x80) ++end;
    return "unexpected character '" + std::string(d_.substr(pos_, end - pos_)) + "'";
  }

  static std::string expected_number(char command) {
    return std::string("expected a number after '") + command + "'";
  }

  /// One argument; `first` arguments follow the command letter (white space only), the others
  /// follow a previous number (comma-wsp allowed).
  double number(char command, bool first) {
    if (!first) skip_comma_wsp(d_, pos_);
    double v = 0;
    const std::size_t at = pos_;
    switch (pos_ < d_.size() ? scan_number(d_, pos_, v) : NumberScan::kAbsent) {
      case NumberScan::kOk:
        return v;
      case NumberScan::kNotFinite:
        fail("coordinate is not a finite number", at);
      case NumberScan::kAbsent:
        break;
    }
    fail(expected_number(command), at);
  }

  bool flag(char command) {
    skip_comma_wsp(d_, pos_);
    if (pos_ < d_.size() && (d_[pos_] == '0' || d_[pos_] == '1')) return d_[pos_++] == '1';
    fail(std::string("expected an arc flag (0 or 1) after '") + command + "'", pos_);
  }

  Point pair(char command, bool first) {
    const double x = number(command, first);
    const double y = number(command, false);
    return {x, y};
  }

  Point checked(const Point& p) const {
    if (!std::isfinite(p.x()) || !std::isfinite(p.y()))
      fail("coordinate is not a finite number (the sum of relative offsets overflows)",
           command_pos_);
    return p;
  }

  /// Drawing after Z continues from the closed subpath's start in a new subpath.
  PathSubpath& current_subpath() {
    if (need_subpath_) {
      PathSubpath s;
      s.start = start_;
      s.offset = command_pos_;
      subpaths_.push_back(std::move(s));
      need_subpath_ = false;
    }
    return subpaths_.back();
  }

  void add(PathSegment segment) {
    segment.from = current_;
    current_ = segment.to;
    current_subpath().segments.push_back(segment);
  }

  void line_to(const Point& p) {
    PathSegment s;
    s.kind = SegmentKind::kLine;
    s.to = p;
    add(s);
  }

  /// The command being executed: its letter, whether it is relative, and the origin its
  /// coordinates are relative to (the current point before it, or (0, 0)).
  struct Command {
    char letter;
    bool relative;
    Point origin;
  };

  /// A coordinate pair of `c` in absolute coordinates.
  Point absolute(const Command& c, const Point& p) const {
    return c.relative ? checked(Point(c.origin + p)) : p;
  }

  void execute(char command, bool repeated) {
    const bool relative = command >= 'a' && command <= 'z';
    const char upper = relative ? static_cast<char>(command - 'a' + 'A') : command;
    const Command c{command, relative, relative ? current_ : Point(0, 0)};
    switch (upper) {
      case 'M':
        move_to(c, repeated);
        break;
      case 'L':
        line_to(absolute(c, pair(command, true)));
        break;
      case 'H': {
        const double x = number(command, true);
        line_to(checked(Point(relative ? current_.x() + x : x, current_.y())));
        break;
      }
      case 'V': {
        const double y = number(command, true);
        line_to(checked(Point(current_.x(), relative ? current_.y() + y : y)));
        break;
      }
      case 'C':
      case 'S':
        cubic_to(c, upper == 'S');
        break;
      case 'Q':
      case 'T':
        quadratic_to(c, upper == 'T');
        break;
      case 'A':
        arc_to(c);
        break;
      case 'Z':
        close_path();
        break;
    }
    // For the reflection of the control point by a following S/T.
    last_was_cubic_ = upper == 'C' || upper == 'S';
    last_was_quadratic_ = upper == 'Q' || upper == 'T';
  }

  /// M/m; a repeated one (coordinates after the first pair) draws lines.
  void move_to(const Command& c, bool repeated) {
    Point p = pair(c.letter, true);
    if (repeated) {
      line_to(absolute(c, p));
      return;
    }
    // A first "m" is absolute: its offset is from (0, 0), and copying avoids -0 + 0.
    if (c.relative && !subpaths_.empty()) p = checked(Point(current_ + p));
    PathSubpath s;
    s.start = p;
    s.offset = command_pos_;
    subpaths_.push_back(std::move(s));
    need_subpath_ = false;
    start_ = current_ = p;
  }

  /// C/c, or S/s (`smooth`: the first control point reflects the previous cubic's second one).
  void cubic_to(const Command& c, bool smooth) {
    PathSegment s;
    s.kind = SegmentKind::kCubic;
    if (smooth)
      s.c1 = last_was_cubic_ ? checked(Point(current_ + (current_ - last_control_))) : current_;
    else
      s.c1 = absolute(c, pair(c.letter, true));
    s.c2 = absolute(c, pair(c.letter, smooth));
    s.to = absolute(c, pair(c.letter, false));
    add(s);
    last_control_ = s.c2;
  }

  /// Q/q, or T/t (`smooth`: the control point reflects the previous quadratic's one).
  void quadratic_to(const Command& c, bool smooth) {
    PathSegment s;
    s.kind = SegmentKind::kQuadratic;
    if (smooth)
      s.c1 = last_was_quadratic_ ? checked(Point(current_ + (current_ - last_control_))) : current_;
    else
      s.c1 = absolute(c, pair(c.letter, true));
    s.to = absolute(c, pair(c.letter, smooth));
    add(s);
    last_control_ = s.c1;
  }

  /// A/a.
  void arc_to(const Command& c) {
    PathSegment s;
    s.kind = SegmentKind::kArc;
    s.rx = std::abs(number(c.letter, true));
    s.ry = std::abs(number(c.letter, false));
    s.rotation_deg = number(c.letter, false);
    s.large_arc = flag(c.letter);
    s.sweep = flag(c.letter);
    s.to = absolute(c, pair(c.letter, false));
    // F.6.2: identical endpoints omit the arc; a zero radius makes it a straight line.
    if (s.to == current_) return;
    if (s.rx == 0 || s.ry == 0) s.kind = SegmentKind::kLine;
    add(s);
  }

  /// Z/z.
  void close_path() {
    if (!need_subpath_) {
      subpaths_.back().closed = true;
      current_ = start_;
      need_subpath_ = true;
    }
  }

  std::string_view d_;
  std::size_t pos_ = 0;
  std::size_t command_pos_ = 0;
  std::vector<PathSubpath> subpaths_;
  Point current_ = Point::Zero();
  Point start_ = Point::Zero();
  Point last_control_ = Point::Zero();
  bool last_was_cubic_ = false;
  bool last_was_quadratic_ = false;
  bool need_subpath_ = false;
};

}  // namespace

std::vector<PathSubpath> parse_path_data(std::string_view d) {
  return PathParser(d).parse();
}

}  // namespace sdog::svg
