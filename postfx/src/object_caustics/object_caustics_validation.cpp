#include "object_caustics/object_caustics_validation.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include "core/convention_checks.h"
#include "core/validation.h"
#include "object_caustics/object_caustics_frame.h"
#include "object_caustics/object_caustics_light_validation.h"

namespace postfx::detail {
namespace {

bool inRange(double value, double lo, double hi) {
  return value >= lo && value <= hi;  // NaN fails both
}
bool inRange(const glm::vec3& v, double lo, double hi) {
  return inRange(v.x, lo, hi) && inRange(v.y, lo, hi) && inRange(v.z, lo, hi);
}
bool finite(const glm::dmat4& m) {
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r)
      if (!std::isfinite(m[c][r])) return false;
  return true;
}

GLint64 bufferSize(GLuint buffer) {
  if (buffer == 0 || glIsBuffer(buffer) != GL_TRUE) return -1;
  GLint64 size = 0;
  glGetNamedBufferParameteri64v(buffer, GL_BUFFER_SIZE, &size);
  return size;
}

int indexBytes(IndexType type) {
  switch (type) {
    case IndexType::UnsignedInt:
      return 4;
    case IndexType::UnsignedShort:
      return 2;
    case IndexType::UnsignedByte:
      return 1;
    default:
      return 0;
  }
}

// Whether `count` records of `stride` bytes, the last one read up to `tail` bytes into it,
// starting `offset` bytes into a buffer of `bytes`, fit inside it. Every operand is
// non-negative and every step a subtraction or a division that cannot overflow, whatever the
// host passed (INT64_MAX counts and offsets included): the product count * stride is never
// formed.
bool fitsInBuffer(std::int64_t bytes, std::int64_t offset, std::int64_t count, std::int64_t stride,
                  std::int64_t tail) {
  if (offset > bytes || tail > bytes - offset) return false;
  return count - 1 <= (bytes - offset - tail) / stride;
}

Result checkCaster(int index, const CasterMesh& m, std::string& error) {
  const std::string field = "objectCaustics.casters[" + std::to_string(index) + "]";
  auto fail = [&](const std::string& message, Result r = Result::InvalidArgument) {
    error = field + message;
    return r;
  };
  // Draw counts are GLsizei (int32): more cannot be drawn in one call.
  constexpr std::int64_t kMaxCount = std::numeric_limits<std::int32_t>::max();
  const bool indexed = m.indexBuffer != 0;
  const std::int64_t drawn = indexed ? m.indexCount : m.vertexCount;
  if (drawn < 3)
    return fail(
        indexed ? ".indexCount must be >= 3 (no triangles), got " + std::to_string(m.indexCount)
                : ".vertexCount must be >= 3 (no triangles), got " + std::to_string(m.vertexCount));
  if (m.vertexCount < 1 || m.vertexCount > kMaxCount)
    return fail(".vertexCount must be in [1, 2^31 - 1], got " + std::to_string(m.vertexCount));
  if (indexed && m.indexCount > kMaxCount)
    return fail(".indexCount must be <= 2^31 - 1, got " + std::to_string(m.indexCount));
  if (m.stride < 12 || m.stride > 2048)
    return fail(".stride must be in [12, 2048] bytes, got " + std::to_string(m.stride));
  if (m.positionOffset < 0 || m.positionOffset > m.stride - 12)
    return fail(".positionOffset must leave 12 bytes inside the stride");
  if (m.normalOffset >= 0 && m.normalOffset > m.stride - 12)
    return fail(".normalOffset must leave 12 bytes inside the stride (or be < 0: none)");
  if (m.baseOffset < 0 || m.indexOffset < 0) return fail(": byte offsets must be >= 0");
  const GLint64 vertexBytes = bufferSize(m.vertexBuffer);
  if (vertexBytes < 0)
    return fail(".vertexBuffer " + std::to_string(m.vertexBuffer) + " is not a buffer name",
                Result::MissingTexture);
  // The last vertex is read up to the end of its position or of its normal, whichever is later.
  const std::int64_t tail = std::max(m.positionOffset, m.normalOffset) + 12;
  if (!fitsInBuffer(vertexBytes, m.baseOffset, m.vertexCount, m.stride, tail))
    return fail(".vertexBuffer holds " + std::to_string(vertexBytes) + " bytes, too few for " +
                    std::to_string(m.vertexCount) + " vertices of " + std::to_string(m.stride) +
                    " bytes from byte " + std::to_string(m.baseOffset),
                Result::SizeMismatch);
  if (indexed) {
    const int bytes = indexBytes(m.indexType);
    if (bytes == 0)
      return fail(".indexType " + std::to_string(static_cast<std::uint32_t>(m.indexType)) +
                  " is not an IndexType (UnsignedInt, UnsignedShort or UnsignedByte)");
    const GLint64 indexBufferBytes = bufferSize(m.indexBuffer);
    if (indexBufferBytes < 0)
      return fail(".indexBuffer " + std::to_string(m.indexBuffer) + " is not a buffer name",
                  Result::MissingTexture);
    if (m.indexOffset % bytes != 0) return fail(".indexOffset must be aligned to the index size");
    if (!fitsInBuffer(indexBufferBytes, m.indexOffset, m.indexCount, bytes, bytes))
      return fail(".indexBuffer holds " + std::to_string(indexBufferBytes) +
                      " bytes, too few for " + std::to_string(m.indexCount) +
                      " indices from byte " + std::to_string(m.indexOffset),
                  Result::SizeMismatch);
  }
  if (!finite(m.modelToWorld)) return fail(".modelToWorld is not finite (NaN or Inf)");
  const double det = glm::determinant(glm::dmat3(m.modelToWorld));
  if (!(std::abs(det) > 1e-30)) return fail(".modelToWorld is not invertible");
  if (!inRange(m.boundsMin, -1e30, 1e30) || !inRange(m.boundsMax, -1e30, 1e30) ||
      !(m.boundsMin.x <= m.boundsMax.x && m.boundsMin.y <= m.boundsMax.y &&
        m.boundsMin.z <= m.boundsMax.z))
    return fail(": boundsMin/boundsMax must be finite with min <= max");
  const CasterMaterial& mat = m.material;
  if (mat.type != CasterMaterialType::Refractive && mat.type != CasterMaterialType::Reflective)
    return fail(notAnEnum(".material.type", static_cast<long long>(mat.type), "CasterMaterialType",
                          "Refractive or Reflective"));
  if (!inRange(mat.ior, 1.0, 3.0))
    return fail(".material.ior must be in [1, 3], got " + number(mat.ior));
  if (!inRange(mat.absorption, 0.0, 1e4))
    return fail(".material.absorption must be in [0, 1e4] per metre, got " +
                number(mat.absorption));
  if (!inRange(mat.reflectance, 0.0, 1.0))
    return fail(".material.reflectance must be in [0, 1], got " + number(mat.reflectance));
  if (!inRange(mat.transmission, 0.0, 1.0))
    return fail(".material.transmission must be in [0, 1], got " + number(mat.transmission));
  if (!inRange(mat.tint, 0.0, 1.0))
    return fail(".material.tint must be in [0, 1], got " + number(mat.tint));
  if (!inRange(mat.roughness, 0.0, 1.0))
    return fail(".material.roughness must be in [0, 1], got " + number(mat.roughness));
  if (!inRange(mat.dispersion, 0.0, kMaxCasterDispersion))
    return fail(".material.dispersion must be in [0, " + number(kMaxCasterDispersion) + "], got " +
                number(mat.dispersion));
  return Result::Ok;
}

}  // namespace

