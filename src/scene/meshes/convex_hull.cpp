// Qhull's convex hull as a closed triangle mesh.

#include "scene/meshes/convex_hull.h"

extern "C" {
#include <libqhull_r/qhull_ra.h>
}

#include <fmt/format.h>

#include <array>
#include <cstdio>
#include <map>
#include <memory>

namespace capsim {

namespace {

// Qhull's state for one run, freed however the run ends.
class QhullRun {
 public:
  QhullRun() { qh_zero(&qh_, nullptr); }
  ~QhullRun() {
    qh_freeqhull(&qh_, !qh_ALL);
    int curlong = 0, totlong = 0;
    qh_memfreeshort(&qh_, &curlong, &totlong);
  }
  QhullRun(const QhullRun&) = delete;
  QhullRun& operator=(const QhullRun&) = delete;
  qhT* get() { return &qh_; }

 private:
  qhT qh_;
};

}  // namespace

HullBuild convex_hull(const std::vector<glm::dvec3>& points) {
  HullBuild out;
  if (points.size() < 4) {
    out.flat_reason = fmt::format("its {} point{} span no volume", points.size(), points.size() == 1 ? "" : "s");
    return out;
  }
  std::vector<coordT> coords;
  coords.reserve(3 * points.size());
  for (const glm::dvec3& p : points) coords.insert(coords.end(), {p.x, p.y, p.z});
  // Qhull reports into a stream; the message is replaced by one of ours.
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> quiet(std::fopen("/dev/null", "w"), &std::fclose);
  QhullRun run;
  qhT* qh = run.get();
  // Qt: triangulated facets. Qhull merges facets that are coplanar within its
  // precision, so every facet is a plane through corners of the input.
  char options[] = "qhull Qt";
  const int status = qh_new_qhull(qh, 3, static_cast<int>(points.size()), coords.data(), False, options, nullptr,
                                  quiet.get());
  if (status != 0) {
    out.flat_reason = "its points lie in one plane (the hull has no volume)";
    return out;
  }
  TriangleMesh mesh;
  std::map<int, std::uint32_t> index;  // input point -> mesh vertex
  const auto vertex_of = [&](vertexT* v) {
    const int id = qh_pointid(qh, v->point);
    const auto [at, added] = index.try_emplace(id, static_cast<std::uint32_t>(mesh.vertices.size()));
    if (added) {
      mesh.vertices.push_back(points[static_cast<std::size_t>(id)]);
      mesh.bounds.extend(points[static_cast<std::size_t>(id)]);
    }
    return at->second;
  };
  facetT* facet;
  FORALLfacets {
    if (qh_setsize(qh, facet->vertices) != 3) continue;  // Qt leaves none other
    std::array<std::uint32_t, 3> t{};
    int k = 0;
    vertexT *vertex, **vertexp;
    FOREACHvertex_(facet->vertices) t[static_cast<std::size_t>(k++)] = vertex_of(vertex);
    const glm::dvec3 a = mesh.vertices[t[0]], b = mesh.vertices[t[1]], c = mesh.vertices[t[2]];
    const glm::dvec3 outward(facet->normal[0], facet->normal[1], facet->normal[2]);
    if (glm::dot(glm::cross(b - a, c - a), outward) < 0) std::swap(t[1], t[2]);
    mesh.triangles.push_back(t);
  }
  out.mesh = std::move(mesh);
  return out;
}

}  // namespace capsim
