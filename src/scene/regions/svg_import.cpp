// SVG shapes as outlines, step for step as OpenSCAD 2021.01's import_svg.cc
// over its libsvg (libsvg.cc, svgpage.cc, shape.cc, path.cc, rect.cc,
// circle.cc, ellipse.cc, line.cc, polygon.cc, polyline.cc,
// transformation.cc, util.cc): the same tokens, the same fixed cuts of
// curves, the same stroke offset and the same page placement, so that the
// outlines have OpenSCAD's vertices.

#include "scene/regions/svg_import.h"

#include "scene/libxml2_library.h"

#include "scene/reading/scene_expression.h"

#include <fmt/format.h>
#include <libxml/xmlreader.h>

#include <algorithm>
#include <charconv>
#include <climits>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

namespace capsim::scene_file {

namespace {

constexpr double kInchToMm = 25.4;
// Larger numbers are refused, as the DXF reader refuses them.
constexpr double kMaxNumber = 1e30;
// libsvg strokes an open outline in integers of 1/10000 unit, by Clipper's
// offset; coordinates beyond this would leave Clipper's range.
constexpr double kStrokeScale = 10000;
constexpr double kMaxStrokeCoordinate = 1e13;
// Point-by-matrix products for the transforms above the shapes.
constexpr double kMaxTransformWork = 1e8;

using Path = std::vector<glm::dvec2>;
using PathList = std::vector<Path>;
using Attrs = std::map<std::string, std::string, std::less<>>;

[[noreturn]] void fail(int line, const std::string& message) {
  throw SvgError(fmt::format("{}: {}", line, message));
}

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f'; }
bool is_digit(char c) { return c >= '0' && c <= '9'; }

// The length of the longest prefix of `s` that Boost.Spirit's real parser
// (libsvg's numbers) reads: a sign, digits with an optional point (".5" and
// "1." included), an exponent only when digits follow its 'e'. 0: none.
std::size_t scan_real(std::string_view s) {
  std::size_t i = 0;
  if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
  const std::size_t whole = i;
  while (i < s.size() && is_digit(s[i])) ++i;
  bool digits = i > whole;
  if (i < s.size() && s[i] == '.') {
    std::size_t j = i + 1;
    while (j < s.size() && is_digit(s[j])) ++j;
    if (digits || j > i + 1) digits = true, i = j;
  }
  if (!digits) return 0;
  if (i < s.size() && (s[i] == 'e' || s[i] == 'E')) {
    std::size_t j = i + 1;
    if (j < s.size() && (s[j] == '+' || s[j] == '-')) ++j;
    const std::size_t exponent = j;
    while (j < s.size() && is_digit(s[j])) ++j;
    if (j > exponent) i = j;
  }
  return i;
}

// A number scan_real accepted.
double to_double(std::string_view s, int line, std::string_view what) {
  std::string_view digits = s;
  if (!digits.empty() && digits.front() == '+') digits.remove_prefix(1);
  double v = 0;
  std::from_chars(digits.data(), digits.data() + digits.size(), v);
  if (!std::isfinite(v) || !(std::abs(v) <= kMaxNumber))
    fail(line, fmt::format("{} '{}' is not a number within {:g}", what, s, kMaxNumber));
  return v;
}

// libsvg's parse_double: the whole text a number. OpenSCAD reads anything
// else as 0; capsim refuses it, but for no text at all (0, as OpenSCAD).
double number(std::string_view s, int line, std::string_view what) {
  if (s.empty()) return 0;
  const std::size_t n = scan_real(s);
  if (n == 0 || n != s.size())
    fail(line, fmt::format("{} '{}' is not a number (OpenSCAD 2021.01 reads it as 0)", what, s));
  return to_double(s, line, what);
}

// boost::tokenizer's char_separator: `dropped` characters separate tokens,
// each `kept` character is a token of its own.
std::vector<std::string> tokenize(std::string_view s, std::string_view dropped, std::string_view kept) {
  std::vector<std::string> tokens;
  std::string current;
  for (char c : s) {
    const bool drop = dropped.find(c) != std::string_view::npos, keep = kept.find(c) != std::string_view::npos;
    if (drop || keep) {
      if (!current.empty()) tokens.push_back(std::move(current));
      current.clear();
      if (keep) tokens.emplace_back(1, c);
    } else {
      current += c;
    }
  }
  if (!current.empty()) tokens.push_back(std::move(current));
  return tokens;
}

// One of libsvg's 3x3 matrices, its last row (0 0 1).
struct Affine {
  double a = 1, b = 0, c = 0, d = 1, e = 0, f = 0;  // [a c e; b d f]
  glm::dvec2 apply(const glm::dvec2& p) const {
    return {a * p.x + c * p.y + e * 1.0, b * p.x + d * p.y + f * 1.0};
  }
};

Affine translation(double x, double y) { return {1, 0, 0, 1, x, y}; }

// A transform attribute's matrices, in the order they apply to a point
// (shape::collect_transform_matrices): "A B" is A(B(p)).
std::vector<Affine> parse_transform(std::string s, int line) {
  const std::string given = s;
  for (const auto& [word, letter] : {std::pair{"matrix", "m"}, std::pair{"translate", "t"}, std::pair{"scale", "s"},
                                     std::pair{"rotate", "r"}, std::pair{"skewX", "x"}, std::pair{"skewY", "y"}})
    for (std::size_t at = s.find(word); at != std::string::npos; at = s.find(word, at + 1))
      s.replace(at, std::string_view(word).size(), letter);
  struct Op {
    char op;
    std::vector<double> args;
  };
  std::vector<Op> ops;
  constexpr std::string_view kOps = "mtsrxy";
  for (const std::string& token : tokenize(s, " ,()", kOps)) {
    if (token.size() == 1 && kOps.find(token[0]) != std::string_view::npos) {
      ops.push_back({token[0], {}});
    } else if (ops.empty()) {
      fail(line, fmt::format("the transform '{}' does not start with matrix, translate, scale, rotate, skewX or "
                             "skewY (OpenSCAD 2021.01 skips '{}')",
                             given, token));
    } else {
      ops.back().args.push_back(number(token, line, "the transform's argument"));
    }
  }
  std::vector<Affine> result;
  for (auto op = ops.rbegin(); op != ops.rend(); ++op) {
    const std::vector<double>& v = op->args;
    const std::size_t n = v.size();
    auto refuse = [&](std::string_view name, std::string_view counts) {
      fail(line, fmt::format("{}() in the transform '{}' takes {} numbers, not {} (OpenSCAD 2021.01 skips it)", name,
                             given, counts, n));
    };
    switch (op->op) {
      case 'm':
        if (n != 6) refuse("matrix", "6");
        result.push_back({v[0], v[1], v[2], v[3], v[4], v[5]});
        break;
      case 't':
        if (n < 1 || n > 2) refuse("translate", "1 or 2");
        result.push_back(translation(v[0], n > 1 ? v[1] : 0));
        break;
      case 's':
        if (n < 1 || n > 2) refuse("scale", "1 or 2");
        result.push_back({v[0], 0, 0, n > 1 ? v[1] : v[0], 0, 0});
        break;
      case 'r': {
        if (n != 1 && n != 3) refuse("rotate", "1 or 3");
        const double sn = sin_degrees(v[0]), cs = cos_degrees(v[0]);
        if (n == 3) result.push_back(translation(-v[1], -v[2]));
        result.push_back({cs, sn, -sn, cs, 0, 0});
        if (n == 3) result.push_back(translation(v[1], v[2]));
        break;
      }
      case 'x':
        if (n != 1) refuse("skewX", "1");
        result.push_back({1, 0, tan_degrees(v[0]), 1, 0, 0});
        break;
      default:
        if (n != 1) refuse("skewY", "1");
        result.push_back({1, tan_degrees(v[0]), 0, 1, 0, 0});
        break;
    }
  }
  return result;
}

// libsvg's units (util.h) and lengths: a number and an optional unit.
enum class Unit { Undefined, None, Percent, Em, Ex, Px, In, Cm, Mm, Pt, Pc };

struct Length {
  double number = 0;
  Unit unit = Unit::Undefined;
};

struct ViewBox {
  double x = 0, y = 0, width = 0, height = 0;
  bool valid = false;
};

enum class Align { None, Min, Mid, Max };

struct Alignment {
  Align x = Align::Mid, y = Align::Mid;
  bool meet = true;
};

// The text of a page attribute, read as Boost.Spirit's phrase_parse reads
// it: white space between the parts is skipped.
class Phrase {
 public:
  explicit Phrase(std::string_view s) : s_(s) { skip(); }
  bool at_end() const { return i_ == s_.size(); }
  bool real(double& v, int line, std::string_view what) {
    const std::size_t n = scan_real(s_.substr(i_));
    if (n == 0) return false;
    v = to_double(s_.substr(i_, n), line, what);
    i_ += n;
    skip();
    return true;
  }
  bool word(std::string_view w) {
    if (s_.substr(i_, w.size()) != w) return false;
    i_ += w.size();
    skip();
    return true;
  }

