#pragma once
// Input validation. Everything here only reads: CPU values and GL *queries* (no binds, no state
// changes, no GL errors), so a rejected call leaves the host's GL state untouched.
#include <epoxy/gl.h>

#include <initializer_list>
#include <string>

#include <postfx/postfx.h>

#include "core/frame_geometry.h"

namespace postfx::detail {

// World coordinates the plugin accepts (camera, water level and origin, caster bounds), in
// metres: every camera- or anchor-relative distance then stays below 2e9 m, so that it, its
// square and its product with the largest coefficient (absorption / cos, <= 1e9 per metre)
// are finite in the GPU's float. Past it a frame is refused rather than drawn with Inf or NaN.
inline constexpr double kMaxWorldCoordinate = 1e9;
inline std::string worldExtentText() {
  return "1e9";
}
// A number as a message prints it (a range's bound, a value refused): %g's six significant
// digits ("100", "0.5", "1e+06", "-1e+30", "nan"); a vector as "(x, y, z)".
std::string number(double value);
std::string number(const glm::vec3& value);

// The range as a message prints it, "[0, 1e6]".
template <typename T>
std::string rangeText(Range<T> r) {
  // Appended, not "[" + string: GCC 12 warns falsely (-Wrestrict) on that operator+.
  std::string text = "[";
  text += number(double(r.min));
  text += ", ";
  text += number(double(r.max));
  text += "]";
  return text;
}
// " must be in [min, max]<unit>, got <value>": the tail of every out-of-range refusal, so that
// each names the accepted range and what it was handed. `unit` starts with its space (" m").
template <typename T, typename V>
std::string mustBeIn(const V& value, Range<T> r, const char* unit = "") {
  std::string text = " must be in ";
  text += rangeText(r);
  text += unit;
  text += ", got ";
  text += number(value);
  return text;
}
// "<field> <value> is not a <type> (<accepted>)": the refusal of an enum out of its values.
std::string notAnEnum(const std::string& field, long long value, const char* type,
                      const char* accepted);
// Whether the value (every component of a vector) lies in the range; NaN never does.
template <typename T>
bool within(double value, Range<T> r) {
  return value >= double(r.min) && value <= double(r.max);
}
template <typename T>
bool within(const glm::vec3& v, Range<T> r) {
  return within(v.x, r) && within(v.y, r) && within(v.z, r);
}

Result validateCreateDesc(const CreateDesc& desc, std::string& error);

// How many water cascades the context's shaders are written for (a valid desc's).
inline int waterCascadeSlots(const CreateDesc& desc) {
  return desc.waterTexture == WaterTextureType::Single2D ? 1 : desc.maxWaterCascades;
}

// CPU-only checks of the frame, in this order: camera, sun, water, shadow, view extinction, then
// each feature's settings (seabed_caustics/caustics_validation.h, god_rays/godrays_validation.h).
Result validateFrameValues(const CreateDesc& create, const FrameDesc& frame, std::string& error);

// What the texture checks learnt, for the pass.
struct ValidatedTextures {
  // The view's rectangle in its target (ViewDesc::viewport; the whole target for a FrameDesc):
  // lower-left pixel and size. Every pass works in it; the blocks describe its size.
  int x = 0, y = 0;
  int width = 0, height = 0;
  int targetWidth = 0, targetHeight = 0;  // of the target (= G-buffer)
  WaterTextureInfo water;
  bool waterMipmapped = false;  // mip-complete: sample with mips; otherwise level 0 only
};

// What checkTexture learnt of a texture.
struct TextureFacts {
  GLint target = 0, format = 0, width = 0, height = 0, layers = 0;
};
// One host texture: a texture name with level-0 storage, one of `targets`, its declared format
// (ref.format, 0: any) its real one, and one of `formats`; messages begin with `field`.
Result checkTexture(const char* field, const TextureRef& ref, std::initializer_list<GLenum> targets,
                    std::initializer_list<GLenum> formats, TextureFacts& facts, std::string& error);

// GL-query checks of every texture: a texture name, the right target and format, sizes that
// match. Runs after validateFrameValues.
// A host depth texture (GL_TEXTURE_2D, depth format, depth mode): the checks every depth input
// gets, for the object caustics' receiver map.
Result checkDepthTexture(const char* field, const TextureRef& ref, std::string& error);

Result validateFrameTextures(const CreateDesc& create, const FrameDesc& frame,
                             ValidatedTextures& out, std::string& error);

}  // namespace postfx::detail
