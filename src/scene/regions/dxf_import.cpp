// OpenSCAD's DxfData reader (dxfdata.cc of 2021.01): the same group codes,
// grid snapping and joining of segments, so that the contours have
// OpenSCAD's vertices.

#include "scene/regions/dxf_import.h"

#include "scene/reading/scene_expression.h"
#include "scene/regions/text_glyphs.h"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <map>
#include <unordered_map>
#include <vector>

namespace capsim::scene_file {

namespace {

// OpenSCAD's GRID_COARSE: end points closer than this are one point.
constexpr double kGridCoarse = 0.0009765625;

// OpenSCAD's Grid2d: cells of kGridCoarse; a point snaps to its own cell, or
// to the nearest used cell around it.
class Grid {
 public:
  std::vector<int>& align(double& x, double& y) {
    std::int64_t ix = static_cast<std::int64_t>(std::round(x / kGridCoarse));
    std::int64_t iy = static_cast<std::int64_t>(std::round(y / kGridCoarse));
    if (cells_.find(key(ix, iy)) == cells_.end()) {
      int dist = 10;
      for (std::int64_t jx = ix - 1; jx <= ix + 1; ++jx)
        for (std::int64_t jy = iy - 1; jy <= iy + 1; ++jy) {
          if (cells_.find(key(jx, jy)) == cells_.end()) continue;
          const int d = static_cast<int>(std::abs(ix - jx) + std::abs(iy - jy));
          if (d < dist) dist = d, ix = jx, iy = jy;
        }
    }
    x = static_cast<double>(ix) * kGridCoarse;
    y = static_cast<double>(iy) * kGridCoarse;
    return cells_[key(ix, iy)];
  }
  bool eq(double x1, double y1, double x2, double y2) {
    align(x1, y1);
    align(x2, y2);
    return std::abs(x1 - x2) < kGridCoarse && std::abs(y1 - y2) < kGridCoarse;
  }

 private:
  struct Hash {
    std::size_t operator()(const std::pair<std::int64_t, std::int64_t>& k) const {
      return std::hash<std::int64_t>()(k.first) * 1000003u ^ std::hash<std::int64_t>()(k.second);
    }
  };
  static std::pair<std::int64_t, std::int64_t> key(std::int64_t x, std::int64_t y) { return {x, y}; }
  std::unordered_map<std::pair<std::int64_t, std::int64_t>, std::vector<int>, Hash> cells_;
};

struct Segment {
  int idx[2];
  int dxf_line;  // the entity's first line, for errors
  bool disabled = false;
};

std::string_view trim(std::string_view s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
  return s;
}

class Reader {
 public:
  Reader(std::string_view text, const DxfOptions& o) : text_(text), o_(o) {}

  Polygon2d read() {
    parse();
    return contours();
  }

 private:
  [[noreturn]] void fail(int line, const std::string& message) const {
    throw DxfError(fmt::format("{}: {}", line, message));
  }

  bool next_line(std::string_view& out) {
    if (pos_ >= text_.size()) return false;
    const std::size_t end = std::min(text_.find('\n', pos_), text_.size());
    out = trim(text_.substr(pos_, end - pos_));
    pos_ = end + 1;
    ++line_;
    return true;
  }

  double number(std::string_view data) const {
    double v = 0;
    const char* first = data.data();
    if (!data.empty() && data.front() == '+') ++first;
    const auto [end, ec] = std::from_chars(first, data.data() + data.size(), v);
    if (ec != std::errc() || end != data.data() + data.size() || !std::isfinite(v) || !(std::abs(v) <= 1e30))
      fail(line_, fmt::format("the value '{}' is not a number within 1e30", data));
    return v;
  }

  double at(const std::vector<double>& v, std::size_t i) const {
    if (i >= v.size()) fail(entity_line_, fmt::format("the {} entity lacks coordinates", mode_));
    return v[i];
  }

  int fragments(double r) const {
    try {
      return openscad_fragments(r, o_.fn, o_.fs, o_.fa);
    } catch (const TextError& e) {
      fail(entity_line_, fmt::format("the {} entity: {}", mode_, e.what()));
    }
  }

  int add_point(double x, double y) {
    points_.emplace_back(x, y);
    return static_cast<int>(points_.size()) - 1;
  }

