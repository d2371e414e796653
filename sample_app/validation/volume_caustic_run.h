#pragma once
// The volume caustics' host, shared by their tests and the report: a glass sphere under water,
// lit by the refracted sun, focusing onto a floor (the receivers), seen from the side by a camera
// looking at a wall behind it (a plane G-buffer), so that the cone of light between the sphere
// and the floor lies in the open water in front of the wall. The plugin's image and the CPU
// reference (ocean::reference::renderVolumeCausticReference) of the same frame.
#include <limits>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include <object_caustics_reference.h>
#include <postfx/postfx.h>

namespace ocean::validation {

struct VolumeCausticScene {
  reference::SphereCaster sphere;  // ior relative to the water
  double planeY = -2.5;            // the floor (world y, m)
  double waterLevel = 3.0;
  double waterIor = 1.333;
  glm::dvec3 towardSun{0.0, 1.0, 0.0};  // unit, above the water
  double wallDistance = 8.0;            // the camera (at the origin) looks down -z at a wall
  glm::dvec3 scattering{0.05}, absorption{0.05};        // WaterSurface's, 1/m
  double phase = 1.0 / (4.0 * 3.14159265358979323846);  // GodRaySettings::intensity
  double surfaceFade = 2.0, depthFade = 40.0;           // GodRaySettings' fades (m)
  // A point light straight above the sphere's centre, this far from it (m), instead of the sun
  // (ObjectCausticsFrame::sunCaustics off); 0: the sun. pointLightCount > 1: that many, each
  // tilted 10 degrees from the vertical, a quarter turn apart.
  double pointLightDistance = 0.0;
  int pointLightCount = 1;
  glm::vec3 pointLightIntensity{1.0f};
  int width = 640, height = 360;
};

// A clear glass ball (R = 0.5 m, IOR 1.5 in water of 1.333) 5 m in front of the camera, its
// centre 0.5 m above the eye, the floor 3 m below its centre (past the paraxial focus, 2.25 m),
// the sun 25 degrees from the zenith so that the cone leans across the image.
VolumeCausticScene glassSphereInWater(int width, int height);

struct VolumeCausticOptions {
  bool volume = true;  // Feature::VolumeCaustics (and the settings' volume.enabled)
  // The sun's god rays too: flat water, full resolution, 64 samples 20 cm apart; the sphere in
  // the host's sun shadow map (ShadowMask) unless shadowless.
  bool godRays = false;
  bool shadowless = false;
  bool hostExtinction = false;  // FrameDesc::viewExtinction = Host (refused with the volume on)
  // With godRays: the god-ray reference of the same frame too (a dense double-precision march of
  // the shafts, ocean::reference::renderGodRayReference, 1024 segments per pixel) into
  // VolumeCausticRun::godRayReference.
  bool godRayReference = false;
  int memoryBudgetMiB = 1024;  // CreateDesc::memoryBudgetMiB
  postfx::GodRayResolution godRayResolution = postfx::GodRayResolution::Full;
  int godRaySamples = 64;
  int timedFrames = 0;  // 0: one dispatch, untimed
};

struct VolumeCausticRun {
  std::vector<glm::dvec3> light;            // what the frame added, per pixel, GL order
  std::vector<glm::dvec3> godRayReference;  // VolumeCausticOptions::godRayReference
  // Pass::ObjectCaustics (with point lights: the sum of their own timings) and the floor
  double medianMs = 0.0, floorMs = 0.0;
  double estimatedMs =
      std::numeric_limits<double>::quiet_NaN();  // PassRun::estimatedMs of Pass::ObjectCaustics
                                                 // (lights included)
};

bool runVolumeCaustic(const VolumeCausticScene& scene,
                      const postfx::ObjectCausticsSettings& settings,
                      const VolumeCausticOptions& options, VolumeCausticRun& out,
                      std::string& error);

// The reference of the in-scattered light alone (raysPerSide^2 rays over the sphere).
std::vector<glm::dvec3> volumeCausticReference(const VolumeCausticScene& scene, int raysPerSide,
                                               unsigned seed = 0, bool progress = true);

// The plugin's volume light against the reference's inside the cone: the pixels where the
// reference's green channel is at least `threshold` of its 99th percentile (every pixel for a
// threshold of 0).
struct ConeError {
  double relativeRmse = 0.0;  // sqrt(sum (a - r)^2 / sum r^2) over those pixels, green
  double fluxRatio = 0.0;     // sum a / sum r over those pixels
  double correlation = 0.0;
  int pixels = 0;
};
ConeError coneError(const std::vector<glm::dvec3>& image, const std::vector<glm::dvec3>& reference,
                    double threshold = 0.05);

}  // namespace ocean::validation