Result validateObjectCaustics(const CreateDesc& create, const FrameDesc& frame,
                              std::string& error) {
  const ObjectCausticsFrame& o = frame.objectCaustics;
  auto fail = [&error](std::string message) {
    error = std::move(message);
    return Result::InvalidArgument;
  };
  const ObjectCausticsSettings& s = o.settings;
  GLint maxTexture = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxTexture);
  if (s.mapSize < 16 || s.mapSize > maxTexture)
    return fail("objectCaustics.settings.mapSize must be in [16, GL_MAX_TEXTURE_SIZE = " +
                std::to_string(maxTexture) + "], got " + std::to_string(s.mapSize));
  if (s.gridSize < 16 || s.gridSize > 2048 || s.gridSize > maxTexture)
    return fail("objectCaustics.settings.gridSize must be in [16, 2048], got " +
                std::to_string(s.gridSize));
  if (s.iterations < 1 || s.iterations > 8)
    return fail("objectCaustics.settings.iterations must be in [1, 8], got " +
                std::to_string(s.iterations));
  if (s.exitIterations < 1 || s.exitIterations > 8)
    return fail("objectCaustics.settings.exitIterations must be in [1, 8], got " +
                std::to_string(s.exitIterations));
  if (!inRange(s.splatRadius, 0.5, 8.0))
    return fail("objectCaustics.settings.splatRadius must be in [0.5, 8] texels, got " +
                number(s.splatRadius));
  if (!inRange(s.footprintScale, 1.0, 8.0))
    return fail("objectCaustics.settings.footprintScale must be in [1, 8], got " +
                number(s.footprintScale));
  if (!inRange(s.intensity, 0.0, 1e4))
    return fail("objectCaustics.settings.intensity must be in [0, 1e4], got " +
                number(s.intensity));
  if (!inRange(s.temporalWeight, 0.0, 0.95))
    return fail("objectCaustics.settings.temporalWeight must be in [0, 0.95], got " +
                number(s.temporalWeight));
  if (s.volume.method != VolumeCausticsMethod::Beams &&
      s.volume.method != VolumeCausticsMethod::Lines)
    return fail(notAnEnum("objectCaustics.settings.volume.method",
                          static_cast<long long>(s.volume.method), "VolumeCausticsMethod",
                          "Beams or Lines"));
  if (o.casterCount < 0 || o.casterCount > kMaxCasters)
    return fail("objectCaustics.casterCount must be in [0, " + std::to_string(kMaxCasters) +
                "], got " + std::to_string(o.casterCount));
  const Result lights = validateLocalLights(create, o, error);
  if (lights != Result::Ok) return lights;
  if (o.casterCount == 0) return Result::Ok;  // nothing else is read
  if (o.casters == nullptr) return fail("objectCaustics.casters is null but casterCount > 0");
  for (int i = 0; i < o.casterCount; ++i) {
    const Result r = checkCaster(i, o.casters[i], error);
    if (r != Result::Ok) return r;
  }
  // The pass works relative to the casters' centre: their world bounds (after the transforms)
  // must stay inside the extent every other position is held to.
  glm::dvec3 lo, hi;
  casterWorldBounds(o, lo, hi);
  for (int a = 0; a < 3; ++a)
    if (!inRange(lo[a], -kMaxWorldCoordinate, kMaxWorldCoordinate) ||
        !inRange(hi[a], -kMaxWorldCoordinate, kMaxWorldCoordinate))
      return fail(
          "objectCaustics.casters: the world bounds (boundsMin/boundsMax under "
          "modelToWorld) must lie within +-" +
          worldExtentText() + " m");
  if (!o.sunCaustics) return Result::Ok;  // the sun's receivers are not read
  return checkReceivers("objectCaustics.receivers", o.receivers, error);
}

Result checkReceivers(const std::string& field, const SunShadowMap& rec, std::string& error) {
  auto fail = [&](const std::string& message) {
    error = field + message;
    return Result::InvalidArgument;
  };
  if (!finite(rec.worldToLightClip)) return fail(".worldToLightClip is not finite");
  if (!(std::abs(glm::determinant(rec.worldToLightClip)) > 1e-300))
    return fail(".worldToLightClip is not invertible");
  if (!isDepthConvention(rec.depthConvention))
    return fail(notAnEnum(".depthConvention", static_cast<long long>(rec.depthConvention),
                          "DepthConvention", "ReverseZ, ForwardZeroToOne or ForwardNegOneToOne"));
  if (!within(rec.bias, kShadowBiasRange))
    return fail(".bias" + mustBeIn(rec.bias, kShadowBiasRange, " m"));
  return checkDepthTexture((field + ".depth").c_str(), rec.depth, error);
}

}  // namespace postfx::detail
