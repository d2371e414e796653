#pragma once
// Caustic casters for Feature::ObjectCaustics: glass and metal objects the plugin draws from
// the sun's (and each local light's) view itself, from the host's own vertex buffers, every
// frame, traces a ray grid through and splats where the rays land (docs/passes.md).
//
// Ownership: the buffers are host-owned GL names. The plugin reads them only inside dispatch()
// through a vertex array of its own (DSA attachment: the host's VAO, GL_ARRAY_BUFFER and
// GL_ELEMENT_ARRAY_BUFFER bindings are never touched), never writes, deletes or maps them, and
// restores every piece of GL state it changes. The CasterMesh array only has to live for the
// dispatch() call.
//
// What the host does around the pass:
//   * It keeps the casters in its own sun shadow map as opaque occluders, so its lighting
//     already removes the direct light a caster blocks. The plugin adds back the light that
//     passes through (or is reflected by) the caster, focused: shadow + caustic = the light a
//     glass object lets through. (With IOR 1 and no absorption the caustic exactly refills the
//     shadow, less the Fresnel losses.)
//   * It hands a receiver depth map (ObjectCausticsFrame::receivers) rendered from the sun
//     WITHOUT the casters: the surfaces the refracted and reflected rays land on. Its sun shadow
//     map rendered with the casters masked out is exactly that.
#include <cstdint>

#include <glm/glm.hpp>

#include <postfx/conventions.h>

namespace postfx {

inline constexpr int kMaxCasters = 64;  // casters per frame

// Limits of the glTF-style glass fields of CasterMaterial.
// A rough surface spreads a ray's light over a cone; its splat grows with the distance to the
// receiver up to this standard deviation (caster-map texels). The cap (on the round part, and
// apart on the stretch along the rays' spread) bounds a sprite to 2 * ceil(3 * 16 * sqrt(2)) + 1
// = 137 texels a side, and so the cost of a rough caster; wider would be a faint wash anyway.
inline constexpr float kMaxRoughSplatSigma = 16.0f;
// KHR_materials_dispersion's value is 20 / Abbe number; [0, 1] are real materials, rutile is
// 2.04. At this cap the half spread is a quarter of (ior - 1), so the red index stays above 1.
inline constexpr float kMaxCasterDispersion = 10.0f;

enum class CasterMaterialType : std::uint32_t {
  Refractive,  // glass, water drops: refracted at the front and the back surface
  Reflective,  // metal: one specular bounce at the surface facing the sun
};

struct CasterMaterial {
  CasterMaterialType type = CasterMaterialType::Refractive;
  // Absolute index of refraction of the object, [1, 3] (1: no bending). Under water the plugin
  // divides it by WaterSurface::ior itself.
  float ior = 1.5f;
  // Refractive: Beer-Lambert absorption per metre inside the object, linear RGB, [0, 1e4]:
  // I = I0 * exp(-absorption * d), d the path length between the two surfaces. glTF's
  // KHR_materials_volume gives absorption = -ln(attenuationColor) / attenuationDistance.
  glm::vec3 absorption{0.0f};
  // Reflective: specular colour at normal incidence (Schlick's F0), linear RGB, [0, 1].
  glm::vec3 reflectance{0.95f};

