// projection() by vertical lines through the CSG tree and marching squares.

#include "scene/regions/projection_2d.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <utility>

namespace capsim::scene_file {
namespace {

using Interval = std::pair<double, double>;  // closed [lo, hi] in z
using Intervals = std::vector<Interval>;     // sorted, disjoint

// One mesh seen from above: its triangles that are not vertical, each
// counter-clockwise in x-y, binned on a grid over the mesh's x-y box.
class MeshFromAbove {
 public:
  explicit MeshFromAbove(const TriangleMesh& mesh) {
    for (const auto& tri : mesh.triangles) {
      Tri t;
      for (int k = 0; k < 3; ++k) t.v[k] = mesh.vertices[tri[static_cast<std::size_t>(k)]];
      const double area = cross(t.v[1] - t.v[0], t.v[2] - t.v[0]);
      if (area == 0) continue;  // vertical: no vertical line crosses it in a point
      if (area < 0) std::swap(t.v[1], t.v[2]);
      tris_.push_back(t);
      lo_ = glm::min(lo_, glm::dvec2(glm::min(glm::min(t.v[0], t.v[1]), t.v[2])));
      hi_ = glm::max(hi_, glm::dvec2(glm::max(glm::max(t.v[0], t.v[1]), t.v[2])));
    }
    if (tris_.empty()) return;
    side_ = std::max(1, static_cast<int>(std::sqrt(static_cast<double>(tris_.size()))));
    cell_ = glm::max((hi_ - lo_) / static_cast<double>(side_), glm::dvec2(1e-300));
    bins_.assign(static_cast<std::size_t>(side_) * static_cast<std::size_t>(side_), {});
    for (std::uint32_t i = 0; i < tris_.size(); ++i) {
      const Tri& t = tris_[i];
      const glm::ivec2 a = bin(glm::dvec2(glm::min(glm::min(t.v[0], t.v[1]), t.v[2])));
      const glm::ivec2 b = bin(glm::dvec2(glm::max(glm::max(t.v[0], t.v[1]), t.v[2])));
      for (int y = a.y; y <= b.y; ++y)
        for (int x = a.x; x <= b.x; ++x) bins_[static_cast<std::size_t>(y * side_ + x)].push_back(i);
    }
  }

  // The line's intervals in the solid: its crossings with the triangles,
  // sorted and paired (a closed mesh is crossed an even number of times).
  void intervals(glm::dvec2 p, std::vector<double>& zs, Intervals& out) const {
    out.clear();
    if (tris_.empty() || p.x < lo_.x || p.y < lo_.y || p.x > hi_.x || p.y > hi_.y) return;
    zs.clear();
    const glm::ivec2 b = bin(p);
    for (std::uint32_t i : bins_[static_cast<std::size_t>(b.y * side_ + b.x)]) {
      double z;
      if (tris_[i].crossing(p, z)) zs.push_back(z);
    }
    std::sort(zs.begin(), zs.end());
    for (std::size_t k = 0; k + 1 < zs.size(); k += 2) out.emplace_back(zs[k], zs[k + 1]);
  }

 private:
  static double cross(glm::dvec2 a, glm::dvec2 b) { return a.x * b.y - a.y * b.x; }

  struct Tri {
    glm::dvec3 v[3];
    // Whether the vertical line through p crosses the triangle, and where.
    // Two triangles that share an edge from either side of it see p on the
    // same side of it: the side is computed from the edge's lower end in
    // both, so rounding cannot put p inside both or neither. A point on the
    // edge counts for exactly one of them (the edge runs up, or left, in
    // one), so a line through an edge is counted once.
    bool crossing(glm::dvec2 p, double& z) const {
      double w[3];
      for (int k = 0; k < 3; ++k) {
        const glm::dvec2 a(v[k]), b(v[(k + 1) % 3]);
        const bool forward = a.x < b.x || (a.x == b.x && a.y < b.y);
        const glm::dvec2 from = forward ? a : b, to = forward ? b : a;
        w[k] = cross(to - from, p - from);
        if (!forward) w[k] = -w[k];
        const glm::dvec2 d = b - a;
        if (w[k] < 0 || (w[k] == 0 && !(d.y > 0 || (d.y == 0 && d.x < 0)))) return false;
      }
      const double sum = w[0] + w[1] + w[2];
      // w[k] weighs the vertex opposite edge k.
      z = (w[1] * v[0].z + w[2] * v[1].z + w[0] * v[2].z) / sum;
      return true;
    }
  };

