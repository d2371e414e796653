#pragma once
// What the host hands the plugin every frame. Conventions, once for all fields:
//   * World space: y up, metres. Positions that can be far from the origin are double.
//   * Matrices are glm (column-major), unjittered.
//   * Textures are host-owned GL names. The plugin never deletes, resizes or changes their
//     parameters; it binds them only inside dispatch() and restores every binding it touched.
//   * TextureRef::format is the texture's sized internal format as the host created it (e.g.
//     GL_RGBA16F). It is checked against the texture itself; 0 means "take it from the texture".
#include <cstdint>

#include <glm/glm.hpp>

#include <postfx/casters.h>
#include <postfx/conventions.h>
#include <postfx/range.h>
#include <postfx/reflected_caustics.h>
#include <postfx/settings.h>

namespace postfx {

struct LocalLight;  // postfx/lights.h
struct LocalWater;  // postfx/local_water.h

inline constexpr int kMaxCascades = 4;
inline constexpr Range<double> kSunLengthRange{1e-6, 1e6};            // |Sun::direction|
inline constexpr Range<float> kIrradianceRange{0.0f, 1e9f};           // Sun::irradiance
inline constexpr Range<float> kSunAngularDiameterRange{0.0f, 10.0f};  // degrees
inline constexpr Range<double> kTileSizeRange{1e-3, 1e7};             // m
inline constexpr Range<double> kWaveStatisticRange{0.0, 1e9};         // 1/m and m
inline constexpr Range<float> kIorRange{1.0f, 3.0f};                  // the water's
inline constexpr Range<float> kWaterCoefficientRange{0.0f, 1e3f};     // 1/m
inline constexpr Range<float> kShadowBiasRange{0.0f, 100.0f};         // m
inline constexpr Range<float> kShadowNormalOffsetRange{0.0f, 16.0f};  // shadow-map texels

struct TextureRef {
  GlName texture = 0;
  GlEnum format = 0;
};

struct Camera {
  // Camera position in world space (m). The GPU works relative to it, so it may be ~1e6 m away
  // from the origin without loss. Every world coordinate (this, WaterSurface::level and origin,
  // the casters' world bounds) must lie within +-1e9 m: past it a camera-relative distance, its
  // square or its product with the absorption would overflow the GPU's float, and the frame is
  // refused (InvalidArgument).
  glm::dvec3 position{0.0};
  // World-to-view matrix (camera looks down -Z, +Y up in view space). Only its rotation (upper
  // 3x3, orthonormal) is read; the translation is ignored, so a full view matrix or one with
  // the translation removed (camera-relative) are both fine.
  glm::mat4 view{1.0f};
  // View-to-clip perspective projection, column-major, without TAA jitter, in the depth
  // convention given at create() (reverse-Z: far/infinite plane at window depth 0). Double, so
  // that forward-Z depth reconstruction keeps its precision (see gbuffer::projectionParams); a
  // float glm::mat4 converts implicitly.
  glm::dmat4 projection{1.0};
};

struct Sun {
  // Vector TOWARD the sun, world space. Need not be unit: the plugin normalises it (in double;
  // a scaled vector gives the same image), but its length must be in kSunLengthRange (finite, its
  // square too), else InvalidArgument. direction.y <= 0 (at or below the horizon): no sunlight
  // this frame; the seabed caustics, god rays and the sun's object caustics are skipped.
  glm::dvec3 direction{0.0, 1.0, 0.0};
  // Sun irradiance at the water surface in the host's HDR units, linear RGB, kIrradianceRange.
  glm::vec3 irradiance{1.0f};
  // Angle the sun's disc subtends (degrees), kSunAngularDiameterRange; 0.53 for the real sun.
  // Light reaches each point from a cone this wide, so caustics soften with depth (at 10 m the
  // disc alone blurs them over ~7 cm); the seabed caustics' TileIrradiance field and the god
  // rays built on it convolve with it. 0: a point sun, infinitely sharp folds.
  float angularDiameterDegrees = 0.53f;
};

struct WaterSurface {
  // Mean water surface height y (m). Pixels at or above it receive no caustics.
  double level = 0.0;
  // World xz that maps to texture uv (0,0) in every cascade (m).
  glm::dvec2 origin{0.0};
  // Water surface texture: GL_TEXTURE_2D_ARRAY, one layer per cascade (or GL_TEXTURE_2D with one
  // cascade, see CreateDesc::waterTexture). RG = slopes (dh/dx, dh/dz), B = height (m),
  // A = Jacobian; GL_RGBA16F, GL_RGBA32F, GL_RG16F or GL_RG32F; mipmapped (a single level is
  // accepted and sampled without mips); sampled with GL_REPEAT by the plugin's own sampler.
  // Layer c covers world xz with uv = (xz - origin) / tileSize[c]. The surface normal is
  // normalize(-sum(dh/dx), 1, -sum(dh/dz)) over the cascades.
  // Required when the frame runs seabed caustics or god rays (Feature::Caustics with
  // caustics.enabled, Feature::GodRays with godRays.enabled); a host with object caustics only
  // (glass, no water simulation) may leave it 0, with `level` below its casters so that they are
  // lit by the sun itself. A texture given is always validated.
  TextureRef texture;
  int cascadeCount = 1;                                    // [1, kMaxCascades], <= layer count
  double tileSize[kMaxCascades] = {64.0, 16.0, 4.0, 1.0};  // metres per tile, kTileSizeRange
  // Optional statistics of each cascade's waves (postfx::water::Ocean::waveStats gives them). They
  // let a pixel leave out the cascades it cannot see (CausticsSettings::minCascadeContrast):
  //  - rmsLaplacian (1/m): RMS of the Laplacian of the cascade's height. To first order its
  //    waves modulate the irradiance at path length L below the surface by L*(1-1/n)*rmsLaplacian:
  //    long, gentle waves only tilt the light at shallow depth, they cannot focus it there.
  //  - longestWavelength (m): where a pixel's (or god-ray sample's) footprint is more than half
  //    of it, every wave of the cascade is finer than the footprint and averages out.
  // 0 = unknown: the cascade is always sampled. kWaveStatisticRange.
  double rmsLaplacian[kMaxCascades] = {0.0, 0.0, 0.0, 0.0};
  double longestWavelength[kMaxCascades] = {0.0, 0.0, 0.0, 0.0};
  // Index of refraction of the water relative to air, kIorRange.
  float ior = 1.333f;
  // Per-channel IOR (R, G, B) used instead of `ior` when the context has Feature::Dispersion.
  glm::vec3 iorRgb{1.331f, 1.333f, 1.338f};
  // Beer-Lambert absorption coefficients per metre, linear RGB, kWaterCoefficientRange. The caustic
  // light is attenuated by exp(-absorption * d / cos(theta_t)) for a receiver d metres below the
  // level, theta_t the refracted sun's angle from the vertical. Default: clear sea water.
  glm::vec3 absorption{0.35f, 0.06f, 0.02f};
  // Scattering coefficients per metre, linear RGB, kWaterCoefficientRange: with absorption they
  // give the extinction sigma_t = absorption + scattering that the god rays attenuate with,
  // matching an underwater fog the host computes from the same two values. Only the god rays read
  // it.
  glm::vec3 scattering{0.02f, 0.03f, 0.04f};
  // Local, non-periodic water beside the cascades (postfx/local_water.h): localWaterCount
  // entries, read during dispatch() only, [0, kMaxLocalWater]; regions need Feature::LocalWater
  // (a frame that gives some without it is refused). 0 (default): nothing is read or allocated.
  const LocalWater* localWater = nullptr;
  int localWaterCount = 0;
};

struct SunShadowMap {
  // Depth texture of the sun's shadow map (any depth format, GL_TEXTURE_2D). Required when the
  // context has Feature::ShadowMask, ignored otherwise. Sampled with the plugin's own comparison
  // sampler (bilinear PCF), whatever the texture's own compare mode.
  TextureRef depth;
  // World-space to light clip-space matrix (light projection * light view), in DOUBLE, with the
  // world translation included. The plugin rebases it onto the camera in double precision.
  glm::dmat4 worldToLightClip{1.0};
  DepthConvention depthConvention = DepthConvention::ForwardZeroToOne;  // it was rendered with
  // Metres the receiver is moved toward the light before the comparison, kShadowBiasRange:
  // one value for any depth range. For the receiver map of the object caustics, the most a
  // pixel may lie off the receiver surface along the light to receive caustic light.
  float bias = 0.02f;
  // Normal offset: a surface point is moved along its G-buffer normal by this many of the map's
  // texels (their world size at the point, from worldToLightClip and the texture's size), times
  // the sine of its angle to the light, kShadowNormalOffsetRange. 1.5 clears the 2x2 PCF
  // footprint (sqrt(2) texels) at any angle: no acne on walls or at grazing light. Sun shadow
  // map only (the god rays' points in the water have no normal; the receiver map ignores it).
  float normalOffsetTexels = 1.5f;
};

// Feature::ObjectCaustics inputs (see postfx/casters.h for what the host does around the pass).
struct ObjectCausticsFrame {
  const CasterMesh* casters = nullptr;  // casterCount entries, read during dispatch() only
  int casterCount = 0;                  // [0, kMaxCasters]; 0 = pass skipped (0 ms)
  // Receiver depth from the sun WITHOUT the casters (any depth format, GL_TEXTURE_2D, any
  // orthographic or perspective projection that sees where the light lands): the refracted rays
  // are intersected with it in image space and the composite adds light only where a pixel lies
  // on it (within `bias` metres of it along the light). Cleared texels (far plane) are "no
  // receiver". Required while casterCount > 0 and sunCaustics.
  SunShadowMap receivers;
  ObjectCausticsSettings settings;
  // Point and spot lights whose light the casters focus too (postfx/lights.h): lightCount
  // entries, read during dispatch() only. lightCount in [0, CreateDesc::maxLocalLights]; more is
  // refused (InvalidArgument naming objectCaustics.lightCount). Each light is traced with the
  // same settings as the sun.
  const LocalLight* lights = nullptr;
  int lightCount = 0;
  // The sun's object caustics, exactly as without lights. false: the sun is left out (its
  // `receivers` are then neither read nor required) and only the lights make caustics.
  bool sunCaustics = true;
};

// Who attenuates the light the plugin adds along the view ray, from the lit point (or, for god
// rays, each in-scattering sample) to the camera, by exp(-sigma_t * submerged length),
// sigma_t = WaterSurface::absorption + scattering: exactly one of the two, never both.
enum class ViewExtinction : std::uint8_t {
  // The plugin (default). Caustic light arrives attenuated and god rays carry their own
  // per-sample extinction: apply your underwater fog to your own lit buffer BEFORE dispatch and
  // leave what dispatch adds unfogged.
  Plugin,
  // Your fog, applied to the whole target AFTER dispatch: caustic light is added unattenuated.
  // God rays are in-scattered light that no after-the-fact fog can attenuate right, so a frame
  // with god rays to draw is refused (InvalidArgument) in this mode.
  Host,
};

struct FrameDesc {
  // Host G-buffer, GL_TEXTURE_2D, all the same size (the size of `target`).
  TextureRef depth;   // GL_DEPTH_COMPONENT16/24/32/32F or DEPTH24_STENCIL8/DEPTH32F_STENCIL8
                      // (depth-stencil textures in GL_DEPTH_STENCIL_TEXTURE_MODE = DEPTH)
  TextureRef normal;  // world-space normal in CreateDesc::normalEncoding
  TextureRef albedo;  // GL_RGBA8, GL_SRGB8_ALPHA8, GL_RGBA16F, GL_RGB10_A2 (linear rgb read)
  // Host HDR light buffer the caustic light and god rays are ADDED to (blend ONE, ONE; alpha
  // untouched): GL_RGBA16F, GL_RGBA32F or GL_R11F_G11F_B10F, mip level 0.
  TextureRef target;
  Camera camera;
  Sun sun;
  WaterSurface water;
  SunShadowMap shadow;
  CausticsSettings caustics;
  GodRaySettings godRays;  // read only with Feature::GodRays
  // Read only with Feature::ReflectedCaustics (postfx/reflected_caustics.h).
  ReflectedCausticsSettings reflectedCaustics;
  ObjectCausticsFrame objectCaustics;                      // read only with Feature::ObjectCaustics
  ViewExtinction viewExtinction = ViewExtinction::Plugin;  // all the light dispatch() adds
};

}  // namespace postfx
