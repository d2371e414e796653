#pragma once
// Caustic casters for Feature::ObjectCaustics (seeds 000 and 003): glass and metal objects the
// plugin draws from the sun's view itself, from the host's own vertex buffers, every frame.
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

enum class CasterMaterialType : std::uint32_t {
  Refractive,  // glass, water drops: refracted at the front and the back surface
  Reflective,  // metal: one specular bounce at the surface facing the sun
};

struct CasterMaterial {
  CasterMaterialType type = CasterMaterialType::Refractive;
  // Absolute index of refraction of the object, (1, 3] (1 accepted: no bending). Under water the
  // plugin divides it by WaterSurface::ior itself.
  float ior = 1.5f;
  // Refractive: Beer-Lambert absorption per metre inside the object, linear RGB, [0, 1e4]:
  // I = I0 * exp(-absorption * d), d the path length between the two surfaces. glTF's
  // KHR_materials_volume gives absorption = -ln(attenuationColor) / attenuationDistance.
  glm::vec3 absorption{0.0f};
  // Reflective: specular colour at normal incidence (Schlick's F0), linear RGB, [0, 1].
  glm::vec3 reflectance{0.95f};
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
  std::int64_t vertexCount = 0;  // vertices in the buffer from baseOffset on, >= 3
  std::int64_t indexCount = 0;   // indices (indexed draws), >= 3, multiple of 3 not required
  std::int64_t baseOffset = 0;   // byte offset of vertex 0 in vertexBuffer, >= 0
  std::int64_t indexOffset = 0;  // byte offset of index 0 in indexBuffer, >= 0
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
  // the resolution of the caster position/normal maps. Cost is linear in gridSize^2.
  int gridSize = 256;
  // Image-space hit iterations against the receivers (seed 000 eq. 1-4: 1 is the paper's
  // choice, 5 gives a negligible error), [1, 8]. When the seed's step oscillates or leaves the
  // bracketed root, a false-position/bisection step replaces it.
  int iterations = 1;
  // The same search for where a refracted ray leaves the glass through its back faces (Wyman's
  // double refraction), [1, 8]. Curved glass needs more than the receivers: a 1 m glass sphere
  // loses 16 % of its flux at 1 (rim rays exit through a misplaced normal and are lost to total
  // internal reflection), 3 % at 3, 0.2 % at 5.
  int exitIterations = 5;
  // Gaussian splat standard deviation in caustic-map texels, [0.5, 8].
  float splatRadius = 1.0f;
  // Side of the caustic map over the side of the casters' footprint, [1, 8]: room for light that
  // lands beside the caster (low sun, strong bending).
  float footprintScale = 2.0f;
  // Multiplier on the sun irradiance for the added light, [0, 1e4].
  float intensity = 1.0f;
  // Seed 003's temporal filter: each frame's map is blended with the previous one (weight
  // temporalWeight on the history), the history clamped to the new frame's 3x3 neighbourhood
  // so that a moving caustic leaves no trail; reset whenever the sun's view moves.
  bool temporalFilter = false;
  float temporalWeight = 0.5f;  // [0, 0.95]
};

}  // namespace postfx
