#include "geometry/input/fold_reader.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <deque>
#include <map>
#include <nlohmann/json.hpp>
#include <utility>
#include <vector>

#include "base/errors.h"
#include "base/json_field.h"
#include "base/text_file.h"
#include "base/text_format.h"
#include "geometry/pattern/pattern_assembly.h"

namespace sdog {
namespace {

using nlohmann::json;

constexpr double kHalfTurn = 180;
/// Two edges continue each other when |sin| of the angle between them is at most this.
constexpr double kCollinear = 1e-9;

struct Edge {
  int a = 0, b = 0;       ///< vertex indices
  char assignment = 'U';  ///< B, M, V, F, U, C or J
  Fold fold = Fold::kUnassigned;
  std::optional<double> angle;  ///< magnitude in degrees, as Crease::angle
  bool dropped = false;         ///< a join edge, or a repeat of an earlier edge

  int other_end(int v) const { return v == a ? b : a; }
  bool is_crease() const { return !dropped && assignment != 'B'; }
  bool folds_like(const Edge& e) const {
    return (assignment == 'C') == (e.assignment == 'C') && fold == e.fold && angle == e.angle;
  }
};

// "line L, column C" of a byte offset.
std::string line_and_column(const std::string& text, size_t byte) {
  byte = std::min(byte, text.size());
  const size_t line =
      1 + std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(byte), '\n');
  const size_t line_start = text.rfind('\n', byte == 0 ? 0 : byte - 1);
  const size_t column =
      byte - (line_start == std::string::npos || byte == 0 ? 0 : line_start + 1) + 1;
  return "line " + std::to_string(line) + ", column " + std::to_string(column);
}

// nlohmann's message without its "[json.exception.parse_error.101] " prefix.
std::string json_message(const json::exception& e) {
  const std::string what = e.what();
  const size_t end = what.find("] ");
  return what.rfind("[json.exception.", 0) == 0 && end != std::string::npos ? what.substr(end + 2)
                                                                            : what;
}

json parse_json(const std::string& text, const std::string& source) {
  try {
    return json::parse(text);
  } catch (const json::parse_error& e) {
    throw InputError(source + ": not valid JSON (" + json_message(e) + ")");
  } catch (const json::out_of_range& e) {
    // A number too large for a double: nlohmann does not say where; its first occurrence.
    const std::string message = json_message(e);
    const size_t quote = message.find('\'');
    const std::string number =
        quote == std::string::npos ? "" : message.substr(quote + 1, message.size() - quote - 2);
    const size_t at = number.empty() ? std::string::npos : text.find(number);
    throw InputError(source + ": not valid JSON (" + message +
                     (at == std::string::npos ? "" : " at " + line_and_column(text, at)) +
                     ": not a finite number)");
  } catch (const json::exception& e) {
    throw InputError(source + ": not valid JSON (" + json_message(e) + ")");
  }
}

class FoldReader {
 public:
  FoldReader(const json& root, const std::string& source)
      : root_(root, "$", source), source_(source) {}

  CreasePattern read() {
    if (!root_.value().is_object())
      root_.fail("expected a JSON object (FOLD files are JSON objects)");
    check_frame_classes();
    read_vertices();
    read_edges();
    read_fold_angles();
    drop_repeated_edges();
    if (joins_ > 0)
      warnings_.push_back(source_ + ": " + std::to_string(joins_) +
                          " join edge(s) (J, modelling helpers) ignored");
    CreasePattern pattern;
    pattern.source = source_;
    pattern.sheet = sheet();
    pattern.sheet.bbox = box_of(pattern.sheet.outer);
    add_creases(pattern);
    pattern.warnings = warnings_;
    return pattern;
  }

 private:
  std::string edge_name(size_t e) const { return source_ + ": edge " + std::to_string(e); }
  // The vertex's coordinates as the file gives them, "[x, y]".
  std::string file_point(int v) const {
    return "[" + format_number(points_[v].x()) + ", " + format_number(-points_[v].y() + 0.0) + "]";
  }
  std::string vertex_name(int v) const {
    return "vertex " + std::to_string(v) + " at " + file_point(v);
  }

