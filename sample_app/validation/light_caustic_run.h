#pragma once
// One point or spot light's object caustics through the plugin, on the host the accuracy tests
// and the report share: a glass sphere (its mesh in host buffers) over a floor, the floor as a
// flat G-buffer seen from straight above a square of bins (one pixel per bin), the light's
// receiver map of the floor, the sun left out (ObjectCausticsFrame::sunCaustics = false). The
// light added to the target, over the floor's white albedo, is the caustic's irradiance on the
// floor: it meets ocean::reference::traceSphereFromLight in the same bins.
#include <limits>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include <object_caustics_local_light.h>
#include <postfx/postfx.h>

namespace ocean::validation {

struct LightCausticScene {
  reference::SphereCaster sphere;
  reference::LocalLightSource light;  // its intensity is the plugin's (1: per unit intensity)
  double range = 1e6;                 // postfx::LocalLight::range
  double planeY = 0.0;                // the floor
  // Under water: the water's level far above everything, its absorption along both legs.
  bool underWater = false;
  glm::dvec3 waterAbsorption{0.35, 0.06, 0.02};
  double waterIor = 1.333;  // the sphere's ior is then relative to water (sphere.ior = n / this)
  // The bins (and pixels): a square of `binSide` m around `binCentre` on the floor.
  glm::dvec3 binCentre{0.0};
  double binSide = 1.0;
  int binCount = 256;
};

// A ball lens: R = 0.25 m, IOR 1.5, tinted glass (absorption 0.2, 1, 3 per m),
// lit by a point light 2 m from its centre, 30 degrees off the vertical; the floor cuts the
// axis just short of the paraxial image (f = n R / (2 (n - 1)) from the centre, 1/s + 1/s' =
// 1/f: s' = 0.4615 m in air), inside the axial caustic, where the light peaks on the axis at the
// origin. Under water: relative IOR 1.5 / 1.333 (s' = 6.5 m: the floor, at 0.98 of it, catches
// a wide spot), the water absorbing along both legs. `binCount` pixels over the spot.
LightCausticScene pointLightBallLens(bool underWater, int binCount = 300);
// A spot 2 m above the same ball (clear glass, centre 0.6 m above the floor), its 20 degree cone
// tilted 10 degrees off the centre: the edge runs through the middle of the ball's 7.2 degree
// disc and cuts half the caustic away; `softness` fades it.
LightCausticScene spotConeCut(double softness, int binCount = 256);

// The floor's bins of `scene`, pixel (i, j) of the target = bin (i, j).
reference::ReceiverBins sceneBins(const LightCausticScene& scene);

struct LightCausticRun {
  std::vector<glm::dvec3> irradiance;    // per bin: the light added over the floor
  double medianMs = 0.0, floorMs = 0.0;  // the light's own timing, the floor pass's
  double estimatedMs =
      std::numeric_limits<double>::quiet_NaN();  // PassRun::estimatedMs of Pass::ObjectCaustics
                                                 // (the light's work)
  postfx::LightSkip skip = postfx::LightSkip::None;
};

// Dispatches `scene` with `settings` (timedFrames + warm-up, then once into a cleared target;
// timedFrames 0: once, untimed). False with a message when the plugin refuses the frame.
bool runLightCaustic(const LightCausticScene& scene, const postfx::ObjectCausticsSettings& settings,
                     int timedFrames, LightCausticRun& out, std::string& error);

// The sun's object caustics of the same sphere on the same host and settings, the sun shining
// from the sphere toward the light (its receivers: the floor seen along it), for the cost of a
// light against the sun's: the median time of Pass::ObjectCaustics and of the floor.
bool timeSunCaustic(const LightCausticScene& scene, const postfx::ObjectCausticsSettings& settings,
                    int timedFrames, double& ms, double& floorMs, std::string& error);

}  // namespace ocean::validation
