#include "embree_scene.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <embree3/rtcore.h>

namespace ocean::reference {

struct EmbreeScene::Handles {
  RTCDevice device = nullptr;
  RTCScene scene = nullptr;
  ~Handles() {
    if (scene) rtcReleaseScene(scene);
    if (device) rtcReleaseDevice(device);
  }
};

namespace {

bool finite(const glm::dvec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// Embree works in float: distances are clamped to what float holds.
float toFloatDistance(double t) {
  return static_cast<float>(std::min(t, static_cast<double>(std::numeric_limits<float>::max())));
}

RTCRay makeRay(const glm::dvec3& from, const glm::dvec3& dir, double tNear, double tFar) {
  RTCRay ray{};
  ray.org_x = static_cast<float>(from.x);
  ray.org_y = static_cast<float>(from.y);
  ray.org_z = static_cast<float>(from.z);
  ray.dir_x = static_cast<float>(dir.x);
  ray.dir_y = static_cast<float>(dir.y);
  ray.dir_z = static_cast<float>(dir.z);
  ray.tnear = toFloatDistance(tNear);
  ray.tfar = toFloatDistance(tFar);
  ray.mask = ~0u;
  ray.flags = 0;
  return ray;
}

}  // namespace

std::unique_ptr<EmbreeScene> EmbreeScene::create(const std::vector<TriangleMesh>& meshes,
                                                 const glm::dvec3& origin, std::string& error) {
  std::unique_ptr<EmbreeScene> self(new EmbreeScene());
  self->handles_ = std::make_unique<Handles>();
  // Two build threads: the machines this runs on share their cores.
  self->handles_->device = rtcNewDevice("threads=2");
  if (!self->handles_->device) {
    error = "Embree: cannot create a device (error " +
            std::to_string(static_cast<int>(rtcGetDeviceError(nullptr))) + ")";
    return nullptr;
  }
  RTCDevice device = self->handles_->device;
  self->handles_->scene = rtcNewScene(device);
  // Robust traversal: no ray slips between two triangles that share an edge.
  rtcSetSceneFlags(self->handles_->scene, RTC_SCENE_FLAG_ROBUST);
  rtcSetSceneBuildQuality(self->handles_->scene, RTC_BUILD_QUALITY_HIGH);
  self->boundsMin_ = glm::dvec3(std::numeric_limits<double>::max());
  self->boundsMax_ = glm::dvec3(-std::numeric_limits<double>::max());
  for (const TriangleMesh& mesh : meshes) {
    if (mesh.normals.size() != mesh.positions.size()) {
      error = "mesh has " + std::to_string(mesh.normals.size()) + " normals for " +
              std::to_string(mesh.positions.size()) + " positions";
      return nullptr;
    }
    TriangleMesh relative;
    relative.triangles = mesh.triangles;
    relative.normals = mesh.normals;
    relative.positions.reserve(mesh.positions.size());
    for (const glm::dvec3& p : mesh.positions) {
      if (!finite(p)) {
        error = "mesh has a non-finite vertex";
        return nullptr;
      }
      relative.positions.push_back(p - origin);
      self->boundsMin_ = glm::min(self->boundsMin_, p - origin);
      self->boundsMax_ = glm::max(self->boundsMax_, p - origin);
    }
    for (const glm::uvec3& t : mesh.triangles) {
      if (std::max({t.x, t.y, t.z}) >= mesh.positions.size()) {
        error = "mesh has a triangle index out of range";
        return nullptr;
      }
    }
    self->meshes_.push_back(std::move(relative));
    const TriangleMesh& stored = self->meshes_.back();
    RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* vertices = static_cast<float*>(
        rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                3 * sizeof(float), std::max<size_t>(stored.positions.size(), 1)));
    auto* indices = static_cast<unsigned*>(rtcSetNewGeometryBuffer(
        geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned),
        std::max<size_t>(stored.triangles.size(), 1)));
    if (!vertices || !indices) {
      rtcReleaseGeometry(geometry);
      error = "Embree: out of memory for a mesh of " + std::to_string(stored.triangles.size()) +
              " triangles";
      return nullptr;
    }
    for (size_t i = 0; i < stored.positions.size(); ++i) {
      vertices[3 * i + 0] = static_cast<float>(stored.positions[i].x);
      vertices[3 * i + 1] = static_cast<float>(stored.positions[i].y);
      vertices[3 * i + 2] = static_cast<float>(stored.positions[i].z);
    }
    for (size_t i = 0; i < stored.triangles.size(); ++i) {
      indices[3 * i + 0] = stored.triangles[i].x;
      indices[3 * i + 1] = stored.triangles[i].y;
      indices[3 * i + 2] = stored.triangles[i].z;
    }
    if (stored.triangles.empty()) {  // a placeholder Embree accepts; never hit (degenerate)
      vertices[0] = vertices[1] = vertices[2] = 0.0f;
      indices[0] = indices[1] = indices[2] = 0;
    }
    rtcCommitGeometry(geometry);
    // Geometry IDs are assigned in order from 0, so geomID indexes meshes_.
    rtcAttachGeometry(self->handles_->scene, geometry);
    rtcReleaseGeometry(geometry);
    self->triangleCount_ += stored.triangles.size();
  }
  rtcCommitScene(self->handles_->scene);
  if (const RTCError code = rtcGetDeviceError(device); code != RTC_ERROR_NONE) {
    error =
        "Embree: building the scene failed (error " + std::to_string(static_cast<int>(code)) + ")";
    return nullptr;
  }
  if (meshes.empty()) self->boundsMin_ = self->boundsMax_ = glm::dvec3(0.0);
  return self;
}