 private:
  void skip() {
    while (i_ < s_.size() && is_space(s_[i_])) ++i_;
  }
  std::string_view s_;
  std::size_t i_ = 0;
};

Length parse_length(std::string_view s, int line, std::string_view what) {
  Length result;
  if (s.empty()) return result;
  Phrase p(s);
  double v = 0;
  if (!p.real(v, line, what)) fail(line, fmt::format("{} '{}' is not a length", what, s));
  result = {v, Unit::None};
  constexpr std::pair<std::string_view, Unit> kUnits[] = {{"em", Unit::Em}, {"ex", Unit::Ex}, {"px", Unit::Px},
                                                          {"in", Unit::In}, {"cm", Unit::Cm}, {"mm", Unit::Mm},
                                                          {"pt", Unit::Pt}, {"pc", Unit::Pc}, {"%", Unit::Percent}};
  for (const auto& [name, unit] : kUnits)
    if (p.word(name)) {
      result.unit = unit;
      break;
    }
  if (!p.at_end())
    fail(line, fmt::format("{} '{}' is not a length (a number and one of em, ex, px, in, cm, mm, pt, pc, %; "
                           "OpenSCAD 2021.01 reads it as no length)",
                           what, s));
  return result;
}

ViewBox parse_viewbox(std::string_view s, int line) {
  ViewBox box;
  if (s.empty()) return box;
  Phrase p(s);
  double v[4];
  for (int k = 0; k < 4; ++k) {
    if (k > 0) p.word(",");
    if (!p.real(v[k], line, "the viewBox's number"))
      fail(line, fmt::format("the viewBox '{}' is not 4 numbers (OpenSCAD 2021.01 reads no viewBox)", s));
  }
  if (!p.at_end()) fail(line, fmt::format("the viewBox '{}' is not 4 numbers (OpenSCAD 2021.01 reads no viewBox)", s));
  if (!(v[2] > 0 && v[3] > 0))
    fail(line, fmt::format("the viewBox '{}' has no area: OpenSCAD 2021.01 scales the drawing by its width and "
                           "height",
                           s));
  return {v[0], v[1], v[2], v[3], true};
}

Alignment parse_alignment(std::string_view s, int line) {
  Alignment result;
  if (s.empty()) return result;
  Phrase p(s);
  p.word("defer");
  constexpr std::pair<std::string_view, std::pair<Align, Align>> kAligns[] = {
      {"none", {Align::None, Align::None}},    {"xMinYMin", {Align::Min, Align::Min}},
      {"xMidYMin", {Align::Mid, Align::Min}},  {"xMaxYMin", {Align::Max, Align::Min}},
      {"xMinYMid", {Align::Min, Align::Mid}},  {"xMidYMid", {Align::Mid, Align::Mid}},
      {"xMaxYMid", {Align::Max, Align::Mid}},  {"xMinYMax", {Align::Min, Align::Max}},
      {"xMidYMax", {Align::Mid, Align::Max}},  {"xMaxYMax", {Align::Max, Align::Max}}};
  bool found = false;
  for (const auto& [name, xy] : kAligns)
    if (p.word(name)) {
      std::tie(result.x, result.y) = xy;
      found = true;
      break;
    }
  if (found && p.word("slice")) result.meet = false;
  else if (found) p.word("meet");
  if (!found || !p.at_end())
    fail(line, fmt::format("the preserveAspectRatio '{}' is not read (OpenSCAD 2021.01 reads xMidYMid meet for it)",
                           s));
  return result;
}

// import_svg.cc's to_mm: a page length in millimetres.
double to_mm(const Length& length, double viewbox, bool viewbox_valid, double dpi) {
  switch (length.unit) {
    case Unit::None: return kInchToMm * length.number / dpi;
    case Unit::Px: return kInchToMm * length.number / 96.0;
    case Unit::Pt: return kInchToMm * length.number / 72.0;
    case Unit::Pc: return kInchToMm * length.number / 6.0;
    case Unit::In: return kInchToMm * length.number;
    case Unit::Cm: return 10 * length.number;
    case Unit::Mm: return length.number;
    case Unit::Undefined: return viewbox_valid ? kInchToMm * viewbox / dpi : 0.0;
    default: return viewbox_valid ? viewbox : 0.0;  // %, em, ex: the viewBox's size as millimetres
  }
}

double alignment_offset(Align a, double page_mm, double scale, double viewbox) {
  switch (a) {
    case Align::Mid: return page_mm / 2.0 - scale * viewbox / 2.0;
    case Align::Max: return page_mm - scale * viewbox;
    default: return 0.0;
  }
}

// boost::split_dots of path.cc: "1.5.5" is "1.5" and ".5".
std::vector<std::string> split_dots(const std::string& s, int line) {
  if (std::count(s.begin(), s.end(), '.') < 2) return {s};
  std::vector<std::string> result;
  std::string text;
  bool dot_seen = false;
  for (const std::string& token : tokenize(s, "", ".")) {
    text += token;
    if (token == ".") {
      dot_seen = true;
    } else if (dot_seen) {
      result.push_back(std::move(text));
      text.clear();
    }
  }
  if (!text.empty()) fail(line, fmt::format("the path's number '{}' is not a number", s));
  return result;
}

struct Node {
  int parent = -1;
  std::vector<Affine> transform;  // in the order they apply
};

// A shape's outlines (OpenSCAD's path_list after apply_transform), or a page.
struct Item {
  bool page = false;
  Length width, height;
  ViewBox viewbox;
  Alignment alignment;
  PathList paths;
  int line = 0;
};

enum class Kind { None, Svg, Group, Text, Path, Rect, Circle, Ellipse, Line, Polygon, Polyline };

Kind kind_of(std::string_view name) {
  constexpr std::pair<std::string_view, Kind> kKinds[] = {
      {"svg", Kind::Svg},         {"g", Kind::Group},         {"text", Kind::Text},       {"tspan", Kind::Text},
      {"path", Kind::Path},       {"rect", Kind::Rect},       {"circle", Kind::Circle},   {"ellipse", Kind::Ellipse},
      {"line", Kind::Line},       {"polygon", Kind::Polygon}, {"polyline", Kind::Polyline}};
  for (const auto& [n, k] : kKinds)
    if (n == name) return k;
  return Kind::None;
}

#if LIBXML_VERSION >= 21200
using XmlErrorArg = const xmlError*;
#else
using XmlErrorArg = xmlErrorPtr;
#endif

struct XmlErrors {
  int line = 0;
  std::string message;
};

void record_error(void* sink, XmlErrorArg error) {
  auto* errors = static_cast<XmlErrors*>(sink);
  if (error == nullptr || error->level < XML_ERR_ERROR || !errors->message.empty()) return;
  errors->line = error->line;
  errors->message = error->message ? error->message : "unknown error";
  while (!errors->message.empty() && is_space(errors->message.back())) errors->message.pop_back();
}

struct ReaderFree {
  void operator()(xmlTextReader* r) const { libxml2().xmlFreeTextReader(r); }
};
struct XmlFree {
  void operator()(xmlChar* s) const { libxml2().free(s); }
};

class Reader {
 public:
  Reader(std::string_view text, const SvgOptions& o) : text_(text), o_(o), xml_(libxml2()) {}

