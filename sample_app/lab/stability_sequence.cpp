#include "stability_sequence.h"

#include <cstdio>

#include <godray_reference.h>

#include "traced_caustics_pass.h"

namespace ocean {
namespace {

FrameInput frameAt(const FrameInput& start, const StabilityMotion& motion, int frame) {
  const double t = frame / motion.fps;
  FrameInput input = start;
  input.camera.position += motion.velocity * t;
  input.camera.yaw += glm::radians(motion.yawRate * t);
  if (motion.timeRuns) input.timeSeconds += t;
  return input;
}

// Renders the host frame with the sample's own plugin passes off: what follows reads the
// frame the plugin was handed (PluginSetup::lastFrame) and adds light elsewhere.
bool renderHost(StabilityHost& host, const FrameInput& input, std::string& error) {
  host.plugin.caustics().enabled = false;
  host.plugin.godRays().enabled = false;
  host.plugin.objectCaustics().enabled = false;
  return host.renderer.render(input, error);
}

bool isCaustics(StabilityPass pass) {
  return pass == StabilityPass::TileCaustics || pass == StabilityPass::RayDeviationCaustics ||
         pass == StabilityPass::WavefrontAreaRatio;
}
bool isObjectCaustics(StabilityPass pass) {
  return pass == StabilityPass::ObjectCaustics || pass == StabilityPass::FilteredObjectCaustics;
}

// The host's create-time choices that shape the pass's light (shadow mask, dispersion, the
// lookup on walls), and the pass's own features only: nothing else runs.
postfx::CreateDesc passCreateDesc(const postfx::CreateDesc& host, StabilityPass pass) {
  postfx::CreateDesc create = host;
  postfx::Feature features = static_cast<postfx::Feature>(0);
  for (postfx::Feature kept :
       {postfx::Feature::ShadowMask, postfx::Feature::Dispersion, postfx::Feature::TriplanarWalls})
    if (postfx::hasFeature(host.features, kept)) features = features | kept;
  if (isCaustics(pass)) features = features | postfx::Feature::Caustics;
  if (pass == StabilityPass::WavefrontAreaRatio)
    features = features | postfx::Feature::WavefrontAreaRatio;
  if (pass == StabilityPass::GodRays) features = features | postfx::Feature::GodRays;
  if (isObjectCaustics(pass)) features = features | postfx::Feature::ObjectCaustics;
  create.features = features;
  return create;
}

// The host's last frame with only `pass` on, its settings the sample's own.
postfx::FrameDesc passFrameDesc(const postfx::FrameDesc& host, StabilityPass pass, GLuint target) {
  postfx::FrameDesc frame = host;
  frame.target = {target, GL_RGBA32F};
  frame.caustics.enabled = isCaustics(pass);
  // Settings are validated whether or not their pass runs: a host on the physical model would
  // otherwise ask the other passes' contexts (created without Feature::WavefrontAreaRatio) for it.
  if (pass == StabilityPass::TileCaustics || !isCaustics(pass))
    frame.caustics.model = postfx::CausticsModel::TileIrradiance;
  if (pass == StabilityPass::RayDeviationCaustics)
    frame.caustics.model = postfx::CausticsModel::RayDeviation;
  if (pass == StabilityPass::WavefrontAreaRatio)
    frame.caustics.model = postfx::CausticsModel::WavefrontAreaRatio;
  frame.godRays.enabled = pass == StabilityPass::GodRays;
  // The god rays' dense reference (reference::renderGodRayReference) marches ray deviation's
  // factor: the RayDeviation model's god rays (the other models' read their irradiance field).
  if (pass == StabilityPass::GodRays) frame.caustics.model = postfx::CausticsModel::RayDeviation;
  frame.objectCaustics.settings.enabled = isObjectCaustics(pass);
  frame.objectCaustics.settings.temporalFilter = pass == StabilityPass::FilteredObjectCaustics;
  if (!isObjectCaustics(pass)) frame.objectCaustics.casterCount = 0;
  return frame;
}

// An RGBA32F texture of the frame's size that each frame's light is added into from zero.
class AddedLightTarget {
 public:
  AddedLightTarget(int width, int height) : width_(width), height_(height) {
    glCreateTextures(GL_TEXTURE_2D, 1, &texture_);
    glTextureStorage2D(texture_, 1, GL_RGBA32F, width, height);
  }
  ~AddedLightTarget() { glDeleteTextures(1, &texture_); }
  AddedLightTarget(const AddedLightTarget&) = delete;
  AddedLightTarget& operator=(const AddedLightTarget&) = delete;
  GLuint texture() const { return texture_; }
  void clear() const {
    const float zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    glClearTexImage(texture_, 0, GL_RGBA, GL_FLOAT, zero);
  }
  std::vector<glm::vec4> read() const {
    std::vector<glm::vec4> image(size_t(width_) * size_t(height_));
    glGetTextureImage(texture_, 0, GL_RGBA, GL_FLOAT, GLsizei(image.size() * sizeof(glm::vec4)),
                      image.data());
    return image;
  }