  // A key the reader needs; its absence is explained.
  Field required(const char* key, const std::string& why) const {
    if (!root_.has(key)) {
      const std::string frames =
          root_.has("file_frames") ? " (only the top-level frame is read, not file_frames)" : "";
      throw InputError(source_ + ": no " + key + frames + "; " + why);
    }
    return root_[key];
  }

  // The number of entries of an array that has one for each edge.
  void expect_one_per_edge(const Field& array) const {
    const size_t n = array.array_size();
    if (n != edges_.size())
      array.fail("has " + std::to_string(n) + " entries, edges_vertices has " +
                 std::to_string(edges_.size()) + "; there must be one for each edge");
  }

  void check_frame_classes() const {
    if (!root_.has("frame_classes")) return;
    const Field classes = root_["frame_classes"];
    bool folded = false, crease_pattern = false;
    for (size_t i = 0; i < classes.array_size(); ++i) {
      const std::string c = classes[i].text();
      folded = folded || c == "foldedForm";
      crease_pattern = crease_pattern || c == "creasePattern";
    }
    if (folded && !crease_pattern)
      classes.fail(
          "a folded form, not a crease pattern (\"foldedForm\" without \"creasePattern\"): its "
          "coordinates are the folded state; read the crease pattern (its SVG or FOLD file) "
          "instead");
  }

  void read_vertices() {
    const Field coords =
        required("vertices_coords", "a crease pattern needs its vertices' coordinates");
    const size_t n = coords.array_size();
    points_.reserve(n);
    for (size_t i = 0; i < n; ++i) {
      const Field c = coords[i];
      const size_t dims = c.array_size();
      if (dims < 2) c.fail("expected [x, y], the vertex's coordinates");
      for (size_t k = 2; k < dims; ++k)
        if (const double z = c[k].number(); z != 0)
          c[k].fail("coordinate " + format_number(z) +
                    " off the plane z = 0; a crease pattern is flat");
      // FOLD's y points down the page, as SVG's (see the header); -y + 0.0 is never -0.
      points_.emplace_back(c[size_t{0}].number(), -c[1].number() + 0.0);
    }
  }

  void read_edges() {
    const Field ends = required("edges_vertices", "a crease pattern needs its edges");
    const Field letters =
        required("edges_assignment",
                 "without assignments the sheet boundary (the B edges) is unknown; give each edge "
                 "B (boundary), M (mountain), V (valley), F (flat) or U (unassigned)");
    edges_.resize(ends.array_size());
    expect_one_per_edge(letters);
    for (size_t e = 0; e < edges_.size(); ++e) {
      read_ends(ends[e], edges_[e]);
      read_assignment(letters[e], e, edges_[e]);
    }
  }

  void read_ends(const Field& pair, Edge& edge) const {
    if (pair.array_size() != 2)
      pair.fail("expected [u, v], the indices of the edge's two vertices");
    int ends[2];
    for (size_t k = 0; k < 2; ++k) {
      ends[k] = pair[k].integer(0);
      if (static_cast<size_t>(ends[k]) >= points_.size())
        pair[k].fail("vertex " + std::to_string(ends[k]) + " does not exist (vertices_coords has " +
                     std::to_string(points_.size()) + " vertices, numbered from 0)");
    }
    edge.a = ends[0];
    edge.b = ends[1];
    if (edge.a == edge.b)
      pair.fail("the edge joins vertex " + std::to_string(edge.a) + " to itself");
    if (points_[edge.a] == points_[edge.b])
      pair.fail("the edge has zero length (vertices " + std::to_string(edge.a) + " and " +
                std::to_string(edge.b) + " are both at " + file_point(edge.a) + ")");
  }