  Polygon2d read() {
    parse_xml();
    return place();
  }

 private:
  void parse_xml() {
    if (text_.find_first_not_of(" \t\r\n") == std::string_view::npos) fail(1, "the file is empty");
    if (text_.size() > static_cast<std::size_t>(INT_MAX)) fail(1, "the file is too large for the XML reader");
    // No network, no external DTD, no entity substitution: a drawing reads
    // nothing but itself.
    std::unique_ptr<xmlTextReader, ReaderFree> reader(
        xml_.xmlReaderForMemory(text_.data(), static_cast<int>(text_.size()), nullptr, nullptr,
                                XML_PARSE_NONET | XML_PARSE_BIG_LINES));
    if (!reader) fail(1, "the XML reader cannot start");
    XmlErrors errors;
    xml_.xmlTextReaderSetStructuredErrorHandler(reader.get(), record_error, &errors);
    int ret = 0;
    while ((ret = xml_.xmlTextReaderRead(reader.get())) == 1) node(reader.get());
    if (ret != 0 || !errors.message.empty())
      fail(errors.line > 0 ? errors.line : xml_.xmlTextReaderGetParserLineNumber(reader.get()),
           fmt::format("the file is not well-formed XML: {}", errors.message.empty() ? "unreadable" : errors.message));
  }