  glm::ivec2 bin(glm::dvec2 p) const {
    const glm::dvec2 f = (p - lo_) / cell_;
    return glm::clamp(glm::ivec2(static_cast<int>(std::clamp(f.x, 0.0, 1e9)), static_cast<int>(std::clamp(f.y, 0.0, 1e9))),
                      glm::ivec2(0), glm::ivec2(side_ - 1));
  }

  std::vector<Tri> tris_;
  glm::dvec2 lo_{std::numeric_limits<double>::infinity()}, hi_{-std::numeric_limits<double>::infinity()};
  int side_ = 0;
  glm::dvec2 cell_{1};
  std::vector<std::vector<std::uint32_t>> bins_;
};

Intervals unite(const Intervals& a, const Intervals& b) {
  Intervals all;
  all.reserve(a.size() + b.size());
  std::merge(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(all));
  Intervals out;
  for (const Interval& i : all) {
    if (!out.empty() && i.first <= out.back().second) {
      out.back().second = std::max(out.back().second, i.second);
    } else {
      out.push_back(i);
    }
  }
  return out;
}

Intervals intersect(const Intervals& a, const Intervals& b) {
  Intervals out;
  std::size_t i = 0, j = 0;
  while (i < a.size() && j < b.size()) {
    const double lo = std::max(a[i].first, b[j].first), hi = std::min(a[i].second, b[j].second);
    if (lo < hi) out.emplace_back(lo, hi);
    (a[i].second < b[j].second) ? ++i : ++j;
  }
  return out;
}

Intervals subtract(const Intervals& a, const Intervals& b) {
  Intervals out;
  std::size_t j = 0;
  for (Interval i : a) {
    while (j < b.size() && b[j].second <= i.first) ++j;
    for (std::size_t k = j; k < b.size() && b[k].first < i.second; ++k) {
      if (b[k].first > i.first) out.emplace_back(i.first, b[k].first);
      i.first = std::max(i.first, b[k].second);
    }
    if (i.first < i.second) out.push_back(i);
  }
  return out;
}

// Whether a point of the plane belongs to the projection.
class Membership {
 public:
  Membership(const MeshedSolids& solids, bool cut) : solids_(solids), cut_(cut) {
    for (const TriangleMesh& m : solids.meshes) meshes_.emplace_back(m);
  }

  bool operator()(glm::dvec2 p) {
    const Intervals in = eval(solids_.root, p);
    if (!cut_) return !in.empty();
    for (const Interval& i : in)
      if (i.first <= 0 && 0 <= i.second) return true;
    return false;
  }

 private:
  Intervals eval(const CsgNode& node, glm::dvec2 p) {
    if (node.is_leaf) {
      Intervals out;
      meshes_[static_cast<std::size_t>(node.primitive)].intervals(p, zs_, out);
      return out;
    }
    Intervals acc;
    bool first = true;
    for (const CsgNode& child : node.children) {
      Intervals c = eval(child, p);
      if (first) {
        acc = std::move(c);
        first = false;
      } else if (node.op == CsgOp::Union) {
        acc = unite(acc, c);
      } else if (node.op == CsgOp::Intersection) {
        acc = intersect(acc, c);
      } else {
        acc = subtract(acc, c);
      }
    }
    return acc;
  }