  void read_assignment(const Field& letter, size_t e, Edge& edge) {
    const std::string text = letter.text();
    const char c = text.size() == 1
                       ? static_cast<char>(std::toupper(static_cast<unsigned char>(text[0])))
                       : '?';
    static const std::map<char, Fold> kFolds = {{'B', Fold::kUnassigned}, {'M', Fold::kMountain},
                                                {'V', Fold::kValley},     {'F', Fold::kFlat},
                                                {'U', Fold::kUnassigned}, {'J', Fold::kUnassigned},
                                                {'C', Fold::kFlat}};
    const auto it = kFolds.find(c);
    if (it == kFolds.end())
      letter.fail("unknown assignment " + json(text).dump() +
                  "; FOLD's are B, M, V, F, U, C and J");
    edge.assignment = c;
    edge.fold = it->second;
    if (c == 'F') edge.angle = 0;  // as the SVG reader: a flat crease has the angle 0
    if (c == 'J') {
      edge.dropped = true;
      ++joins_;
    }
  }

  void read_fold_angles() {
    if (!root_.has("edges_foldAngle")) return;
    const Field angles = root_["edges_foldAngle"];
    expect_one_per_edge(angles);
    for (size_t e = 0; e < edges_.size(); ++e) {
      const Field a = angles[e];
      if (a.value().is_null() || edges_[e].assignment == 'J') continue;
      const double degrees = a.number();
      if (degrees < -kHalfTurn || degrees > kHalfTurn)
        a.fail("fold angle " + format_number(degrees) + " outside [-180, 180] degrees");
      apply_fold_angle(a, degrees, edges_[e]);
    }
  }

  // FOLD's signed angle on an edge: valleys positive, mountains negative.
  static void apply_fold_angle(const Field& a, double degrees, Edge& edge) {
    const std::string angle = "fold angle " + format_number(degrees);
    switch (edge.assignment) {
      case 'B':
      case 'C':
      case 'F':
        if (degrees != 0)
          a.fail(angle + " on " +
                 (edge.assignment == 'B'   ? "a boundary edge (B)"
                  : edge.assignment == 'C' ? "a cut (C)"
                                           : "a flat crease (F)") +
                 ", which does not fold; FOLD gives it 0");
        return;
      case 'M':
        if (degrees > 0)
          a.fail(angle + " on a mountain crease (M); FOLD's mountain angles are negative");
        break;
      case 'V':
        if (degrees < 0)
          a.fail(angle + " on a valley crease (V); FOLD's valley angles are positive");
        break;
      default:  // U: the sign assigns the crease; 0 says nothing
        if (degrees == 0) return;
        edge.fold = degrees > 0 ? Fold::kValley : Fold::kMountain;
    }
    edge.angle = std::abs(degrees);
  }

  // An edge that joins the same two vertices as an earlier one is dropped, with a warning.
  void drop_repeated_edges() {
    std::map<std::pair<int, int>, size_t> first;
    for (size_t e = 0; e < edges_.size(); ++e) {
      Edge& edge = edges_[e];
      if (edge.dropped) continue;
      const auto [it, added] =
          first.try_emplace({std::min(edge.a, edge.b), std::max(edge.a, edge.b)}, e);
      if (added) continue;
      const Edge& kept = edges_[it->second];
      warnings_.push_back(edge_name(e) + " (" + edge.assignment + ") joins the same vertices (" +
                          std::to_string(edge.a) + " and " + std::to_string(edge.b) + ") as edge " +
                          std::to_string(it->second) + " (" + kept.assignment + "); ignored");
      edge.dropped = true;
    }
  }

  // The sheet from the B edges chained into closed loops.
  Sheet sheet() const {
    std::vector<std::vector<int>> at(points_.size());  // B edges at each vertex
    for (size_t e = 0; e < edges_.size(); ++e)
      if (!edges_[e].dropped && edges_[e].assignment == 'B') {
        at[edges_[e].a].push_back(static_cast<int>(e));
        at[edges_[e].b].push_back(static_cast<int>(e));
      }
    for (size_t v = 0; v < at.size(); ++v) {
      if (at[v].size() == 1)
        throw InputError(edge_name(at[v][0]) +
                         ": the sheet boundary (B edges) is not closed: it stops at " +
                         vertex_name(static_cast<int>(v)) +
                         ", which has no other B edge; the B edges must form closed loops");
      if (at[v].size() > 2)
        throw InputError(
            edge_name(at[v][0]) + ": the sheet boundary branches at " +
            vertex_name(static_cast<int>(v)) + ", which has " + std::to_string(at[v].size()) +
            " B edges; every vertex of a boundary loop has exactly two, and loops may not touch");
    }
    std::vector<Polyline2> loops;
    std::vector<std::string> origins;
    std::vector<bool> used(edges_.size(), false);
    for (size_t first = 0; first < edges_.size(); ++first) {
      if (used[first] || edges_[first].dropped || edges_[first].assignment != 'B') continue;
      Polyline2 loop;
      int e = static_cast<int>(first), v = edges_[first].a;
      do {
        used[e] = true;
        loop.push_back(points_[v]);
        v = edges_[e].other_end(v);
        e = at[v][0] == e ? at[v][1] : at[v][0];
      } while (!used[e]);
      loops.push_back(std::move(loop));
      origins.push_back(edge_name(first));
    }
    if (loops.empty())
      throw InputError(source_ +
                       ": no boundary edge (B) in edges_assignment, so the sheet is unknown; "
                       "mark the edges of the sheet's outline B");
    return sheet_from_loops(loops, origins);
  }