  // libsvg.cc's processNode.
  void node(xmlTextReader* r) {
    const int type = xml_.xmlTextReaderNodeType(r);
    if (type != XML_READER_TYPE_ELEMENT && type != XML_READER_TYPE_END_ELEMENT &&
        type != XML_READER_TYPE_ENTITY_REFERENCE)
      return;
    const xmlChar* raw = xml_.xmlTextReaderConstName(r);
    const std::string_view name = raw ? reinterpret_cast<const char*>(raw) : "--";
    const xmlNode* current = xml_.xmlTextReaderCurrentNode(r);
    line_ = current ? static_cast<int>(xml_.xmlGetLineNo(current)) : xml_.xmlTextReaderGetParserLineNumber(r);
    if (type == XML_READER_TYPE_ENTITY_REFERENCE)
      fail(line_, fmt::format("the entity reference '&{};' (in the element of this line) is not read: capsim "
                              "expands no entities in content (OpenSCAD 2021.01 does)",
                              name));
    if (type == XML_READER_TYPE_ELEMENT) {
      const bool empty = xml_.xmlTextReaderIsEmptyElement(r) == 1;
      start(name, r);
      if (!empty) return;
    }
    if (name == "defs") in_defs_ = false;
    if (in_defs_) return;
    if ((name == "g" || name == "tspan" || name == "text") && !stack_.empty()) stack_.pop_back();
  }

  Attrs attributes(xmlTextReader* r) {
    Attrs attrs;
    while (xml_.xmlTextReaderMoveToNextAttribute(r) == 1) {
      const xmlChar* name = xml_.xmlTextReaderConstName(r);
      std::unique_ptr<xmlChar, XmlFree> value(xml_.xmlTextReaderValue(r));
      attrs[name ? reinterpret_cast<const char*>(name) : ""] = value ? reinterpret_cast<const char*>(value.get()) : "";
    }
    xml_.xmlTextReaderMoveToElement(r);
    return attrs;
  }

  static const std::string& get(const Attrs& attrs, std::string_view name) {
    static const std::string none;
    const auto found = attrs.find(name);
    return found == attrs.end() ? none : found->second;
  }

  void start(std::string_view name, xmlTextReader* r) {
    if (name == "defs") in_defs_ = true;
    const Kind kind = kind_of(name);
    if (kind == Kind::None || in_defs_) return;
    if (first_line_ == 0) first_line_ = line_;
    const Attrs attrs = attributes(r);
    attrs_ = &attrs;
    Item item;
    item.line = line_;
    Node n;
    n.parent = stack_.empty() ? -1 : stack_.back();
    if (kind == Kind::Svg) {
      // svgpage reads no transform of its own.
      item.page = true;
      item.width = parse_length(get(attrs, "width"), line_, "the svg element's width");
      item.height = parse_length(get(attrs, "height"), line_, "the svg element's height");
      item.viewbox = parse_viewbox(get(attrs, "viewBox"), line_);
      item.alignment = parse_alignment(get(attrs, "preserveAspectRatio"), line_);
    } else {
      n.transform = parse_transform(get(attrs, "transform"), line_);
      item.paths = shape_paths(kind, name);
    }
    nodes_.push_back(std::move(n));
    const int index = static_cast<int>(nodes_.size()) - 1;
    if (kind == Kind::Svg || kind == Kind::Group || kind == Kind::Text) stack_.push_back(index);
    transform(index, item.paths);
    items_.push_back(std::move(item));
    attrs_ = nullptr;
  }

  // shape::apply_transform: the matrices of the shape and of every
  // ancestor but the outermost, each applied in turn.
  void transform(int index, PathList& paths) {
    std::vector<const std::vector<Affine>*> chain;
    std::size_t count = 0;
    for (int k = index; nodes_[static_cast<std::size_t>(k)].parent >= 0; k = nodes_[static_cast<std::size_t>(k)].parent) {
      chain.push_back(&nodes_[static_cast<std::size_t>(k)].transform);
      count += chain.back()->size();
    }
    if (count == 0) return;
    for (Path& p : paths) {
      transform_work_ += static_cast<double>(count) * static_cast<double>(p.size());
      if (transform_work_ > kMaxTransformWork)
        fail(line_, fmt::format("the transforms above the shapes take more than {:g} point transforms",
                                kMaxTransformWork));
      for (glm::dvec2& v : p)
        for (const std::vector<Affine>* t : chain)
          for (const Affine& m : *t) v = m.apply(v);
    }
  }

  PathList shape_paths(Kind kind, std::string_view name) {
    const Attrs& a = *attrs_;
    auto num = [&](std::string_view attr) {
      return number(get(a, attr), line_, fmt::format("the {}'s {}", name, attr));
    };
    PathList paths;
    switch (kind) {
      case Kind::Path: return path_data(get(a, "d"));
      case Kind::Rect: return rect(num("x"), num("y"), num("width"), num("height"), num("rx"), num("ry"));
      case Kind::Circle: {
        const double cx = num("cx"), cy = num("cy"), r = num("r");
        paths.push_back(ellipse(cx, cy, r, r));
        return paths;
      }
      case Kind::Ellipse: {
        const double cx = num("cx"), cy = num("cy"), rx = num("rx"), ry = num("ry");
        paths.push_back(ellipse(cx, cy, rx, ry));
        return paths;
      }
      case Kind::Line: {
        const double x1 = num("x1"), y1 = num("y1"), x2 = num("x2"), y2 = num("y2");
        Path line;
        add(line, {x1, y1});
        add(line, {x2, y2});
        stroke(paths, line);
        return paths;
      }
      case Kind::Polygon:
      case Kind::Polyline: {
        Path path;
        const std::vector<std::string> tokens = tokenize(get(a, "points"), " ,", "");
        if (tokens.size() % 2 != 0)
          fail(line_, fmt::format("the {}'s points are {} numbers, not pairs (OpenSCAD 2021.01 drops the last)", name,
                                  tokens.size()));
        for (std::size_t k = 0; k < tokens.size(); k += 2)
          add(path, {number(tokens[k], line_, fmt::format("the {}'s point", name)),
                     number(tokens[k + 1], line_, fmt::format("the {}'s point", name))});
        if (kind == Kind::Polyline) {
          stroke(paths, path);
        } else {
          if (!path.empty()) add(path, path.front());
          paths.push_back(std::move(path));
        }
        return paths;
      }
      default: return paths;  // svg, g, text, tspan: no outline of their own
    }
  }