EmbreeScene::~EmbreeScene() = default;

void EmbreeScene::meshBoundingSphere(size_t mesh, glm::dvec3& centre, double& radius) const {
  centre = glm::dvec3(0.0);
  radius = 0.0;
  if (mesh >= meshes_.size() || meshes_[mesh].positions.empty()) return;
  const std::vector<glm::dvec3>& p = meshes_[mesh].positions;
  glm::dvec3 lo = p[0], hi = p[0];
  for (const glm::dvec3& q : p) {
    lo = glm::min(lo, q);
    hi = glm::max(hi, q);
  }
  centre = 0.5 * (lo + hi);
  for (const glm::dvec3& q : p) radius = std::max(radius, glm::length(q - centre));
}

bool EmbreeScene::intersect(const glm::dvec3& from, const glm::dvec3& dir, double tNear,
                            double tFar, RayHit& hit) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRayHit query{};
  query.ray = makeRay(from, dir, tNear, tFar);
  query.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  query.hit.primID = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(handles_->scene, &context, &query);
  if (query.hit.geomID == RTC_INVALID_GEOMETRY_ID) return false;
  const TriangleMesh& mesh = meshes_[query.hit.geomID];
  const glm::uvec3& tri = mesh.triangles[query.hit.primID];
  // Embree's barycentrics: p = (1 - u - v) v0 + u v1 + v v2.
  const double u = query.hit.u, v = query.hit.v;
  glm::dvec3 n =
      (1.0 - u - v) * mesh.normals[tri.x] + u * mesh.normals[tri.y] + v * mesh.normals[tri.z];
  const double length = glm::length(n);
  if (!(length > 1e-12)) {  // opposite vertex normals: fall back to the face's own
    n = glm::cross(mesh.positions[tri.y] - mesh.positions[tri.x],
                   mesh.positions[tri.z] - mesh.positions[tri.x]);
    const double faceLength = glm::length(n);
    n = faceLength > 0.0 ? n / faceLength : glm::dvec3(0.0, 1.0, 0.0);
  } else {
    n /= length;
  }
  hit.t = query.ray.tfar;
  hit.normal = n;
  hit.mesh = static_cast<int>(query.hit.geomID);
  return true;
}

bool EmbreeScene::occluded(const glm::dvec3& from, const glm::dvec3& dir, double tNear,
                           double tFar) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRay ray = makeRay(from, dir, tNear, tFar);
  rtcOccluded1(handles_->scene, &context, &ray);
  // Embree marks an occluded ray by setting tfar to -inf.
  return ray.tfar < 0.0f;
}

}  // namespace ocean::reference