  // The edge of e's class that continues e straight on through its vertex v, or -1: v must have
  // exactly two edges of the class.
  int continuation(int e, int v) const {
    int other = -1;
    for (const int f : creases_at_[v]) {
      if (f == e || !edges_[f].folds_like(edges_[e])) continue;
      if (other >= 0) return -1;
      other = f;
    }
    if (other < 0) return -1;
    const Eigen::Vector2d d1 = points_[edges_[e].other_end(v)] - points_[v];
    const Eigen::Vector2d d2 = points_[edges_[other].other_end(v)] - points_[v];
    const double cross = d1.x() * d2.y() - d1.y() * d2.x();
    const bool straight = d1.dot(d2) < 0 && std::abs(cross) <= kCollinear * d1.norm() * d2.norm();
    return straight ? other : -1;
  }

  // The crease through edge `first`, extended through both ends while edges continue it.
  Crease crease_from(int first, std::vector<bool>& used) const {
    std::deque<int> chain{edges_[first].a, edges_[first].b};
    used[first] = true;
    for (const bool forward : {true, false}) {
      int e = first, v = forward ? edges_[first].b : edges_[first].a;
      for (int next = continuation(e, v); next >= 0 && !used[next]; next = continuation(e, v)) {
        used[next] = true;
        v = edges_[next].other_end(v);
        forward ? chain.push_back(v) : chain.push_front(v);
        e = next;
      }
    }
    Crease crease;
    for (const int v : chain) crease.points.push_back(points_[v]);
    crease.fold = edges_[first].fold;
    crease.angle = edges_[first].angle;
    if (edges_[first].assignment == 'C') crease.kind = CurveKind::kSlit;
    crease.id = "edge " + std::to_string(first);
    crease.origin = edge_name(first);
    return crease;
  }

  void add_creases(CreasePattern& pattern) {
    creases_at_.assign(points_.size(), {});
    for (size_t e = 0; e < edges_.size(); ++e)
      if (edges_[e].is_crease()) {
        creases_at_[edges_[e].a].push_back(static_cast<int>(e));
        creases_at_[edges_[e].b].push_back(static_cast<int>(e));
      }
    std::vector<bool> used(edges_.size(), false);
    for (size_t e = 0; e < edges_.size(); ++e) {
      if (used[e] || !edges_[e].is_crease()) continue;
      Crease crease = crease_from(static_cast<int>(e), used);
      check_near_sheet(crease.points, crease.origin, pattern);
      pattern.creases.push_back(std::move(crease));
    }
  }

  const Field root_;
  const std::string source_;
  Polyline2 points_;  ///< sheet units: FOLD's (x, y) as (x, -y)
  std::vector<Edge> edges_;
  std::vector<std::vector<int>> creases_at_;  ///< the crease edges at each vertex
  int joins_ = 0;
  std::vector<std::string> warnings_;
};

}  // namespace

CreasePattern parse_fold(const std::string& text, const std::string& source) {
  const json root = parse_json(text, source);
  return FoldReader(root, source).read();
}

CreasePattern read_fold_file(const std::string& path) {
  return parse_fold(read_text_file(path), path);
}

}  // namespace sdog
