#include "core/validation.h"

#include "core/convention_checks.h"
#include "core/gl_enum_names.h"
#include "core/texture_format.h"
#include "god_rays/godrays_validation.h"
#include "reflected_caustics/reflected_validation.h"
#include "seabed_caustics/caustics_validation.h"
#include "seabed_caustics/local_water_validation.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <initializer_list>
#include <sstream>
#include <utility>

namespace postfx::detail {
namespace {

bool finite(const glm::dvec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}
bool withinWorld(const glm::dvec3& p) {
  return std::abs(p.x) <= kMaxWorldCoordinate && std::abs(p.y) <= kMaxWorldCoordinate &&
         std::abs(p.z) <= kMaxWorldCoordinate;
}
bool finite(const glm::mat4& m) {
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r)
      if (!std::isfinite(m[c][r])) return false;
  return true;
}
bool finite(const glm::dmat4& m) {
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r)
      if (!std::isfinite(m[c][r])) return false;
  return true;
}

// NaN fails both comparisons, so it is caught by the same test as an out-of-range value.
bool inRange(double value, double lo, double hi) {
  return value >= lo && value <= hi;
}

}  // namespace

std::string number(double value) {
  std::ostringstream s;
  s << value;
  return s.str();
}

std::string number(const glm::vec3& value) {
  // Appended, not "(" + string: GCC 12 warns falsely (-Wrestrict) on that operator+.
  std::string text = "(";
  text += number(double(value.x));
  text += ", ";
  text += number(double(value.y));
  text += ", ";
  text += number(double(value.z));
  text += ")";
  return text;
}

std::string notAnEnum(const std::string& field, long long value, const char* type,
                      const char* accepted) {
  std::string text = field;
  text += " ";
  text += std::to_string(value);
  text += " is not a ";
  text += type;
  text += " (";
  text += accepted;
  text += ")";
  return text;
}

