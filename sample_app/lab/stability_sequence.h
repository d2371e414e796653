#pragma once
// The sequences the temporal-stability measurement (temporal_stability.h) is taken on: the
// sample's frame rendered along a slow motion and, for every frame, the light one pass adds,
// isolated in a cleared target of the measurement's own. That is what (frame with the pass) -
// (frame without it) gives at the point of the frame where the plugin adds its light, without
// the host's later water surface, which only carries it on. The plugin pass runs in a context
// of its own, kept for the whole sequence (the object caustics' temporal filter keeps its
// history in it); the references (traced caustics, dense god-ray march) add their light the
// same way.
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <scene/model.h>
#include <glm/glm.hpp>

#include "plugin_setup.h"
#include "renderer.h"

namespace ocean {

enum class StabilityPass {
  TileCaustics,          // CausticsModel::TileIrradiance (the default)
  RayDeviationCaustics,  // CausticsModel::RayDeviation
  WavefrontAreaRatio,    // CausticsModel::WavefrontAreaRatio (Feature::WavefrontAreaRatio)
  GodRays,
  ObjectCaustics,          // temporal filter off (the default)
  FilteredObjectCaustics,  // ObjectCausticsSettings::temporalFilter on, default weight
};
const char* stabilityPassName(StabilityPass pass);  // "caustics, tile irradiance", ...

enum class StabilityReference {
  TracedCaustics,  // photon tracing of the frame's own water against the scene (all 3 models)
  DenseGodRays,    // the god rays' dense double-precision march
};
// The reference of the light `pass` approximates in a whole frame, if there is one (the object
// caustics' exact tracing exists for a glass sphere over a plane only, not a frame).
std::optional<StabilityReference> stabilityReference(StabilityPass pass);
const char* stabilityReferenceName(StabilityReference reference);

// A slow motion: frame k is rendered at k / fps seconds.
struct StabilityMotion {
  glm::dvec3 velocity{0.0};  // of the camera, m/s
  double yawRate = 0.0;      // of the camera, degrees per second
  bool timeRuns = false;     // false: every frame at the start time
  double fps = 30.0;
};
// Time frozen, the camera swimming at 0.5 m/s and turning at 5 degrees per second: a slow
// look around, 1.7 cm and 0.17 degrees per frame at 30 fps.
StabilityMotion cameraMotion(double fps = 30.0);
// The camera still, time running.
StabilityMotion timeMotion(double fps = 30.0);
// Nothing moves.
StabilityMotion stillMotion();
// "camera 0.5 m/s and 5 deg/s, time frozen, 30 fps", "camera still, time running, 30 fps".
std::string describeMotion(const StabilityMotion& motion);

// The sample's frame the passes are measured on. The plugin's own passes are switched off in
// it (their light is not what is measured: each pass is dispatched again on its own).
struct StabilityHost {
  Renderer& renderer;
  PluginSetup& plugin;  // created with Options::objectCaustics (the casters and receiver map)
  const ocean_scene::Model& scene;  // the traced reference intersects it
  FrameInput start;
};

using AddedLightFrames = std::vector<std::vector<glm::vec4>>;  // RGBA, GL order, per frame

// Changes the frame the measured pass is given (frame index, its description): a test's way to
// stand for a host whose inputs jitter from frame to frame.
using FrameAdjustment = std::function<void(int frame, postfx::FrameDesc& desc)>;

// `frames` frames along `motion`: the light `pass` adds to each.
bool renderPassSequence(StabilityHost& host, StabilityPass pass, const StabilityMotion& motion,
                        int frames, AddedLightFrames& out, std::string& error,
                        const FrameAdjustment& adjust = {});

struct ReferenceSequenceSettings {
  // The traced reference draws the same photons every frame (the same seed and a fixed number
  // of batches), so a still frame traces bit-identically and frames close in time or position
  // share most of their noise: what changes is mostly the light, not the estimate of it.
  int traceBatches = 8;
  unsigned long long seed = 1;
  int godRaySamples = 1024;  // segments per pixel of the dense march (its minimum)
  int threads = 2;
};

bool renderReferenceSequence(StabilityHost& host, StabilityReference reference,
                             const StabilityMotion& motion, int frames,
                             const ReferenceSequenceSettings& settings, AddedLightFrames& out,
                             std::string& error);

// The first frame traced twice with seeds `settings.seed` and `settings.seed + 1`: the change
// that the trace's noise alone would make if every frame drew new photons (an upper bound of
// what noise adds to the traced reference's change).
bool tracedNoisePair(StabilityHost& host, const ReferenceSequenceSettings& settings,
                     AddedLightFrames& out, std::string& error);

}  // namespace ocean
