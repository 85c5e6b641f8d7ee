#pragma once
// Every primitive of a scene as an Embree 3 user geometry, so that Embree's BVH
// finds the candidates along a ray and the oracle's own double-precision code
// (oracle_geometry.h) intersects them.
//
// Why user geometries in world space rather than instances: Embree carries rays
// and instance transforms in float, which would make the oracle less exact than
// the double-precision tracer it judges. Here Embree only culls: the bounds
// callback returns the primitive's world box, rounded outward and padded far
// beyond float error, and the intersect callback ignores Embree's float ray and
// intersects the exact double ray held in the query context. It records the
// primitive's whole-line interval and reports no hit, so traversal goes on and
// every primitive along the ray is met.

#include "oracle/oracle_geometry.h"

#include <embree3/rtcore.h>

#include <cmath>
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace oracle {

// One primitive's interval along the line.
struct PrimSpan {
  std::uint32_t primitive = 0;
  Span span;
};

struct DeviceDeleter {
  void operator()(RTCDeviceTy* d) const { rtcReleaseDevice(d); }
};
struct SceneDeleter {
  void operator()(RTCSceneTy* s) const { rtcReleaseScene(s); }
};
using DeviceHandle = std::unique_ptr<RTCDeviceTy, DeviceDeleter>;
using SceneHandle = std::unique_ptr<RTCSceneTy, SceneDeleter>;

// One device for the whole test binary: creating one costs far more than a scene.
inline RTCDevice shared_device() {
  static DeviceHandle device = [] {
    DeviceHandle d(rtcNewDevice(nullptr));
    if (!d) throw std::runtime_error("rtcNewDevice failed");
    return d;
  }();
  return device.get();
}

// A ray for Embree: the ray in float, t from 0 on, no hit yet.
inline RTCRayHit embree_ray(const capsim::Ray& ray) {
  RTCRayHit rh{};
  rh.ray.org_x = static_cast<float>(ray.origin.x);
  rh.ray.org_y = static_cast<float>(ray.origin.y);
  rh.ray.org_z = static_cast<float>(ray.origin.z);
  rh.ray.dir_x = static_cast<float>(ray.dir.x);
  rh.ray.dir_y = static_cast<float>(ray.dir.y);
  rh.ray.dir_z = static_cast<float>(ray.dir.z);
  rh.ray.tnear = 0.0f;
  rh.ray.tfar = INFINITY;
  rh.ray.mask = 0xFFFFFFFFu;
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  return rh;
}

// Embree's RTCIntersectContext must come first: the callback receives a pointer
// to it and recovers the rest of the query from the same address.
struct CollectContext {
  RTCIntersectContext rtc;
  const capsim::Ray* ray = nullptr;
  const std::vector<OraclePrimitive>* prims = nullptr;
  std::vector<PrimSpan>* out = nullptr;
  std::vector<std::uint32_t>* seen = nullptr;  // query stamp per primitive
  std::uint32_t stamp = 0;
};

// Float box, rounded outward, padded by a small fraction of its size and of its
// distance from the origin: generous against float rounding of the ray in
// Embree's traversal; a looser box only costs extra callback calls.
inline void bounds_callback(const RTCBoundsFunctionArguments* args) {
  const auto* p = static_cast<const OraclePrimitive*>(args->geometryUserPtr);
  const capsim::Aabb& b = p->world_bounds;
  const double pad =
      1e-4 * (glm::length(b.extent()) + glm::length(glm::abs(b.lo)) + glm::length(glm::abs(b.hi)));
  args->bounds_o->lower_x = std::nextafter(static_cast<float>(b.lo.x - pad), -INFINITY);
  args->bounds_o->lower_y = std::nextafter(static_cast<float>(b.lo.y - pad), -INFINITY);
  args->bounds_o->lower_z = std::nextafter(static_cast<float>(b.lo.z - pad), -INFINITY);
  args->bounds_o->upper_x = std::nextafter(static_cast<float>(b.hi.x + pad), INFINITY);
  args->bounds_o->upper_y = std::nextafter(static_cast<float>(b.hi.y + pad), INFINITY);
  args->bounds_o->upper_z = std::nextafter(static_cast<float>(b.hi.z + pad), INFINITY);
}

inline void intersect_callback(const RTCIntersectFunctionNArguments* args) {
  auto* ctx = reinterpret_cast<CollectContext*>(args->context);
  for (unsigned lane = 0; lane < args->N; ++lane) {
    if (!args->valid[lane]) continue;
    const std::uint32_t id = args->geomID;
    if ((*ctx->seen)[id] == ctx->stamp) continue;  // a BVH may list a primitive twice
    (*ctx->seen)[id] = ctx->stamp;
    const Span s = line_span((*ctx->prims)[id], *ctx->ray);
    if (!s.empty()) ctx->out->push_back({id, s});
    // No hit is reported: the ray's tfar stays infinite and traversal continues.
  }
}

// A committed Embree scene whose geometry IDs are the primitive indices.
class EmbreeCollector {
 public:
  explicit EmbreeCollector(std::vector<OraclePrimitive> prims)
      : prims_(std::move(prims)), seen_(prims_.size(), 0) {
    RTCDevice device = shared_device();
    scene_.reset(rtcNewScene(device));
    rtcSetSceneFlags(scene_.get(), RTC_SCENE_FLAG_ROBUST);
    for (std::uint32_t i = 0; i < prims_.size(); ++i) {
      RTCGeometry g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_USER);
      rtcSetGeometryUserPrimitiveCount(g, 1);
      rtcSetGeometryUserData(g, &prims_[i]);
      rtcSetGeometryBoundsFunction(g, bounds_callback, nullptr);
      rtcSetGeometryIntersectFunction(g, intersect_callback);
      rtcCommitGeometry(g);
      rtcAttachGeometryByID(scene_.get(), g, i);
      rtcReleaseGeometry(g);
    }
    rtcCommitScene(scene_.get());
    if (rtcGetDeviceError(device) != RTC_ERROR_NONE)
      throw std::runtime_error("Embree scene construction failed");
  }
  EmbreeCollector(const EmbreeCollector&) = delete;
  EmbreeCollector& operator=(const EmbreeCollector&) = delete;

  // Every primitive the whole line meets, with its interval, for the Embree ray
  // segment [0, inf) from the origin (the oracle only ever asks about t >= 0, and
  // a primitive whose interval reaches t >= 0 has a box that the segment meets).
  void collect(const capsim::Ray& ray, std::vector<PrimSpan>& out) {
    out.clear();
    CollectContext ctx;
    rtcInitIntersectContext(&ctx.rtc);
    ctx.ray = &ray;
    ctx.prims = &prims_;
    ctx.out = &out;
    ctx.seen = &seen_;
    ctx.stamp = ++stamp_;
    RTCRayHit rh = embree_ray(ray);
    rtcIntersect1(scene_.get(), &ctx.rtc, &rh);
  }

  // The same answer without Embree: every primitive tested. Used to check that
  // Embree's culling never drops a primitive.
  void collect_brute_force(const capsim::Ray& ray, std::vector<PrimSpan>& out) const {
    out.clear();
    for (std::uint32_t i = 0; i < prims_.size(); ++i) {
      const Span s = line_span(prims_[i], ray);
      if (!s.empty()) out.push_back({i, s});
    }
  }

  const std::vector<OraclePrimitive>& prims() const { return prims_; }

 private:
  std::vector<OraclePrimitive> prims_;
  std::vector<std::uint32_t> seen_;
  std::uint32_t stamp_ = 0;
  SceneHandle scene_;
};

}  // namespace oracle