  void add(Path& path, const glm::dvec2& v) {
    if (++points_ > kMaxSvgPoints)
      fail(line_, fmt::format("more than {} points (the curves, arcs and strokes included)", kMaxSvgPoints));
    path.push_back(v);
  }

  // shape::draw_ellipse: 40 points.
  Path ellipse(double x, double y, double rx, double ry) {
    Path path;
    constexpr unsigned long kFn = 40;
    for (unsigned long idx = 1; idx <= kFn; ++idx) {
      const double a = static_cast<double>(idx) * 360.0 / kFn;
      add(path, {rx * sin_degrees(a) + x, ry * cos_degrees(a) + y});
    }
    return path;
  }

  // rect.cc: square corners as 4 points, round ones as a path written with
  // boost::format's 6 significant digits.
  PathList rect(double x, double y, double width, double height, double rx, double ry) {
    const bool has_rx = !(std::fabs(rx) < 1e-8), has_ry = !(std::fabs(ry) < 1e-8);
    if (has_rx || has_ry) {
      if (!has_rx) rx = ry;
      else if (!has_ry) ry = rx;
      if (rx > width / 2) rx = width / 2;
      if (ry > height / 2) ry = height / 2;
      const std::string d = fmt::format(
          "M {:.6g},{:.6g} H {:.6g} A {:.6g},{:.6g} 0 0,1 {:.6g},{:.6g} V {:.6g} A {:.6g},{:.6g} 0 0,1 {:.6g},{:.6g} "
          "H {:.6g} A {:.6g},{:.6g} 0 0,1 {:.6g},{:.6g} V {:.6g} A {:.6g},{:.6g} 0 0,1 {:.6g},{:.6g} z",
          x + rx, y, x + width - rx, rx, ry, x + width, y + ry, y + height - ry, rx, ry, x + width - rx, y + height,
          x + rx, rx, ry, x, y + height - ry, y + ry, rx, ry, x + rx, y);
      return path_data(d);
    }
    Path path;
    for (const glm::dvec2& v : {glm::dvec2(x, y), glm::dvec2(x + width, y), glm::dvec2(x + width, y + height),
                                glm::dvec2(x, y + height), glm::dvec2(x, y)})
      add(path, v);
    return {path};
  }

  // shape's stroke attributes, or their style properties.
  std::string style(std::string_view property) const {
    const std::string& s = get(*attrs_, "style");
    for (const std::string& declaration : tokenize(s, ";", "")) {
      const std::size_t colon = declaration.find(':');
      if (colon == std::string::npos || declaration.find(':', colon + 1) != std::string::npos) continue;
      if (std::string_view(declaration).substr(0, colon) == property) return declaration.substr(colon + 1);
    }
    return {};
  }
  std::string stroke_attribute(std::string_view property) const {
    const std::string& given = get(*attrs_, property);
    return given.empty() ? style(property) : given;
  }

  // shape::offset_path: an open outline becomes the outline of its stroke,
  // Clipper's offset by half the stroke-width (at least 0.01, else 1) in
  // integers of 1/10000 unit.
  void stroke(PathList& out, const Path& path) {
    double width = number(stroke_attribute("stroke-width"), line_, "the stroke-width");
    if (width < 0.01) width = 1;
    const std::string cap = stroke_attribute("stroke-linecap"), join = stroke_attribute("stroke-linejoin");
    const ClipperLib::EndType end = cap == "butt" ? ClipperLib::etOpenButt
                                    : cap == "round" ? ClipperLib::etOpenRound
                                                     : ClipperLib::etOpenSquare;
    const ClipperLib::JoinType joint = join == "bevel" ? ClipperLib::jtSquare
                                       : join == "round" ? ClipperLib::jtRound
                                                         : ClipperLib::jtMiter;
    if (!(width <= kMaxStrokeCoordinate))
      fail(line_, fmt::format("the stroke-width {} is beyond the {:g} capsim strokes", width, kMaxStrokeCoordinate));
    ClipperLib::Path line;
    for (const glm::dvec2& v : path) {
      if (!(std::abs(v.x) <= kMaxStrokeCoordinate && std::abs(v.y) <= kMaxStrokeCoordinate))
        fail(line_, fmt::format("a stroked outline reaches ({}, {}), beyond the {:g} capsim strokes", v.x, v.y,
                                kMaxStrokeCoordinate));
      line.emplace_back(static_cast<ClipperLib::cInt>(v.x * kStrokeScale),
                        static_cast<ClipperLib::cInt>(v.y * kStrokeScale));
    }
    const double delta = width * kStrokeScale / 2;
    if (joint == ClipperLib::jtRound || end == ClipperLib::etOpenRound) bound_round_stroke(line, delta);
    ClipperLib::ClipperOffset offset;
    ClipperLib::Paths result;
    try {
      offset.AddPath(line, joint, end);
      offset.Execute(result, delta);
    } catch (const ClipperLib::clipperException& e) {
      fail(line_, fmt::format("the stroke cannot be offset: {}", e.what()));
    }
    for (const ClipperLib::Path& p : result) {
      Path outline;
      for (const ClipperLib::IntPoint& q : p)
        add(outline, {static_cast<double>(q.X) / kStrokeScale, static_cast<double>(q.Y) / kStrokeScale});
      add(outline, {static_cast<double>(p[0].X) / kStrokeScale, static_cast<double>(p[0].Y) / kStrokeScale});
      out.push_back(std::move(outline));
    }
  }