  void add_line(double x1, double y1, double x2, double y2) {
    if (!in_entities_ && !in_blocks_) return;
    if (in_entities_ && !(o_.layer.empty() || o_.layer == layer_)) return;
    if (lines_.size() + points_.size() / 2 >= kMaxDxfSegments)
      fail(entity_line_, fmt::format("more than {} line segments (a circle or arc cut into too many by $fn, $fa "
                                     "and $fs, or too many entities)",
                                     kMaxDxfSegments));
    grid_.align(x1, y1);
    grid_.align(x2, y2);
    grid_.align(x1, y1).push_back(static_cast<int>(lines_.size()));
    grid_.align(x2, y2).push_back(static_cast<int>(lines_.size()));
    if (in_entities_) lines_.push_back({{add_point(x1, y1), add_point(x2, y2)}, entity_line_});
    if (in_blocks_ && !block_.empty()) blocks_[block_].push_back({{add_point(x1, y1), add_point(x2, y2)}, entity_line_});
  }

  void add_arc_lines(const glm::dvec2& c, double r, double a0, double sweep, int n) {
    for (int i = 0; i < n; ++i) {
      const double a1 = a0 + sweep * i / n, a2 = a0 + sweep * (i + 1) / n;
      add_line(cos_degrees(a1) * r + c.x, sin_degrees(a1) * r + c.y, cos_degrees(a2) * r + c.x,
               sin_degrees(a2) * r + c.y);
    }
  }

  // The entity just ended (its group code 0 reached): its lines.
  void finish_entity() {
    if (mode_ == "SECTION") {
      in_entities_ = id_ == "ENTITIES";
      in_blocks_ = id_ == "BLOCKS";
    } else if (mode_ == "LINE") {
      add_line(at(xs_, 0), at(ys_, 0), at(xs_, 1), at(ys_, 1));
    } else if (mode_ == "LWPOLYLINE") {
      const std::size_t n = std::max(xs_.size(), ys_.size());
      for (std::size_t i = 1; i < n; ++i) add_line(at(xs_, i - 1), at(ys_, i - 1), at(xs_, i), at(ys_, i));
      if ((flags_ & 1) && n > 0) add_line(at(xs_, n - 1), at(ys_, n - 1), at(xs_, 0), at(ys_, 0));
    } else if (mode_ == "CIRCLE") {
      const int n = fragments(radius_);
      add_arc_lines({at(xs_, 0), at(ys_, 0)}, radius_, 0, 360, n);
    } else if (mode_ == "ARC") {
      int n = fragments(radius_);
      if (!(arc_start_ <= 1e9 && arc_stop_ <= 1e9 && arc_start_ >= -1e9 && arc_stop_ >= -1e9))
        fail(entity_line_, "the ARC entity's angles are beyond 1e9 degrees");
      while (arc_start_ > arc_stop_) arc_stop_ += 360.0;
      const double sweep = arc_stop_ - arc_start_;
      if (sweep > 360.0 * 1000) fail(entity_line_, "the ARC entity turns more than 1000 times");
      n = static_cast<int>(std::ceil(n * sweep / 360));
      add_arc_lines({at(xs_, 0), at(ys_, 0)}, radius_, arc_start_, sweep, n);
    } else if (mode_ == "ELLIPSE") {
      finish_ellipse();
    } else if (mode_ == "INSERT") {
      finish_insert();
    } else if (mode_ == "BLOCK") {
      block_ = id_;
    } else if (mode_ == "ENDBLK") {
      block_.clear();
    } else if (mode_ == "DIMENSION" || mode_ == "ENDSEC" || mode_.empty()) {
      // A dimension is a measurement, not an outline; OpenSCAD keeps it for dxf_dim().
    } else if (in_blocks_ || (in_entities_ && (o_.layer.empty() || o_.layer == layer_))) {
      fail(entity_line_, fmt::format("the {} entity is not read (OpenSCAD skips it with a warning, and the outline "
                                     "would lack it); capsim reads LINE, LWPOLYLINE, CIRCLE, ARC, ELLIPSE and "
                                     "INSERT",
                                     mode_));
    }
  }