 private:
  GLuint texture_ = 0;
  int width_, height_;
};

reference::FrameTraceDesc traceDesc(const ReferenceSequenceSettings& settings,
                                    unsigned long long seed) {
  reference::FrameTraceDesc trace;
  trace.seed = seed;
  trace.minBatches = settings.traceBatches;
  trace.maxBatches = settings.traceBatches;
  trace.targetNoise = 0.0;  // never "converged" early: every frame traces the same batches
  trace.threads = settings.threads;
  return trace;
}

bool traceInto(StabilityHost& host, const FrameInput& input, const AddedLightTarget& target,
               const reference::FrameTraceDesc& trace, std::string& error) {
  // The Embree scene is built around the camera, so it follows a moving one.
  auto traced =
      TracedCausticsPass::create(host.plugin, host.scene, input.camera.position, trace, error);
  if (!traced) return false;
  target.clear();
  return traced->addTo(target.texture(), error);
}

}  // namespace

const char* stabilityPassName(StabilityPass pass) {
  switch (pass) {
    case StabilityPass::TileCaustics:
      return "caustics, tile irradiance";
    case StabilityPass::RayDeviationCaustics:
      return "caustics, ray deviation";
    case StabilityPass::WavefrontAreaRatio:
      return "caustics, wavefront area ratio";
    case StabilityPass::GodRays:
      return "god rays";
    case StabilityPass::ObjectCaustics:
      return "object caustics";
    case StabilityPass::FilteredObjectCaustics:
      return "object caustics, temporal filter";
  }
  return "?";
}

std::optional<StabilityReference> stabilityReference(StabilityPass pass) {
  if (isCaustics(pass)) return StabilityReference::TracedCaustics;
  if (pass == StabilityPass::GodRays) return StabilityReference::DenseGodRays;
  return std::nullopt;
}

const char* stabilityReferenceName(StabilityReference reference) {
  return reference == StabilityReference::TracedCaustics ? "traced caustics"
                                                         : "dense god-ray march";
}

StabilityMotion cameraMotion(double fps) {
  StabilityMotion motion;
  motion.velocity = {0.3, 0.0, -0.4};
  motion.yawRate = 5.0;
  motion.fps = fps;
  return motion;
}

StabilityMotion timeMotion(double fps) {
  StabilityMotion motion;
  motion.timeRuns = true;
  motion.fps = fps;
  return motion;
}

StabilityMotion stillMotion() {
  return {};
}

std::string describeMotion(const StabilityMotion& motion) {
  char text[160];
  if (glm::length(motion.velocity) == 0.0 && motion.yawRate == 0.0) {
    std::snprintf(text, sizeof text, "camera still, time %s, %g fps",
                  motion.timeRuns ? "running" : "frozen", motion.fps);
  } else {
    std::snprintf(text, sizeof text, "camera %.2g m/s and %.2g deg/s, time %s, %g fps",
                  glm::length(motion.velocity), motion.yawRate,
                  motion.timeRuns ? "running" : "frozen", motion.fps);
  }
  return text;
}

bool renderPassSequence(StabilityHost& host, StabilityPass pass, const StabilityMotion& motion,
                        int frames, AddedLightFrames& out, std::string& error,
                        const FrameAdjustment& adjust) {
  out.clear();
  const postfx::CreateDesc create = passCreateDesc(host.plugin.createDesc(), pass);
  postfx::Context* context = nullptr;
  if (postfx::create(create, context) != postfx::Result::Ok) {
    error = std::string("postfx: ") + postfx::lastError(nullptr);
    return false;
  }
  const RenderSettings& size = host.renderer.settings();
  const AddedLightTarget target(size.width, size.height);
  bool ok = true;
  for (int k = 0; k < frames && ok; ++k) {
    ok = renderHost(host, frameAt(host.start, motion, k), error);
    if (!ok) break;
    target.clear();
    postfx::FrameDesc frame = passFrameDesc(host.plugin.lastFrame(), pass, target.texture());
    if (adjust) adjust(k, frame);
    ok = postfx::dispatch(*context, frame) == postfx::Result::Ok;
    if (!ok) error = std::string("postfx: ") + postfx::lastError(context);
    if (ok) out.push_back(target.read());
  }
  postfx::destroy(context);
  return ok;
}

bool renderReferenceSequence(StabilityHost& host, StabilityReference reference,
                             const StabilityMotion& motion, int frames,
                             const ReferenceSequenceSettings& settings, AddedLightFrames& out,
                             std::string& error) {
  out.clear();
  const RenderSettings& size = host.renderer.settings();
  const AddedLightTarget target(size.width, size.height);
  for (int k = 0; k < frames; ++k) {
    const FrameInput input = frameAt(host.start, motion, k);
    if (!renderHost(host, input, error)) return false;
    if (reference == StabilityReference::TracedCaustics) {
      if (!traceInto(host, input, target, traceDesc(settings, settings.seed), error)) return false;
      out.push_back(target.read());
      continue;
    }
    const postfx::CreateDesc create =
        passCreateDesc(host.plugin.createDesc(), StabilityPass::GodRays);
    const postfx::FrameDesc frame =
        passFrameDesc(host.plugin.lastFrame(), StabilityPass::GodRays, target.texture());
    reference::GodRayInputs inputs;
    if (!reference::captureGodRayInputs(create, frame, inputs, error)) return false;
    reference::GodRayReferenceOptions options;
    options.samples = settings.godRaySamples;
    options.threads = settings.threads;
    options.progress = false;
    const std::vector<glm::dvec3> light =
        reference::renderGodRayReference(create, frame, inputs, options);
    std::vector<glm::vec4> image(light.size());
    for (size_t i = 0; i < light.size(); ++i) image[i] = glm::vec4(glm::vec3(light[i]), 0.0f);
    out.push_back(std::move(image));
  }
  return true;
}

bool tracedNoisePair(StabilityHost& host, const ReferenceSequenceSettings& settings,
                     AddedLightFrames& out, std::string& error) {
  out.clear();
  const RenderSettings& size = host.renderer.settings();
  const AddedLightTarget target(size.width, size.height);
  if (!renderHost(host, host.start, error)) return false;
  for (unsigned long long seed : {settings.seed, settings.seed + 1}) {
    if (!traceInto(host, host.start, target, traceDesc(settings, seed), error)) return false;
    out.push_back(target.read());
  }
  return true;
}

}  // namespace ocean