  // Round joins and caps take Clipper's steps per radian (its arc tolerance
  // 0.25 of an integer unit) times the angle turned: refused before Clipper
  // makes them when they would pass the points' bound.
  void bound_round_stroke(const ClipperLib::Path& line, double delta) const {
    double steps = std::numbers::pi / std::acos(1 - 0.25 / delta);
    steps = std::min(steps, delta * std::numbers::pi);
    double turned = 2 * std::numbers::pi;  // the two caps
    for (std::size_t k = 1; k + 1 < line.size(); ++k) {
      const double ux = static_cast<double>(line[k].X - line[k - 1].X), uy = static_cast<double>(line[k].Y - line[k - 1].Y);
      const double vx = static_cast<double>(line[k + 1].X - line[k].X), vy = static_cast<double>(line[k + 1].Y - line[k].Y);
      turned += std::abs(std::atan2(ux * vy - uy * vx, ux * vx + uy * vy));
    }
    const double estimate = steps / (2 * std::numbers::pi) * turned + 8.0 * static_cast<double>(line.size() + 2);
    if (static_cast<double>(points_) + estimate > static_cast<double>(kMaxSvgPoints))
      fail(line_, fmt::format("the stroke's round joins and caps would make more than {} points (the stroke-width "
                              "is {:g})",
                              kMaxSvgPoints, delta * 2 / kStrokeScale));
  }

  // path::is_open_path.
  static bool is_open(const Path& path) {
    const glm::dvec2 p1 = path[0], p2 = path.back();
    return std::pow(std::pow(p1.x - p2.x, 2) + std::pow(p1.y - p2.y, 2) + std::pow(0.0, 2), 0.5) > 0.1;
  }

  void check_finite(const Path& path, std::size_t from, std::string_view what) const {
    for (std::size_t k = from; k < path.size(); ++k)
      if (!std::isfinite(path[k].x) || !std::isfinite(path[k].y))
        fail(line_, fmt::format("{} has points that are not finite in OpenSCAD 2021.01", what));
  }

  // path::arc_to (the SVG implementation notes, F.6.5): 4 + 10 segments
  // per 180 degrees.
  void arc_to(Path& path, double x1, double y1, double rx, double ry, double x2, double y2, double angle, bool large,
              bool sweep) {
    const double cos_rad = cos_degrees(angle), sin_rad = sin_degrees(angle);
    const double dx = (x1 - x2) / 2, dy = (y1 - y2) / 2;
    const double x1_ = cos_rad * dx + sin_rad * dy, y1_ = -sin_rad * dx + cos_rad * dy;
    const double d = (x1_ * x1_) / (rx * rx) + (y1_ * y1_) / (ry * ry);
    if (d > 1) {
      rx = std::fabs(std::sqrt(d) * rx);
      ry = std::fabs(std::sqrt(d) * ry);
    }
    double t1 = rx * rx * ry * ry - rx * rx * y1_ * y1_ - ry * ry * x1_ * x1_;
    const double t2 = rx * rx * y1_ * y1_ + ry * ry * x1_ * x1_;
    if (t1 < 0) t1 = 0;
    double t3 = std::sqrt(t1 / t2);
    if (large == sweep) t3 = -t3;
    const double cx_ = t3 * rx * y1_ / ry, cy_ = t3 * -ry * x1_ / rx;
    const double cx = cos_rad * cx_ - sin_rad * cy_ + (x1 + x2) / 2.0;
    const double cy = sin_rad * cx_ + cos_rad * cy_ + (y1 + y2) / 2.0;
    const double ux = (x1_ - cx_) / rx, uy = (y1_ - cy_) / ry, vx = (-x1_ - cx_) / rx, vy = (-y1_ - cy_) / ry;
    auto vector_angle = [](double ax, double ay, double bx, double by) {
      double a = atan2_degrees(by, bx) - atan2_degrees(ay, ax);
      return a < 0 ? a + 360 : a;
    };
    const double theta = vector_angle(1, 0, ux, uy);
    double delta = vector_angle(ux, uy, vx, vy);
    if (!sweep) delta -= 360;
    if (!std::isfinite(cx) || !std::isfinite(cy) || !std::isfinite(theta) || !std::isfinite(delta))
      fail(line_, fmt::format("the arc from ({}, {}) to ({}, {}) has a zero radius or ends where it starts: "
                              "OpenSCAD 2021.01 computes no finite points for it",
                              x1, y1, x2, y2));
    const int steps = static_cast<int>(std::fabs(delta) * 10.0 / 180 + 4);
    for (int a = 0; a <= steps; ++a) {
      const double phi = theta + delta * a / steps;
      const double xx = cos_rad * cos_degrees(phi) * rx - sin_rad * sin_degrees(phi) * ry;
      const double yy = sin_rad * cos_degrees(phi) * rx + cos_rad * sin_degrees(phi) * ry;
      add(path, {xx + cx, yy + cy});
    }
  }