  void finish_ellipse() {
    if (!(std::abs(ellipse_start_) <= 1e9 && std::abs(ellipse_stop_) <= 1e9))
      fail(entity_line_, "the ELLIPSE entity's angles are beyond 1e9 radians");
    while (ellipse_start_ > ellipse_stop_) ellipse_stop_ += 2 * M_PI;
    const glm::dvec2 center(at(xs_, 0), at(ys_, 0));
    const glm::dvec2 ce(at(xs_, 1), at(ys_, 1));
    const double r_major = std::sqrt(ce.x * ce.x + ce.y * ce.y);
    double rot = std::acos(std::clamp(ce.x / r_major, -1.0, 1.0));
    if (ce.y < 0.0) rot = 2 * M_PI - rot;
    const double r_minor = r_major * radius_;  // code 40 holds the axis ratio here
    const double sweep = ellipse_stop_ - ellipse_start_;
    if (sweep > 2 * M_PI * 1000) fail(entity_line_, "the ELLIPSE entity turns more than 1000 times");
    int n = fragments(r_major);
    n = static_cast<int>(std::ceil(n * sweep / (2 * M_PI)));
    glm::dvec2 p1(0.0);
    for (int i = 0; i <= n; ++i) {
      const double a = ellipse_start_ + sweep * i / n;
      const glm::dvec2 p2(std::cos(a) * r_major, std::sin(a) * r_minor);
      const glm::dvec2 q(std::cos(rot) * p2.x - std::sin(rot) * p2.y + center.x,
                         std::sin(rot) * p2.x + std::cos(rot) * p2.y + center.y);
      if (i > 0) add_line(p1.x, p1.y, q.x, q.y);
      p1 = q;
    }
  }

  // A block's lines, scaled (codes 41, 42), turned (code 50) and placed.
  void finish_insert() {
    const auto found = blocks_.find(id_);
    if (found == blocks_.end()) return;
    const std::vector<Segment> block = found->second;  // add_line may add to blocks_
    const double a = arc_start_;
    for (const Segment& s : block) {
      const double lx1 = points_[s.idx[0]].x * ellipse_start_, ly1 = points_[s.idx[0]].y * ellipse_stop_;
      const double lx2 = points_[s.idx[1]].x * ellipse_start_, ly2 = points_[s.idx[1]].y * ellipse_stop_;
      add_line((cos_degrees(a) * lx1 - sin_degrees(a) * ly1) * o_.scale + at(xs_, 0),
               (sin_degrees(a) * lx1 + cos_degrees(a) * ly1) * o_.scale + at(ys_, 0),
               (cos_degrees(a) * lx2 - sin_degrees(a) * ly2) * o_.scale + at(xs_, 0),
               (sin_degrees(a) * lx2 + cos_degrees(a) * ly2) * o_.scale + at(ys_, 0));
    }
  }

  void start_entity(std::string_view data) {
    mode_ = std::string(data);
    entity_line_ = line_;  // the line naming the entity
    layer_.clear();
    id_.clear();
    flags_ = 0;
    xs_.clear();
    ys_.clear();
    radius_ = arc_start_ = arc_stop_ = 0;
    ellipse_start_ = ellipse_stop_ = mode_ == "INSERT" ? 1.0 : 0.0;  // an INSERT's scale
  }

  void parse() {
    std::string_view code, data;
    while (next_line(code)) {
      if (!next_line(data)) data = {};
      int id = 0;
      const auto [end, ec] = std::from_chars(code.data(), code.data() + code.size(), id);
      if (ec != std::errc() || end != code.data() + code.size()) {
        if (code.empty() && pos_ >= text_.size()) break;  // the file's last newline
        fail(line_ - 1, fmt::format("'{}' is not a DXF group code", code));
      }
      // Coordinates outside blocks are moved by the origin and scaled.
      const bool raw = in_blocks_;
      auto coordinate = [&](double origin) { return raw ? number(data) : (number(data) - origin) * o_.scale; };
      switch (id) {
        case 0:
          finish_entity();
          start_entity(data);
          break;
        case 2: id_ = std::string(data); break;
        case 8: layer_ = std::string(data); break;
        case 10:
        case 11: xs_.push_back(coordinate(o_.origin.x)); break;
        case 20:
        case 21: ys_.push_back(coordinate(o_.origin.y)); break;
        case 40: radius_ = number(data) * (raw ? 1 : o_.scale); break;
        case 41: ellipse_start_ = number(data); break;
        case 42: ellipse_stop_ = number(data); break;
        case 50: arc_start_ = number(data); break;
        case 51: arc_stop_ = number(data); break;
        case 70: flags_ = std::fmod(number(data), 2) != 0 ? 1 : 0; break;  // bit 1: closed
        default: break;
      }
    }
  }