  const MeshedSolids& solids_;
  bool cut_;
  std::vector<MeshFromAbove> meshes_;
  std::vector<double> zs_;
};

// The distance from p to the line through a and b (to a when they coincide).
double off_line(glm::dvec2 p, glm::dvec2 a, glm::dvec2 b) {
  const glm::dvec2 d = b - a;
  const double len = glm::length(d);
  if (len == 0) return glm::length(p - a);
  return std::abs(d.x * (p.y - a.y) - d.y * (p.x - a.x)) / len;
}

// Douglas-Peucker on the open run path[first..last]: marks the points kept.
void keep_run(const std::vector<glm::dvec2>& path, std::size_t first, std::size_t last, double tol,
              std::vector<char>& keep) {
  if (last <= first + 1) return;
  double worst = -1;
  std::size_t at = first;
  for (std::size_t k = first + 1; k < last; ++k) {
    const double d = off_line(path[k], path[first], path[last]);
    if (d > worst) {
      worst = d;
      at = k;
    }
  }
  if (worst <= tol) return;
  keep[at] = 1;
  keep_run(path, first, at, tol, keep);
  keep_run(path, at, last, tol, keep);
}

// A closed loop with the points that lie within tol of a straight run left out.
std::vector<glm::dvec2> simplify(const std::vector<glm::dvec2>& loop, double tol) {
  const std::size_t n = loop.size();
  if (n < 4) return loop;
  std::size_t far = 0;
  for (std::size_t k = 1; k < n; ++k)
    if (glm::length(loop[k] - loop[0]) > glm::length(loop[far] - loop[0])) far = k;
  std::vector<glm::dvec2> path(loop);
  path.push_back(loop[0]);
  std::vector<char> keep(path.size(), 0);
  keep[0] = keep[far] = keep[n] = 1;
  keep_run(path, 0, far, tol, keep);
  keep_run(path, far, n, tol, keep);
  std::vector<glm::dvec2> out;
  for (std::size_t k = 0; k < n; ++k)
    if (keep[k]) out.push_back(path[k]);
  // The two anchors were kept whatever their place: drop either if it lies on
  // the run through its neighbours.
  for (std::size_t k = 0; out.size() > 3 && k < out.size();) {
    const std::size_t m = out.size();
    if (off_line(out[k], out[(k + m - 1) % m], out[(k + 1) % m]) <= tol) {
      out.erase(out.begin() + static_cast<std::ptrdiff_t>(k));
    } else {
      ++k;
    }
  }
  return out;
}

// The grid cuts each corner of the outline by a short edge. Where that edge
// joins two long straight runs (each point of which lies on the boundary),
// the corner is where the runs' lines meet: put it back there. A run shorter
// than `run` or a meeting point farther than `reach` from the short edge
// leaves the edge as it is (a curve, or a feature finer than the grid).
std::vector<glm::dvec2> restore_corners(std::vector<glm::dvec2> loop, double shortest, double run, double reach) {
  for (std::size_t i = 0; loop.size() > 3 && i < loop.size(); ++i) {
    const std::size_t n = loop.size();
    const glm::dvec2 a = loop[(i + n - 1) % n], b = loop[i], c = loop[(i + 1) % n], d = loop[(i + 2) % n];
    if (glm::length(c - b) >= shortest || glm::length(b - a) < run || glm::length(d - c) < run) continue;
    const glm::dvec2 u = b - a, v = d - c;
    const double den = u.x * v.y - u.y * v.x;
    if (std::abs(den) < 1e-9 * glm::length(u) * glm::length(v)) continue;  // parallel runs: a step, not a corner
    const double s = ((c.x - a.x) * v.y - (c.y - a.y) * v.x) / den;
    const glm::dvec2 x = a + s * u;
    if (glm::length(x - 0.5 * (b + c)) > reach) continue;
    loop[i] = x;
    loop.erase(loop.begin() + static_cast<std::ptrdiff_t>((i + 1) % n));
    if ((i + 1) % n == 0) --i;  // the front moved down by one
  }
  return loop;
}

}  // namespace

std::vector<std::vector<glm::dvec2>> project_solids(const MeshedSolids& solids, bool cut) {
  Aabb box;
  for (const TriangleMesh& m : solids.meshes)
    if (!m.triangles.empty()) box.extend(m.bounds);
  if (box.empty()) return {};
  Membership inside(solids, cut);

  // The grid: one cell of margin on every side, so that its border lies
  // outside; offset by an irrational fraction of a cell, so that grid lines
  // do not run along the round coordinates models are built on.
  const glm::dvec2 lo(box.lo), hi(box.hi);
  const double longer = std::max(hi.x - lo.x, hi.y - lo.y);
  const double h = longer > 0 ? longer / kProjectionGrid : 1;
  const glm::dvec2 origin = lo - h * (1 + 0.3819660112501051);
  const int nx = static_cast<int>(std::ceil((hi.x - origin.x) / h)) + 2;
  const int ny = static_cast<int>(std::ceil((hi.y - origin.y) / h)) + 2;
  auto point = [&](int i, int j) { return origin + h * glm::dvec2(i, j); };
  auto at = [&](int i, int j) { return static_cast<std::size_t>(j) * static_cast<std::size_t>(nx) + static_cast<std::size_t>(i); };

  std::vector<char> in(static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny));
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) in[at(i, j)] = (i > 0 && j > 0 && i < nx - 1 && j < ny - 1) && inside(point(i, j));

  // Edge ids: 2 * at(i, j) the edge to (i + 1, j), + 1 the edge to (i, j + 1).
  std::vector<glm::dvec2> crossing(2 * in.size());
  std::vector<char> crossed(2 * in.size(), 0);
  auto crossing_on = [&](std::size_t edge) {
    if (!crossed[edge]) {
      const std::size_t node = edge / 2;
      const int i = static_cast<int>(node % static_cast<std::size_t>(nx)), j = static_cast<int>(node / static_cast<std::size_t>(nx));
      glm::dvec2 a = point(i, j), b = edge % 2 ? point(i, j + 1) : point(i + 1, j);
      if (!in[node]) std::swap(a, b);  // a inside, b outside
      for (int k = 0; k < 60; ++k) {
        const glm::dvec2 m = 0.5 * (a + b);
        if (m == a || m == b) break;
        (inside(m) ? a : b) = m;
      }
      crossing[edge] = 0.5 * (a + b);
      crossed[edge] = 1;
    }
    return crossing[edge];
  };

  // Each crossed edge starts one boundary segment (in the cell where, going
  // counter-clockwise round the cell, it leads from inside to outside) and
  // ends one; the inside lies to the left of every segment.
  std::vector<std::int64_t> next(2 * in.size(), -1);
  for (int j = 0; j + 1 < ny; ++j) {
    for (int i = 0; i + 1 < nx; ++i) {
      const bool c[4] = {bool(in[at(i, j)]), bool(in[at(i + 1, j)]), bool(in[at(i + 1, j + 1)]), bool(in[at(i, j + 1)])};
      const std::size_t edge[4] = {2 * at(i, j), 2 * at(i + 1, j) + 1, 2 * at(i, j + 1), 2 * at(i, j) + 1};
      int inside_corners = c[0] + c[1] + c[2] + c[3];
      if (inside_corners == 0 || inside_corners == 4) continue;
      const bool saddle = inside_corners == 2 && c[0] == c[2];
      const bool joined = saddle && inside(point(i, j) + glm::dvec2(0.5 * h));
      for (int k = 0; k < 4; ++k) {
        if (!(c[k] && !c[(k + 1) % 4])) continue;  // not an exit
        int e = k;
        for (int s = 0; s < 4; ++s) {
          e = joined ? (e + 1) % 4 : (e + 3) % 4;
          if (!c[e] && c[(e + 1) % 4]) break;  // an entry
        }
        next[edge[k]] = static_cast<std::int64_t>(edge[e]);
      }
    }
  }

  std::vector<std::vector<glm::dvec2>> paths;
  std::vector<char> used(next.size(), 0);
  for (std::size_t start = 0; start < next.size(); ++start) {
    if (next[start] < 0 || used[start]) continue;
    std::vector<glm::dvec2> loop;
    // Every crossed edge ends a segment too, so the walk comes back to start.
    for (std::int64_t e = static_cast<std::int64_t>(start); e >= 0 && !used[static_cast<std::size_t>(e)];
         e = next[static_cast<std::size_t>(e)]) {
      used[static_cast<std::size_t>(e)] = 1;
      loop.push_back(crossing_on(static_cast<std::size_t>(e)));
    }
    loop = restore_corners(simplify(loop, h * 1e-4), 2 * h, 4 * h, 2 * h);
    if (loop.size() >= 3) paths.push_back(std::move(loop));
  }
  return paths;
}

}  // namespace capsim::scene_file