namespace {

std::string formatName(GLenum format) {
  return glEnumName(format);
}

// Every query here is valid for any texture name of any kind, so none can raise a GL error in
// the host's context. The target is the one fact that needs care: glGetTextureParameteriv
// refuses buffer textures (GL_INVALID_OPERATION in Mesa), while level-0 queries accept every
// kind. So the level is read first: a buffer texture names its buffer there, and one without a
// buffer has no width; only a texture that is neither is asked for its target.
bool queryTexture(GLuint texture, TextureFacts& facts) {
  if (texture == 0 || glIsTexture(texture) != GL_TRUE) return false;
  GLint buffer = 0;
  glGetTextureLevelParameteriv(texture, 0, GL_TEXTURE_BUFFER_DATA_STORE_BINDING, &buffer);
  glGetTextureLevelParameteriv(texture, 0, GL_TEXTURE_INTERNAL_FORMAT, &facts.format);
  glGetTextureLevelParameteriv(texture, 0, GL_TEXTURE_WIDTH, &facts.width);
  glGetTextureLevelParameteriv(texture, 0, GL_TEXTURE_HEIGHT, &facts.height);
  glGetTextureLevelParameteriv(texture, 0, GL_TEXTURE_DEPTH, &facts.layers);
  if (buffer != 0) {
    facts.target = GL_TEXTURE_BUFFER;
  } else if (facts.width > 0) {
    glGetTextureParameteriv(texture, GL_TEXTURE_TARGET, &facts.target);
  }  // else no storage (or a buffer texture without a buffer): target left 0, reported below
  return true;
}

constexpr std::initializer_list<GLenum> kDepthFormats = {
    GL_DEPTH_COMPONENT16,  GL_DEPTH_COMPONENT24, GL_DEPTH_COMPONENT32,
    GL_DEPTH_COMPONENT32F, GL_DEPTH24_STENCIL8,  GL_DEPTH32F_STENCIL8};

std::initializer_list<GLenum> normalFormats(NormalEncoding encoding) {
  static constexpr std::initializer_list<GLenum> octahedral = {
      GL_RG16_SNORM, GL_RG8_SNORM, GL_RG16F, GL_RG32F, GL_RGBA16_SNORM, GL_RGBA16F, GL_RGBA32F};
  static constexpr std::initializer_list<GLenum> xyz = {
      GL_RGB16F,      GL_RGBA16F,      GL_RGB32F,      GL_RGBA32F,
      GL_RGB16_SNORM, GL_RGBA16_SNORM, GL_RGBA8_SNORM, GL_R11F_G11F_B10F};
  static constexpr std::initializer_list<GLenum> unorm = {GL_RGBA8, GL_RGB8, GL_RGB10_A2, GL_RGBA16,
                                                          GL_RGB16};
  return encoding == NormalEncoding::Octahedral
             ? octahedral
             : (encoding == NormalEncoding::WorldXyz ? xyz : unorm);
}

Result checkDepthMode(const char* field, GLuint texture, std::string& error) {
  GLint mode = GL_DEPTH_COMPONENT;
  glGetTextureParameteriv(texture, GL_DEPTH_STENCIL_TEXTURE_MODE, &mode);
  if (mode != GL_DEPTH_COMPONENT) {
    error = std::string(field) +
            ": depth-stencil texture is in GL_STENCIL_INDEX mode; set "
            "GL_DEPTH_STENCIL_TEXTURE_MODE to GL_DEPTH_COMPONENT";
    return Result::UnsupportedFormat;
  }
  return Result::Ok;
}

// Mip levels the water texture can be sampled with. A texture made with glTexStorage is always
// complete; otherwise the chain must reach the smallest level (or GL_TEXTURE_MAX_LEVEL).
bool isMipComplete(GLuint texture, int width, int height) {
  GLint immutable = GL_FALSE;
  glGetTextureParameteriv(texture, GL_TEXTURE_IMMUTABLE_FORMAT, &immutable);
  int fullChain = 1;
  for (int size = std::max(width, height); size > 1; size >>= 1) ++fullChain;
  if (immutable == GL_TRUE) {
    GLint levels = 1;
    glGetTextureParameteriv(texture, GL_TEXTURE_IMMUTABLE_LEVELS, &levels);
    return levels > 1;
  }
  GLint baseLevel = 0, maxLevel = 1000;
  glGetTextureParameteriv(texture, GL_TEXTURE_BASE_LEVEL, &baseLevel);
  glGetTextureParameteriv(texture, GL_TEXTURE_MAX_LEVEL, &maxLevel);
  if (baseLevel != 0) return false;
  const int needed = std::min(fullChain, maxLevel + 1);
  if (needed <= 1) return false;
  for (int level = 1; level < needed; ++level) {
    GLint w = 0;
    glGetTextureLevelParameteriv(texture, level, GL_TEXTURE_WIDTH, &w);
    if (w <= 0) return false;
  }
  return true;
}

Result checkShadowTexture(const CreateDesc& create, const FrameDesc& frame, std::string& error) {
  if (!hasFeature(create.features, Feature::ShadowMask)) return Result::Ok;
  TextureFacts shadow;
  const Result r = checkTexture("shadow.depth", frame.shadow.depth, {GL_TEXTURE_2D}, kDepthFormats,
                                shadow, error);
  return r != Result::Ok ? r : checkDepthMode("shadow.depth", frame.shadow.depth.texture, error);
}

}  // namespace

