#include "seabed_caustics/caustics_constants.h"

#include <algorithm>
#include <cmath>

#include <gbuffer/codec.h>

#include <glm/gtc/matrix_transform.hpp>

#include "core/convention_checks.h"
#include "core/shadow_light.h"

#include "core/block_check.h"
#include "seabed_caustics/tile_irradiance_pass.h"
#include "seabed_caustics/wavefront_area_ratio_layout.h"

namespace postfx::detail {

namespace {

// Horizontal offset per metre of depth of sunlight from `towardSun` refracted by a surface of
// unit normal `normal`.
glm::dvec2 landingOffsetPerDepth(const glm::dvec3& towardSun, const glm::dvec3& normal,
                                 double ior) {
  const glm::dvec3 t = glm::refract(-towardSun, normal, 1.0 / ior);
  return glm::dvec2(t.x, t.z) / std::max(-t.y, 1e-6);
}

}  // namespace

glm::dvec4 landingDriftJacobian(const glm::dvec3& towardSun, double ior) {
  // Central differences of the exact offset per metre of depth; it is smooth in the slopes.
  auto drift = [&](double sx, double sz) {
    return landingOffsetPerDepth(towardSun, glm::normalize(glm::dvec3(-sx, 1.0, -sz)), ior);
  };
  const double e = 1e-4;
  const glm::dvec2 dx = (drift(e, 0.0) - drift(-e, 0.0)) / (2.0 * e);
  const glm::dvec2 dz = (drift(0.0, e) - drift(0.0, -e)) / (2.0 * e);
  return glm::dvec4(dx, dz);
}

glm::dvec3 sunDiscLandingCovariance(const glm::dvec3& towardSun, double ior, double angularRadius) {
  const glm::dvec3 sun = glm::normalize(towardSun);
  const glm::dvec3 helper =
      std::abs(sun.y) < 0.9 ? glm::dvec3(0.0, 1.0, 0.0) : glm::dvec3(1.0, 0.0, 0.0);
  const glm::dvec3 side = glm::normalize(glm::cross(sun, helper));
  const glm::dvec3 up = glm::cross(side, sun);
  auto drift = [&](const glm::dvec3& toward) {
    return landingOffsetPerDepth(glm::normalize(toward), glm::dvec3(0.0, 1.0, 0.0), ior);
  };
  const double e = 1e-4;
  const glm::dvec2 a = (drift(sun + e * side) - drift(sun - e * side)) / (2.0 * e);
  const glm::dvec2 b = (drift(sun + e * up) - drift(sun - e * up)) / (2.0 * e);
  // A uniform disc of radius r has variance r^2 / 4 along each of its axes.
  const double v = 0.25 * angularRadius * angularRadius;
  return v * glm::dvec3(a.x * a.x + b.x * b.x, a.x * a.y + b.x * b.y, a.y * a.y + b.y * b.y);
}

bool wavefrontAreaRatioActive(const CreateDesc& create, const FrameDesc& frame) {
  return hasFeature(create.features, Feature::WavefrontAreaRatio) &&
         frame.caustics.model == CausticsModel::WavefrontAreaRatio && frame.sun.direction.y > 0.0;
}

shared::CausticsBlock buildCausticsBlock(const CreateDesc& create, const FrameDesc& frame,
                                         int width, int height, const WaterTextureInfo& water) {
  shared::CausticsBlock b{};
  const Camera& camera = frame.camera;
  const WaterSurface& surface = frame.water;
  const CausticsSettings& settings = frame.caustics;
  const glm::dvec3 sun = glm::normalize(frame.sun.direction);

  b.viewToWorld = glm::mat4(glm::mat3(viewToWorldRotation(camera.view)));
  b.viewport = glm::vec4(1.0f / static_cast<float>(width), 1.0f / static_cast<float>(height),
                         static_cast<float>(width), static_cast<float>(height));
  const gbuffer::ProjectionParams params =
      gbuffer::projectionParams(camera.projection, toGbuffer(create.depthConvention));
  b.projection = params.xy;
  const double levelRelative = surface.level - camera.position.y;
  const double radiansPerPixel = 2.0 / (std::abs(camera.projection[1][1]) * height);
  b.depthAndWater =
      glm::vec4(params.z, static_cast<float>(levelRelative), static_cast<float>(radiansPerPixel));

  b.towardSun = glm::vec4(glm::vec3(sun), settings.tau);
  b.reference = glm::vec4(glm::vec3(incidencePlaneNormal(sun)), settings.reflectionWeight);
  const glm::dvec3 up = -refractedSunDown(sun, surface.ior);
  b.refractedUp = glm::vec4(glm::vec3(up), settings.surfaceFadeDepth);
  const bool dispersion = hasFeature(create.features, Feature::Dispersion);
  const glm::vec3 ior = dispersion ? surface.iorRgb : glm::vec3(surface.ior);
  b.eta = glm::vec4(1.0f / ior, settings.triplanarSharpness);
  b.lightScale = glm::vec4(frame.sun.irradiance * settings.intensity, settings.minCascadeContrast);
  // up.y >= cos(critical angle) ~ 0.66 for water and a sun above the horizon, but it tends to
  // 0 as the IOR tends to 1 with a grazing sun (IOR 1 and a sun 1e-40 rad high gave 1e40: Inf
  // in float, Inf in the added light). The floor keeps both quotients finite in float and changes
  // nothing where up.y > 1e-6.
  const double upY = std::max(up.y, 1e-6);
  b.absorptionPerDepth = glm::vec4(glm::dvec3(surface.absorption) / upY, 0.0);
  if (frame.viewExtinction == ViewExtinction::Plugin)
    b.viewExtinction = glm::vec4(surface.absorption + surface.scattering, 0.0f);
  const double kx = up.x / upY, kz = up.z / upY;
  // No water texture (accepted only for object caustics alone): no cascade is read, by the floor
  // either.
  const int cascades = surface.texture.texture != 0 ? surface.cascadeCount : 0;
  b.oblique = glm::vec4(static_cast<float>(kx), static_cast<float>(kz), settings.lodBias,
                        static_cast<float>(cascades));

  const glm::dvec3 cameraFromOrigin =
      camera.position - glm::dvec3(surface.origin.x, surface.level, surface.origin.y);
  const double obliqueU = cameraFromOrigin.x - kx * cameraFromOrigin.y;
  const double obliqueV = cameraFromOrigin.z - kz * cameraFromOrigin.y;
  for (int c = 0; c < surface.cascadeCount && c < POSTFX_MAX_CASCADES; ++c) {
    const double tile = surface.tileSize[c];
    b.cascadeAxes[c] =
        glm::vec4(tileFraction(cameraFromOrigin.x, tile), tileFraction(cameraFromOrigin.y, tile),
                  tileFraction(cameraFromOrigin.z, tile), 1.0 / tile);
    const double texelsPerMetre = std::max(water.width, water.height) / tile;
    b.cascadeOblique[c] = glm::vec4(tileFraction(obliqueU, tile), tileFraction(obliqueV, tile),
                                    std::log2(texelsPerMetre), 0.0);
    // log2(wavelength / 2) as log2(wavelength) - 1: half of the smallest subnormal rounds to 0,
    // whose log is -Inf (a valid 5e-324 m once refused the frame as a float overflow).
    // Paraxial focusing: a curvature kappa modulates the irradiance at path length L by
    // L * (1 - 1/n) * kappa, and L = depth / up.y along the unperturbed refracted sun.
    const double laplacian = surface.rmsLaplacian[c];
    const double wavelength = surface.longestWavelength[c];
    b.cascadeSkip[c] = glm::vec4(
        laplacian > 0.0 ? static_cast<float>((1.0 - 1.0 / double(surface.ior)) * laplacian / upY)
                        : -1.0f,
        wavelength > 0.0 ? static_cast<float>(std::log2(wavelength) - 1.0) : 1e30f, 0.0f, 0.0f);
  }
  if (tileIrradianceActive(frame)) {
    const TileIrradianceLayout l = tileIrradianceLayout(frame);
    b.tileIrradiance =
        glm::vec4(static_cast<float>(l.layers), static_cast<float>(1.0 / l.maxDepth), 0.0f, 0.0f);
    for (int c = 0; c < surface.cascadeCount && c < POSTFX_MAX_CASCADES; ++c) {
      if (l.slot[c] < 0) continue;
      b.cascadeSkip[c].w = static_cast<float>(std::log2(l.resolution / surface.tileSize[c]));
    }
    b.tileDrift = glm::vec4(landingDriftJacobian(sun, surface.ior));
  }

  const bool shadow = hasFeature(create.features, Feature::ShadowMask);
  if (shadow) {
    b.shadowMatrix = saturatedFloat(frame.shadow.worldToLightClip *
                                    glm::translate(glm::dmat4(1.0), camera.position));
  }
  // Reverse-Z stores larger depths nearer the light, so "toward the light" is +bias there.
  const SunShadowMap& map = frame.shadow;
  b.shadowParams =
      glm::vec4(map.bias, map.depthConvention == DepthConvention::ForwardNegOneToOne ? 1.0f : 0.0f,
                0.0f, 0.0f);
  if (shadow) {
    const ShadowLight light = shadowLight(map.worldToLightClip, map.depthConvention);
    const glm::dvec3 relative = light.vector - camera.position;
    b.shadowLight = light.perspective
                        ? glm::vec4(saturatedFloat(relative.x), saturatedFloat(relative.y),
                                    saturatedFloat(relative.z), 1.0f)
                        : glm::vec4(glm::vec3(light.vector), 0.0f);
    const glm::dvec2 perTexel =
        clipUnitsToMetres(map.worldToLightClip) * double(map.normalOffsetTexels);
    b.shadowNormalOffset =
        glm::vec4(saturatedFloat(perTexel.x), saturatedFloat(perTexel.y), 0.0f, 0.0f);
  }
  if (wavefrontAreaRatioActive(create, frame)) {
    const WavefrontAreaRatioLayout l = wavefrontAreaRatioLayout(frame);
    b.irradianceWindow =
        glm::vec4(static_cast<float>(l.windowOrigin.x - camera.position.x),
                  static_cast<float>(l.windowOrigin.y - camera.position.z),
                  static_cast<float>(1.0 / l.windowSize), static_cast<float>(l.layers));
    for (int k = 0; k < l.layers; ++k)
      b.irradianceDepths[k / 4][k % 4] = static_cast<float>(l.depth[k]);
  }
  return b;
}

}  // namespace postfx::detail