  // glTF-style glass (KHR_materials_transmission, _volume, _dispersion); the defaults are
  // clear, smooth, solid glass.
  //
  // Refractive: the share of the light crossing the surface that goes on as a refracted ray,
  // [0, 1] (glTF transmissionFactor x (1 - metallic)); the rest is scattered diffusely by the
  // host's shading and focuses nothing. The caustic's flux scales with it.
  float transmission = 1.0f;
  // Refractive: colour of the transmitted light, linear RGB, [0, 1] (glTF baseColorFactor.rgb
  // tints transmission). Applied once per ray, whatever the path length; absorption is the
  // path-length-dependent colour.
  glm::vec3 tint{1.0f};
  // Refractive: a thin-walled shell (glTF: no KHR_materials_volume, or thicknessFactor 0): the
  // ray crosses two parallel interfaces close together, so it keeps its direction (no focusing,
  // no offset), loses the Fresnel reflection of both, and is not absorbed (no volume). False: a
  // solid, refracted where it enters and where it leaves, absorbed along the traversed chord.
  bool thinWalled = false;
  // Both types: glTF perceptual roughness, [0, 1]. The outgoing ray is spread over a cone of
  // angular standard deviation alpha = roughness^2 radians (GGX alpha, the microfacet normals'
  // spread), so its splat's standard deviation grows to
  //   sqrt(splatRadius^2 + (alpha * d / texel)^2) texels, at most kMaxRoughSplatSigma,
  // d the distance from where the ray leaves the caster to where it lands. The flux of the
  // splat is unchanged: a rough caster's caustic is wider and dimmer, never brighter.
  float roughness = 0.0f;
  // Refractive, only when the context has Feature::Dispersion: KHR_materials_dispersion
  // (20 / Abbe number), [0, kMaxCasterDispersion]. Each colour channel is traced with its own
  // IOR, as the extension's implementation note gives: half spread h = (ior - 1) * 0.025 *
  // dispersion, IOR (ior - h, ior, ior + h) for (R, G, B), red at least 1. 0: one IOR, one ray.
  float dispersion = 0.0f;
};

// One caster: a triangle list read from the host's buffers.
// Vertex format: float32 x3 position and (optionally) float32 x3 normal in model space, at byte
// offsets inside a vertex of `stride` bytes. normalOffset < 0: flat normals are derived from
// the triangles. Indices, when given, must all be < vertexCount (not checked: reading them
// would stall).
struct CasterMesh {
  std::uint32_t vertexBuffer = 0;  // GL buffer name (required)
  std::uint32_t indexBuffer = 0;   // GL buffer name, 0 = non-indexed (vertexCount vertices)
  IndexType indexType = IndexType::UnsignedInt;  // of indexBuffer's indices
  // Counts are at most 2^31 - 1 (one GL draw). The buffers must hold every vertex (position
  // and normal of the last one included) and index from the offsets on; checked without
  // overflow for any value, else SizeMismatch.
  std::int64_t vertexCount = 0;  // vertices from baseOffset on, >= 1 (>= 3 when non-indexed)
  std::int64_t indexCount = 0;   // indices (indexed draws), >= 3, multiple of 3 not required
  std::int64_t baseOffset = 0;   // byte offset of vertex 0 in vertexBuffer, >= 0
  std::int64_t indexOffset = 0;  // byte offset of index 0, >= 0, a multiple of the index size
  int positionOffset = 0;        // bytes, >= 0, position + 12 <= stride
  int normalOffset = 12;         // bytes, < 0 = none, normal + 12 <= stride
  int stride = 24;               // bytes, [12, 2048]
  // Model-space bounding box of the vertices: the plugin fits the sun's view to it without
  // reading the buffers back. min <= max, finite.
  glm::vec3 boundsMin{-1.0f}, boundsMax{1.0f};
  // Model to world, in DOUBLE (world positions may be far from the origin); finite, invertible.
  glm::dmat4 modelToWorld{1.0};
  CasterMaterial material;
};

// How Feature::VolumeCaustics draws each traced ray's in-scattered light into the view.
enum class VolumeCausticsMethod : std::uint32_t {
  // Each ray a beam whose cross-section is a Gaussian as wide as half the spacing of its
  // neighbouring rays (interpolated from where they leave the caster to where they land, at
  // least the pixel's footprint): a camera-facing quad per ray, the view ray's closest approach
  // to the beam weighted by the 1D kernel (photon beams, beam x beam 1D). Smooth at any grid.
  Beams,
  // Each ray a one-pixel GL line (illumination rays drawn as lines): cheaper per ray, but the
  // cone breaks into separate lines where the rays are sparser than the pixels.
  Lines,
};

// The light a caster's rays scatter toward the camera in the water between the caster and where
// they land (Feature::VolumeCaustics): single scattering with the god rays' model, so it fills
// the shadow the host's shadow map cuts into the shafts (postfx/settings.h, GodRaySettings):
//   L = sum over rays of P * phase * sigma_s * k(b) / sin(theta) * T_light * T_view * rho(depth)
// P the ray's power (the sun's irradiance, or the light's intensity, times its grid cell's area
// or solid angle, Fresnel, transmission, tint and the glass's absorption), phase =
// GodRaySettings::intensity, sigma_s and sigma_t = absorption + scattering from WaterSurface,
// T_light = exp(-sigma_t * the ray's path in water from the surface or the light),
// T_view = exp(-sigma_t * the view ray's path in water), rho the god rays' surface and depth fade,
// k the method's 1D kernel in the distance b between the view ray and the ray, theta their angle.
// Beyond GodRaySettings::maxDistance from the camera nothing is added (as the shafts). Only the
// part of a ray under the water level scatters; rays that land on no receiver are not drawn.
struct VolumeCausticsSettings {
  bool enabled = true;  // off: nothing is drawn and no extra ray data is written (0 ms)
  VolumeCausticsMethod method = VolumeCausticsMethod::Beams;
};

// Per-frame tuning of the object caustics, a plain struct with defaults. Out-of-range values:
// dispatch() returns InvalidArgument and draws nothing.
struct ObjectCausticsSettings {
  bool enabled = true;  // off: the pass is skipped (0 ms)
  // Caustic map texels per side, [16, GL_MAX_TEXTURE_SIZE]. The map covers the casters' sun
  // footprint times footprintScale. It and its temporal history take 48 bytes per texel
  // (RGBA32F x 3): 12 MiB at 512, 3 GiB at 8192; a frame over CreateDesc::memoryBudgetMiB is
  // refused with OutOfMemory before anything is drawn.
  int mapSize = 512;
  // Light rays per side of the regular grid over the casters' sun footprint, [16, 2048]; also
  // the resolution of the caster position/normal maps. Cost is linear in gridSize^2, and so is
  // memory: 84 bytes per ray (the caster maps and where each ray lands; 148 with
  // Feature::Dispersion, which traces each colour alone): 5.3 MiB at 256.
  int gridSize = 256;
  // Image-space hit iterations against the receivers (the caustics-mapping estimate of where a
  // ray meets the receiver depth, refined: 1 is that method's own choice, 5 gives a negligible
  // error), [1, 8]. When a step oscillates or leaves the bracketed root, a
  // false-position/bisection step replaces it.
  int iterations = 1;
  // The same search for where a refracted ray leaves the glass through its back faces (double
  // refraction), [1, 8]. Curved glass needs more than the receivers: too few misplace the exit
  // normal of rim rays, which are then lost to total internal reflection (docs/passes.md).
  int exitIterations = 5;
  // Gaussian splat standard deviation in caustic-map texels, [0.5, 8].
  float splatRadius = 1.0f;
  // Side of the caustic map over the side of the casters' footprint, [1, 8]: room for light that
  // lands beside the caster (low sun, strong bending).
  float footprintScale = 2.0f;
  // Multiplier on the sun irradiance for the added light, [0, 1e4].
  float intensity = 1.0f;
  // Temporal filter of the sun's caustic map: blended with the previous frame's (weight
  // temporalWeight on the history, clamped to the new frame's 3x3 neighbourhood so that a
  // moving caustic leaves no trail). The history is dropped whenever the map, refitted around
  // the casters every frame, lies anywhere else: the sun turns, or the casters' bounds move
  // (along the light by any amount, across it by about a ray cell). So a moving caster is in
  // effect never filtered; still casters under moving water are. Local lights: no filter.
  bool temporalFilter = false;
  float temporalWeight = 0.5f;  // history weight, [0, 0.95]
  // Read only with Feature::VolumeCaustics: the rays' light in the water (48 more bytes per ray
  // and colour channel while the feature is on).
  VolumeCausticsSettings volume;
};

}  // namespace postfx