Result checkTexture(const char* field, const TextureRef& ref, std::initializer_list<GLenum> targets,
                    std::initializer_list<GLenum> formats, TextureFacts& facts,
                    std::string& error) {
  // A renderbuffer's name is also a texture's in GL's separate namespaces (LearnOpenGL's
  // G-buffer depth is a renderbuffer): say so whatever the texture of that name is.
  const bool renderbuffer = ref.texture != 0 && glIsRenderbuffer(ref.texture) == GL_TRUE;
  const std::string renderbufferHint =
      renderbuffer ? std::string("; ") + std::to_string(ref.texture) +
                         " is also a renderbuffer's name: the plugin samples its inputs, so "
                         "each must be a texture (attach a texture with "
                         "glNamedFramebufferTexture instead of the renderbuffer)"
                   : std::string();
  const std::string fix = std::string("; allocate it as one with glTextureStorage2D(texture, 1, ") +
                          glEnumName(*formats.begin()) + ", width, height)";
  if (!queryTexture(ref.texture, facts)) {
    error = std::string(field) + ": " + std::to_string(ref.texture) + " is not a texture name" +
            (renderbuffer ? " but a renderbuffer's: the plugin samples its inputs, so each must "
                            "be a texture (attach one with glNamedFramebufferTexture instead)"
                          : " (a texture is required)");
    return Result::MissingTexture;
  }
  if (facts.width <= 0 || facts.height <= 0) {
    error = std::string(field) + ": texture " + std::to_string(ref.texture) +
            " has no storage at level 0 (give it some with glTextureStorage2D)" + renderbufferHint;
    return Result::MissingTexture;
  }
  if (std::find(targets.begin(), targets.end(), static_cast<GLenum>(facts.target)) ==
      targets.end()) {
    error = std::string(field) + ": texture target " + formatName(facts.target) +
            " is not accepted here (" + formatList(targets) + ")" + renderbufferHint;
    return Result::UnsupportedFormat;
  }
  const GLenum reported = static_cast<GLenum>(facts.format);
  const GLenum sized = effectiveSizedFormat(ref.texture, reported);
  // A declaration matches the name GL reports or the sized format an unsized one stands for.
  if (ref.format != 0 && ref.format != reported && ref.format != sized) {
    error = std::string(field) + ": TextureRef::format declares " + formatName(ref.format) +
            " but texture " + std::to_string(ref.texture) + "'s internal format is " +
            formatName(reported) +
            (sized != 0 && sized != reported ? " (" + formatName(sized) + ")" : std::string()) +
            "; pass the texture the declaration names, or declare 0 to skip this check" +
            renderbufferHint;
    return Result::UnsupportedFormat;
  }
  if (std::find(formats.begin(), formats.end(), sized) == formats.end()) {
    std::string what = "internal format " + formatName(reported);
    if (isUnsizedFormat(reported))
      what += sized != 0 ? " (unsized; its components are " + formatName(sized) + "'s)"
                         : " (unsized, with components no accepted format has)";
    error = std::string(field) + ": " + what + " is not accepted here (" + formatList(formats) +
            ")" + fix + renderbufferHint;
    return Result::UnsupportedFormat;
  }
  facts.format = static_cast<GLint>(sized);
  return Result::Ok;
}

Result checkDepthTexture(const char* field, const TextureRef& ref, std::string& error) {
  TextureFacts facts;
  const Result r = checkTexture(field, ref, {GL_TEXTURE_2D}, kDepthFormats, facts, error);
  return r != Result::Ok ? r : checkDepthMode(field, ref.texture, error);
}

Result validateCreateDesc(const CreateDesc& desc, std::string& error) {
  if (static_cast<std::uint32_t>(desc.features) >= (1u << 14)) {
    char bits[16];
    std::snprintf(bits, sizeof bits, "0x%x", static_cast<unsigned>(desc.features) & ~0x3fffu);
    error = std::string("CreateDesc.features: unknown feature bits ") + bits +
            " (the known ones are 0x1-0x2000, postfx::Feature)";
    return Result::InvalidArgument;
  }
  if (hasFeature(desc.features, Feature::VolumeCaustics) &&
      !hasFeature(desc.features, Feature::ObjectCaustics)) {
    error = "CreateDesc.features: VolumeCaustics needs ObjectCaustics (it draws the casters' rays)";
    return Result::InvalidArgument;
  }
  if (!isDepthConvention(desc.depthConvention)) {
    error = notAnEnum("CreateDesc.depthConvention", static_cast<long long>(desc.depthConvention),
                      "DepthConvention", "ReverseZ, ForwardZeroToOne or ForwardNegOneToOne");
    return Result::InvalidArgument;
  }
  if (!isNormalEncoding(desc.normalEncoding)) {
    error = notAnEnum("CreateDesc.normalEncoding", static_cast<long long>(desc.normalEncoding),
                      "NormalEncoding", "Octahedral, WorldXyz or WorldXyzUnorm");
    return Result::InvalidArgument;
  }
  if (desc.waterTexture != WaterTextureType::Array2D &&
      desc.waterTexture != WaterTextureType::Single2D) {
    error = notAnEnum("CreateDesc.waterTexture", static_cast<long long>(desc.waterTexture),
                      "WaterTextureType", "Array2D or Single2D");
    return Result::InvalidArgument;
  }
  if (desc.waterTexture == WaterTextureType::Array2D &&
      (desc.maxWaterCascades < 1 || desc.maxWaterCascades > kMaxCascades)) {
    error = "CreateDesc.maxWaterCascades must be in [1, " + std::to_string(kMaxCascades) +
            "], got " + std::to_string(desc.maxWaterCascades);
    return Result::InvalidArgument;
  }
  if (desc.maxLocalLights < 0 || desc.maxLocalLights > kMaxLocalLightsLimit) {
    error = "CreateDesc.maxLocalLights must be in [0, " + std::to_string(kMaxLocalLightsLimit) +
            "], got " + std::to_string(desc.maxLocalLights);
    return Result::InvalidArgument;
  }
  if (desc.memoryBudgetMiB < 1 || desc.memoryBudgetMiB > (1 << 20)) {
    error = "CreateDesc.memoryBudgetMiB must be in [1, 1048576], got " +
            std::to_string(desc.memoryBudgetMiB);
    return Result::InvalidArgument;
  }
  constexpr std::int64_t kMaxWorkBudget = std::int64_t(1) << 40;
  for (const auto& [value, name] : {std::pair{desc.casterTriangleBudget, "casterTriangleBudget"},
                                    std::pair{desc.splatBudget, "splatBudget"}}) {
    if (value < 1 || value > kMaxWorkBudget) {
      error =
          std::string("CreateDesc.") + name + " must be in [1, 2^40], got " + std::to_string(value);
      return Result::InvalidArgument;
    }
  }
  return Result::Ok;
}