  // path::curve_to: 20 segments for a quadratic or a cubic Bezier curve.
  void quadratic_to(Path& path, double x, double y, double cx1, double cy1, double x2, double y2) {
    constexpr unsigned long kFn = 20;
    for (unsigned long idx = 1; idx <= kFn; ++idx) {
      const double a = static_cast<double>(idx) * (1.0 / static_cast<double>(kFn));
      add(path, {x * std::pow(1.0 - a, 2) + cx1 * 2 * std::pow(1.0 - a, 1) * a + x2 * a * a,
                 y * std::pow(1.0 - a, 2) + cy1 * 2 * std::pow(1.0 - a, 1) * a + y2 * a * a});
    }
  }
  void cubic_to(Path& path, double x, double y, double cx1, double cy1, double cx2, double cy2, double x2, double y2) {
    constexpr unsigned long kFn = 20;
    for (unsigned long idx = 1; idx <= kFn; ++idx) {
      const double a = static_cast<double>(idx) * (1.0 / static_cast<double>(kFn));
      add(path, {x * std::pow(1.0 - a, 3) + cx1 * 3 * std::pow(1.0 - a, 2) * a +
                     cx2 * 3 * std::pow(1.0 - a, 1) * a * a + x2 * a * a * a,
                 y * std::pow(1.0 - a, 3) + cy1 * 3 * std::pow(1.0 - a, 2) * a +
                     cy2 * 3 * std::pow(1.0 - a, 1) * a * a + y2 * a * a * a});
    }
  }

  // path::set_attrs: the path data's commands, each point as OpenSCAD
  // computes it; a subpath that does not come back within 0.1 of its start
  // is stroked, unless the data closes some subpath with z (then the last
  // one is left as drawn, closed by the even-odd rule).
  PathList path_data(std::string_view d) {
    constexpr std::string_view kCommands = "-zmlcqahvstZMLCQAHVST";
    std::vector<std::string> tokens;
    for (const std::string& token : tokenize(d, " ,", kCommands))
      for (std::string& part : split_dots(token, line_)) tokens.push_back(std::move(part));

    // The command's numbers come in groups; each group draws when it is
    // whole, in path.cc's arithmetic (relative numbers added to the current
    // point, a smooth curve's first control point the reflection of the
    // last one).
    auto arity = [](char c) -> std::size_t {
      switch (c | 0x20) {
        case 'h':
        case 'v': return 1;
        case 'm':
        case 'l':
        case 't': return 2;
        case 's':
        case 'q': return 4;
        case 'c': return 6;
        case 'a': return 7;
        default: return 0;
      }
    };
    double x = 0, y = 0, cx1 = 0, cy1 = 0, cx2 = 0, cy2 = 0;
    bool last_cubic = false, last_quadratic = false, negate = false, closed = false;
    char cmd = ' ';
    int given = 0;  // numbers since the command
    std::vector<double> a;  // the group's numbers
    std::string exp;
    PathList list(1);
    auto complete = [&] {
      if (negate || !exp.empty())
        fail(line_, fmt::format("the path data has '{}{}' where a number should be", exp, negate ? "-" : ""));
      if (arity(cmd) > 0 && (given == 0 || !a.empty()))
        fail(line_, fmt::format("the path's '{}' command lacks numbers (OpenSCAD 2021.01 drops the incomplete "
                                "segment)",
                                cmd));
    };
    auto flag = [&](double p) {
      if (p != 0 && p != 1)
        fail(line_, fmt::format("the arc's flag {} is not 0 or 1 (OpenSCAD 2021.01 reads flags as separate "
                                "numbers)",
                                p));
      return p > 0.5;
    };
    auto draw = [&] {
      const bool relative = cmd >= 'a' && cmd <= 'z';
      auto ax = [&](std::size_t k) { return relative ? x + a[k] : a[k]; };
      auto ay = [&](std::size_t k) { return relative ? y + a[k] : a[k]; };
      Path& path = list.back();
      const std::size_t before = path.size();
      const char c = static_cast<char>(cmd | 0x20);
      glm::dvec2 end(x, y);
      if (c == 'm') {
        end = {ax(0), ay(1)};
        cmd = relative ? 'l' : 'L';  // further pairs draw lines
        if (!list.back().empty()) {
          if (is_open(list.back())) {
            const Path open = std::move(list.back());
            list.pop_back();
            stroke(list, open);
          }
          list.emplace_back();
        }
        add(list.back(), end);
      } else if (c == 'l' || c == 'h' || c == 'v') {
        end = c == 'l' ? glm::dvec2(ax(0), ay(1)) : c == 'h' ? glm::dvec2(ax(0), y) : glm::dvec2(x, ay(0));
        add(path, end);
      } else if (c == 'c' || c == 's') {
        if (c == 'c') cx1 = ax(0), cy1 = ay(1);
        else if (last_cubic) cx1 = x + (x - cx2), cy1 = y + (y - cy2);
        else cx1 = x, cy1 = y;
        const std::size_t k = c == 'c' ? 2 : 0;
        cx2 = ax(k), cy2 = ay(k + 1), end = {ax(k + 2), ay(k + 3)};
        cubic_to(path, x, y, cx1, cy1, cx2, cy2, end.x, end.y);
      } else if (c == 'q' || c == 't') {
        if (c == 'q') cx1 = ax(0), cy1 = ay(1);
        else if (last_quadratic) cx1 = x + (x - cx1), cy1 = y + (y - cy1);
        else cx1 = x, cy1 = y;
        const std::size_t k = c == 'q' ? 2 : 0;
        end = {ax(k), ay(k + 1)};
        quadratic_to(path, x, y, cx1, cy1, end.x, end.y);
      } else {
        end = {ax(5), ay(6)};
        arc_to(path, x, y, std::fabs(a[0]), std::fabs(a[1]), end.x, end.y, a[2], flag(a[3]), flag(a[4]));
      }
      if (c != 'm' && path.size() > before) check_finite(path, before, "the path");  // a move may re-seat `path`
      x = end.x, y = end.y;
      last_cubic = c == 'c' || c == 's';
      last_quadratic = c == 'q' || c == 't';
      a.clear();
    };
    for (const std::string& v : tokens) {
      if (v.size() == 1 && kCommands.find(v[0]) != std::string_view::npos) {
        if (v[0] == '-') {
          if (negate) fail(line_, "the path data has '--' where a number should be");
          negate = true;
          continue;
        }
        complete();
        cmd = v[0];
        given = 0;
        if (cmd == 'z' || cmd == 'Z') {
          if (!list.back().empty()) {
            const glm::dvec2 first = list.back().front();
            add(list.back(), first);
            x = first.x, y = first.y;
          }
          list.emplace_back();
          closed = true;
          last_cubic = last_quadratic = false;
        }
        continue;
      }
      if (v.back() == 'e') {
        if (!exp.empty()) fail(line_, fmt::format("the path's number '{}' is not a number", exp + v));
        exp = negate ? "-" + v : v;
        negate = false;
        continue;
      }
      if (std::isalpha(static_cast<unsigned char>(v[0])))
        fail(line_, fmt::format("the path command '{}' is not one of M, L, H, V, C, S, Q, T, A, Z (or their lower "
                                "case)",
                                v[0]));
      double p = number(exp + (exp.empty() || !negate ? "" : "-") + v, line_, "the path's number");
      if (exp.empty() && negate) p = -p;
      exp.clear();
      negate = false;
      if (cmd == ' ') fail(line_, "the path data starts with a number, not a command (OpenSCAD 2021.01 skips it)");
      if (cmd == 'z' || cmd == 'Z')
        fail(line_, "the path data has a number after z (OpenSCAD 2021.01 closes the path again for it)");
      ++given;
      a.push_back(p);
      if (a.size() == arity(cmd)) draw();
    }
    complete();
    while (!list.empty() && list.back().empty()) list.pop_back();
    if (!closed && !list.empty() && is_open(list.back())) {
      const Path open = std::move(list.back());
      list.pop_back();
      stroke(list, open);
    }
    return list;
  }