  // The segments joined into contours, each followed from end to end
  // through the grid; OpenSCAD's toPolygon2d order (reversed).
  Polygon2d contours() {
    if (lines_.empty())
      throw DxfError(o_.layer.empty() ? std::string("the file draws no lines in its ENTITIES section")
                                      : fmt::format("the layer '{}' draws no lines (no such layer, or it is empty)",
                                                    o_.layer));
    std::map<int, int> enabled;
    for (std::size_t i = 0; i < lines_.size(); ++i) enabled[static_cast<int>(i)] = static_cast<int>(i);
    // The contour from segment `current`, entered at its end `end`, followed
    // until no segment continues it; its point indices in order.
    auto follow = [&](int current, int end) {
      std::vector<int> indices{lines_[current].idx[end]};
      for (;;) {
        indices.push_back(lines_[current].idx[!end]);
        const glm::dvec2 ref = points_[static_cast<std::size_t>(lines_[current].idx[!end])];
        lines_[current].disabled = true;
        enabled.erase(current);
        double x = ref.x, y = ref.y;
        const std::vector<int> around = grid_.align(x, y);
        bool found = false;
        for (int k : around) {
          if (static_cast<std::size_t>(k) >= lines_.size() || lines_[k].disabled) continue;
          for (int e = 0; e < 2 && !found; ++e) {
            const glm::dvec2 q = points_[static_cast<std::size_t>(lines_[k].idx[e])];
            if (grid_.eq(ref.x, ref.y, q.x, q.y)) current = k, end = e, found = true;
          }
          if (found) break;
        }
        if (!found) break;
      }
      return indices;
    };
    // OpenSCAD's toPolygon2d: the points in reverse order; a closed contour
    // comes back to its first point, which is not repeated.
    Polygon2d shape;
    auto add = [&](const std::vector<int>& indices, bool closed) {
      Outline2d outline;
      const std::size_t last = closed ? indices.size() - 1 : indices.size();
      for (std::size_t j = 1; j <= last; ++j)
        outline.vertices.push_back(points_[static_cast<std::size_t>(indices[indices.size() - j])]);
      shape.outlines.push_back(std::move(outline));
    };
    // Open contours first, each from a segment end no other segment shares.
    // OpenSCAD closes them with a straight edge from their last point to
    // their first (a profile for rotate_extrude drawn up to the axis is one).
    for (std::size_t i = 0; i < lines_.size(); ++i)
      for (int j = 0; j < 2 && !lines_[i].disabled; ++j) {
        const glm::dvec2 p = points_[static_cast<std::size_t>(lines_[i].idx[j])];
        double x = p.x, y = p.y;
        bool shared = false;
        for (int k : grid_.align(x, y))
          if (k != static_cast<int>(i) && static_cast<std::size_t>(k) < lines_.size() && !lines_[k].disabled)
            shared = true;
        if (!shared) add(follow(static_cast<int>(i), j), false);
      }
    while (!enabled.empty()) add(follow(enabled.begin()->second, 0), true);
    return shape;
  }

  std::string_view text_;
  const DxfOptions& o_;
  std::size_t pos_ = 0;
  int line_ = 0;  // of the last line read, from 1
  Grid grid_;
  std::vector<glm::dvec2> points_;
  std::vector<Segment> lines_;
  std::unordered_map<std::string, std::vector<Segment>> blocks_;
  bool in_entities_ = false, in_blocks_ = false;
  std::string block_;
  // The entity being read.
  std::string mode_, layer_, id_;
  int entity_line_ = 0, flags_ = 0;
  std::vector<double> xs_, ys_;
  double radius_ = 0, arc_start_ = 0, arc_stop_ = 0, ellipse_start_ = 0, ellipse_stop_ = 0;
};

}  // namespace

Polygon2d read_dxf(std::string_view text, const DxfOptions& options) { return Reader(text, options).read(); }

}  // namespace capsim::scene_file