Result validateFrameValues(const CreateDesc& create, const FrameDesc& frame, std::string& error) {
  auto fail = [&error](std::string message) {
    error = std::move(message);
    return Result::InvalidArgument;
  };
  const Camera& camera = frame.camera;
  if (!finite(camera.position)) return fail("camera.position is not finite");
  if (!withinWorld(camera.position))
    return fail("camera.position must lie within +-" + worldExtentText() + " m of the origin");
  if (!finite(camera.view)) return fail("camera.view is not finite");
  if (!finite(camera.projection)) return fail("camera.projection is not finite");
  const glm::dmat3 rotation = glm::dmat3(glm::mat3(camera.view));
  const glm::dmat3 gram = glm::transpose(rotation) * rotation;
  for (int c = 0; c < 3; ++c)
    for (int r = 0; r < 3; ++r)
      if (std::abs(gram[c][r] - (c == r ? 1.0 : 0.0)) > 1e-3)
        return fail("camera.view: the upper 3x3 is not a rotation (orthonormal)");
  const glm::dmat4& p = camera.projection;
  // Bounded so that the floats made from it (and 2 / (P[1][1] * height)) stay finite.
  for (const double entry : {p[0][0], p[1][1], p[2][0], p[2][1], p[2][2], p[3][2]})
    if (!(std::abs(entry) <= 1e30)) return fail("camera.projection: entries must be within +-1e30");
  if (!(std::abs(p[0][0]) >= 1e-30 && std::abs(p[1][1]) >= 1e-30))
    return fail("camera.projection: P[0][0] and P[1][1] must be at least 1e-30 in magnitude");
  if (p[0][0] == 0.0 || p[1][1] == 0.0 || std::abs(p[2][3] + 1.0) > 1e-5 ||
      std::abs(p[3][3]) > 1e-5 || p[3][2] == 0.0)
    return fail("camera.projection is not a perspective projection (P[2][3] = -1, P[3][3] = 0)");

  // The length is formed from components already bounded, so its square cannot overflow (a
  // sun of (0, 1e300, 0) once had an infinite length and was normalised to zero).
  const Sun& sun = frame.sun;
  const double maxSun = kSunLengthRange.max;
  if (!inRange(sun.direction.x, -maxSun, maxSun) || !inRange(sun.direction.y, -maxSun, maxSun) ||
      !inRange(sun.direction.z, -maxSun, maxSun) ||
      !within(glm::length(sun.direction), kSunLengthRange))
    return fail("sun.direction must be finite with a length in " + rangeText(kSunLengthRange) +
                " (it is normalised)");
  if (!within(sun.irradiance, kIrradianceRange))
    return fail("sun.irradiance" + mustBeIn(sun.irradiance, kIrradianceRange));
  if (!within(sun.angularDiameterDegrees, kSunAngularDiameterRange))
    return fail("sun.angularDiameterDegrees" +
                mustBeIn(sun.angularDiameterDegrees, kSunAngularDiameterRange));

  const WaterSurface& water = frame.water;
  if (!std::isfinite(water.level)) return fail("water.level is not finite");
  if (!inRange(water.level, -kMaxWorldCoordinate, kMaxWorldCoordinate))
    return fail("water.level must lie within +-" + worldExtentText() + " m");
  if (!std::isfinite(water.origin.x) || !std::isfinite(water.origin.y))
    return fail("water.origin is not finite");
  if (!inRange(water.origin.x, -kMaxWorldCoordinate, kMaxWorldCoordinate) ||
      !inRange(water.origin.y, -kMaxWorldCoordinate, kMaxWorldCoordinate))
    return fail("water.origin must lie within +-" + worldExtentText() + " m");
  const int maxCascades = waterCascadeSlots(create);
  if (water.cascadeCount < 1 || water.cascadeCount > maxCascades)
    return fail("water.cascadeCount must be in [1, " + std::to_string(maxCascades) +
                "] (CreateDesc.maxWaterCascades), got " + std::to_string(water.cascadeCount));
  for (int c = 0; c < water.cascadeCount; ++c)
    if (!within(water.tileSize[c], kTileSizeRange))
      return fail("water.tileSize[" + std::to_string(c) + "]" +
                  mustBeIn(water.tileSize[c], kTileSizeRange, " m"));
  for (int c = 0; c < water.cascadeCount; ++c) {
    if (!within(water.rmsLaplacian[c], kWaveStatisticRange))
      return fail("water.rmsLaplacian[" + std::to_string(c) + "]" +
                  mustBeIn(water.rmsLaplacian[c], kWaveStatisticRange, " 1/m"));
    if (!within(water.longestWavelength[c], kWaveStatisticRange))
      return fail("water.longestWavelength[" + std::to_string(c) + "]" +
                  mustBeIn(water.longestWavelength[c], kWaveStatisticRange, " m"));
  }
  if (!within(water.ior, kIorRange)) return fail("water.ior" + mustBeIn(water.ior, kIorRange));
  if (hasFeature(create.features, Feature::Dispersion) && !within(water.iorRgb, kIorRange))
    return fail("water.iorRgb" + mustBeIn(water.iorRgb, kIorRange));
  if (!within(water.absorption, kWaterCoefficientRange))
    return fail("water.absorption" + mustBeIn(water.absorption, kWaterCoefficientRange, " 1/m"));
  // Scattering is read by the god rays and, with ViewExtinction::Plugin, by every pass's
  // view-path extinction: a negative value there would amplify the light exponentially.
  if ((hasFeature(create.features, Feature::GodRays) ||
       frame.viewExtinction == ViewExtinction::Plugin) &&
      !within(water.scattering, kWaterCoefficientRange))
    return fail("water.scattering" + mustBeIn(water.scattering, kWaterCoefficientRange, " 1/m"));
  if (const Result local = validateLocalWaterValues(create, water, error); local != Result::Ok)
    return local;

  if (hasFeature(create.features, Feature::ShadowMask)) {
    const SunShadowMap& shadow = frame.shadow;
    if (!finite(shadow.worldToLightClip)) return fail("shadow.worldToLightClip is not finite");
    if (!isDepthConvention(shadow.depthConvention))
      return fail(notAnEnum("shadow.depthConvention",
                            static_cast<long long>(shadow.depthConvention), "DepthConvention",
                            "ReverseZ, ForwardZeroToOne or ForwardNegOneToOne"));
    if (!within(shadow.bias, kShadowBiasRange))
      return fail("shadow.bias" + mustBeIn(shadow.bias, kShadowBiasRange, " m"));
    if (!within(shadow.normalOffsetTexels, kShadowNormalOffsetRange))
      return fail("shadow.normalOffsetTexels" +
                  mustBeIn(shadow.normalOffsetTexels, kShadowNormalOffsetRange, " texels"));
  }

  if (frame.viewExtinction != ViewExtinction::Plugin &&
      frame.viewExtinction != ViewExtinction::Host)
    return fail(notAnEnum("viewExtinction", static_cast<long long>(frame.viewExtinction),
                          "ViewExtinction", "Plugin or Host"));
  if (frame.viewExtinction == ViewExtinction::Host &&
      hasFeature(create.features, Feature::GodRays) && frame.godRays.enabled)
    return fail(
        "viewExtinction Host with god rays enabled: a fog after dispatch would attenuate the "
        "shafts a second time (use ViewExtinction::Plugin and fog before dispatch)");
  const bool volume = hasFeature(create.features, Feature::VolumeCaustics);
  if (volume && frame.viewExtinction == ViewExtinction::Host &&
      frame.objectCaustics.settings.volume.enabled)
    return fail(
        "viewExtinction Host with objectCaustics.settings.volume enabled: a fog after dispatch "
        "would attenuate the in-scattered light a second time (use ViewExtinction::Plugin)");
  const Result r = validateCausticsSettings(create, frame.caustics, error);
  if (r != Result::Ok) return r;
  if (hasFeature(create.features, Feature::ReflectedCaustics)) {
    const Result reflected = validateReflectedCaustics(frame.reflectedCaustics, error);
    if (reflected != Result::Ok) return reflected;
  }
  // The volume caustics scatter with the god rays' phase, fades and reach.
  if (hasFeature(create.features, Feature::GodRays) || volume)
    return validateGodRays(frame.godRays, error);
  return Result::Ok;
}