  // import_svg.cc: the pages' sizes, viewBoxes and alignments give the scale
  // and offset from user units to millimetres; y turns up about the page's
  // height (or the centre of the drawing's box, with center); the shapes,
  // each under the even-odd rule, are united.
  Polygon2d place() {
    double width_mm = 0, height_mm = 0;
    glm::dvec2 scale(1.0), align(0.0), viewbox(0.0);
    glm::dvec2 lo(std::numeric_limits<double>::max()), hi(std::numeric_limits<double>::lowest());
    for (const Item& item : items_) {
      if (item.page) {
        const ViewBox& box = item.viewbox;
        width_mm = to_mm(item.width, box.width, box.valid, o_.dpi);
        height_mm = to_mm(item.height, box.height, box.valid, o_.dpi);
        if (box.valid) {
          viewbox = {box.x, box.y};
          scale = {width_mm / box.width, height_mm / box.height};
          if (item.alignment.x != Align::None) {
            // meet: the smaller scale fits the viewport, slice: the larger fills it.
            const double s = item.alignment.meet ? std::min(scale.x, scale.y) : std::max(scale.x, scale.y);
            scale = {s, s};
            align = {alignment_offset(item.alignment.x, width_mm, scale.x, box.width),
                     alignment_offset(item.alignment.y, height_mm, scale.y, box.height)};
          }
        }
      }
      for (const Path& p : item.paths)
        for (const glm::dvec2& v : p) {
          const glm::dvec2 s(scale.x * v.x, scale.y * v.y);
          lo = glm::min(lo, s), hi = glm::max(hi, s);
        }
    }
    const glm::dvec2 middle = (lo + hi) / 2.0;
    const double cx = o_.center ? middle.x : -align.x;
    const double cy = o_.center ? middle.y : height_mm - align.y;
    std::vector<Polygon2d> shapes;
    for (const Item& item : items_) {
      if (item.paths.empty()) continue;
      Polygon2d shape;
      for (const Path& p : item.paths) {
        Outline2d outline;
        for (const glm::dvec2& v : p) {
          // As OpenSCAD 2021.01: the viewBox's y is added where SVG subtracts it.
          const glm::dvec2 w(scale.x * (-viewbox.x + v.x) - cx, scale.y * (-viewbox.y - v.y) + cy);
          if (!(std::abs(w.x) <= kMaxClippedCoordinate && std::abs(w.y) <= kMaxClippedCoordinate))
            fail(item.line, fmt::format("the shape reaches ({}, {}) mm, beyond the {:g} capsim's clipping holds", w.x,
                                        w.y, kMaxClippedCoordinate));
          outline.vertices.push_back(w);
        }
        shape.outlines.push_back(std::move(outline));
      }
      shapes.push_back(std::move(shape));
    }
    const int line = first_line_ > 0 ? first_line_ : 1;
    Polygon2d result;
    try {
      result = clip_shapes(shapes, ClipperLib::ctUnion);
    } catch (const ClipperRangeError& e) {
      fail(line, e.what());
    }
    if (result.outlines.empty())
      fail(line, "the file draws nothing: no rect, circle, ellipse, line, polygon, polyline or path with an area "
                 "outside defs");
    return result;
  }

  std::string_view text_;
  const SvgOptions& o_;
  const Libxml2& xml_;
  int line_ = 1, first_line_ = 0;
  bool in_defs_ = false;
  std::vector<int> stack_;  // the open svg, g, text and tspan elements
  std::vector<Node> nodes_;
  std::vector<Item> items_;
  const Attrs* attrs_ = nullptr;  // of the element being read
  std::size_t points_ = 0;
  double transform_work_ = 0;
};

}  // namespace

Polygon2d read_svg(std::string_view text, const SvgOptions& options) { return Reader(text, options).read(); }

}  // namespace capsim::scene_file