Result validateFrameTextures(const CreateDesc& create, const FrameDesc& frame,
                             ValidatedTextures& out, std::string& error) {
  TextureFacts target, depth, normal, albedo;
  Result r = checkTexture("target", frame.target, {GL_TEXTURE_2D},
                          {GL_RGBA16F, GL_RGBA32F, GL_R11F_G11F_B10F}, target, error);
  if (r != Result::Ok) return r;
  r = checkTexture("depth", frame.depth, {GL_TEXTURE_2D}, kDepthFormats, depth, error);
  if (r != Result::Ok) return r;
  r = checkDepthMode("depth", frame.depth.texture, error);
  if (r != Result::Ok) return r;
  r = checkTexture("normal", frame.normal, {GL_TEXTURE_2D}, normalFormats(create.normalEncoding),
                   normal, error);
  if (r != Result::Ok) return r;
  r = checkTexture("albedo", frame.albedo, {GL_TEXTURE_2D},
                   {GL_RGBA8, GL_SRGB8_ALPHA8, GL_RGBA16F, GL_RGB10_A2, GL_RGB8, GL_SRGB8}, albedo,
                   error);
  if (r != Result::Ok) return r;
  const TextureFacts* sized[] = {&depth, &normal, &albedo};
  const char* names[] = {"depth", "normal", "albedo"};
  for (int i = 0; i < 3; ++i) {
    if (sized[i]->width != target.width || sized[i]->height != target.height) {
      error = std::string(names[i]) + " is " + std::to_string(sized[i]->width) + "x" +
              std::to_string(sized[i]->height) + " but target is " + std::to_string(target.width) +
              "x" + std::to_string(target.height);
      return Result::SizeMismatch;
    }
  }

  // Only the seabed caustics and the god rays (and the benchmark floor beside them) sample the
  // water: a host with glass but no water simulation may leave it 0. A texture given is
  // still checked, so a stale name is reported rather than sampled.
  r = validateLocalWaterTextures(frame.water, error);
  if (r != Result::Ok) return r;
  const bool waterNeeded =
      (hasFeature(create.features, Feature::Caustics) && frame.caustics.enabled) ||
      (hasFeature(create.features, Feature::GodRays) && frame.godRays.enabled) ||
      (hasFeature(create.features, Feature::ReflectedCaustics) && frame.reflectedCaustics.enabled);
  if (!waterNeeded && frame.water.texture.texture == 0) {
    out.x = out.y = 0;
    out.width = out.targetWidth = target.width;
    out.height = out.targetHeight = target.height;
    out.water = {};
    out.waterMipmapped = false;
    return checkShadowTexture(create, frame, error);
  }

  if (frame.water.texture.texture == 0) {
    error =
        "water.texture: required while seabed caustics or god rays are enabled (0 is accepted "
        "only when both are off, e.g. object caustics alone)";
    return Result::MissingTexture;
  }
  TextureFacts water;
  const bool single = create.waterTexture == WaterTextureType::Single2D;
  r = checkTexture("water.texture", frame.water.texture,
                   {static_cast<GLenum>(single ? GL_TEXTURE_2D : GL_TEXTURE_2D_ARRAY)},
                   {GL_RGBA16F, GL_RGBA32F, GL_RG16F, GL_RG32F}, water, error);
  if (r != Result::Ok) return r;
  if (!single && water.layers < frame.water.cascadeCount) {
    error = "water.texture has " + std::to_string(water.layers) + " layers but cascadeCount is " +
            std::to_string(frame.water.cascadeCount);
    return Result::SizeMismatch;
  }

  r = checkShadowTexture(create, frame, error);
  if (r != Result::Ok) return r;

  out.x = out.y = 0;
  out.width = out.targetWidth = target.width;
  out.height = out.targetHeight = target.height;
  out.water.width = water.width;
  out.water.height = water.height;
  out.waterMipmapped = isMipComplete(frame.water.texture.texture, water.width, water.height);
  return Result::Ok;
}

}  // namespace postfx::detail
