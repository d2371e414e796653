#pragma once
// The light the plugin's seabed-caustics pass adds to a pixel, in its own units, with its
// caustic factor replaced by traced irradiance. The plugin
// (shaders/postfx/seabed_caustics/caustics.frag) adds
//     albedo * E_sun * intensity * exp(-absorption d / u.y) * fade(d) * [omega * (n.u) * vis]
//     * exp(-sigma_t * submerged view length)   (FrameDesc::viewExtinction Plugin only)
// for a receiver d metres under the level, u the unperturbed refracted sun reversed, n the
// G-buffer normal, vis its shadow-map visibility and omega its caustic factor (1 for flat
// water). The bracket is the caustic irradiance relative to flat water's on a horizontal
// receiver at normal incidence of the refracted beam. The reference puts in its place
// the traced ratio R = E / E_flat times the same (n.u):
//     [R (n.u)] = E u.y,   E_flat = (n.u) / u.y,
// E the traced irradiance (flat water on a horizontal receiver = 1; occlusion traced, so no
// shadow-map visibility), keeping every other factor (albedo, sun, intensity, the plugin's
// absorption along the unperturbed path, surface fade) exactly as the plugin computes it: with
// flat water and no occluder the two agree exactly, and (reference - frame without caustics)
// compares pixel by pixel with (plugin frame - frame without caustics).
#include <postfx/postfx.h>
#include <glm/glm.hpp>

namespace ocean::reference {

//
// The object caustics' composite (shaders/postfx/object_caustics/object_caustics_composite.frag)
// adds, for the sun, albedo * E_sun * objectIntensity * exp(-absorption d / u.y) * [caustic *
// (n.u)] * (the same view extinction), no surface fade, caustic the map's irradiance relative to
// the sun's across the refracted beam: [caustic (n.u)] is again E u.y for traced irradiance E.
//
// The reflected caustics above the water (postfx/reflected_caustics.h) add
//     albedo * E_sun * intensity * R(sun.y) * [I * max(n . l_r, 0) * visibility] * (view
//     extinction)
// l_r = (sun.x, -sun.y, sun.z), R flat water's unpolarised Fresnel reflectance at the sun's
// incidence, I the reflected light relative to flat water's mirror light (1 over a flat sea).
// The trace's reflected irradiance E_r (flat water's reflected flux on a horizontal receiver
// facing down = 1, so a flat sea gives max(n . l_r, 0) / |l_r.y|) takes the bracket's place as
// [I max(n . l_r, 0) vis] = E_r |l_r.y|, occlusion traced. Without includeMirrorMean the plugin
// adds only the waves' modulation, (I - 1) in place of I: E_r - (flat water's mirror light
// there) in place of E_r.
struct CausticLightUnits {
  glm::vec3 lightScale{1.0f};          // E_sun * intensity
  glm::vec3 objectLightScale{1.0f};    // E_sun * ObjectCausticsSettings::intensity
  float objectIntensity = 1.0f;        // ObjectCausticsSettings::intensity
  glm::vec3 absorptionPerDepth{0.0f};  // absorption / u.y (1/m)
  float fadeDepth = 0.0f;              // CausticsSettings::surfaceFadeDepth
  double upY = 1.0;                    // u.y
  glm::vec3 viewExtinction{0.0f};      // sigma_t with ViewExtinction::Plugin, else 0 (1/m)
  float levelRelative = 0.0f;          // water level - camera height (m)
  // E_sun * ReflectedCausticsSettings::intensity * R(sun.y); 0 without a sun above the horizon
  glm::vec3 reflectedLightScale{0.0f};
  double mirrorY = 1.0;           // |l_r.y| = sun.y
  bool includeMirrorMean = true;  // ReflectedCausticsSettings::includeMirrorMean
};

CausticLightUnits causticLightUnits(const postfx::FrameDesc& frame);

// What the plugin would add with its caustic factor replaced by `tracedIrradiance` E.
// `viewDistance`: metres from the camera to the receiver.
glm::vec3 referenceCausticLight(const CausticLightUnits& units, const glm::vec3& albedo,
                                double depthBelow, double tracedIrradiance, double viewDistance);

// What the plugin's object caustics would add with their map replaced by traced irradiance
// `tracedIrradiance` (per channel) of light that went through or off a caster.
glm::vec3 referenceObjectCausticLight(const CausticLightUnits& units, const glm::vec3& albedo,
                                      double depthBelow, const glm::dvec3& tracedIrradiance,
                                      double viewDistance);

// What the plugin's reflected caustics would add to a receiver `depthBelow` (< 0: above) the
// level with their light field replaced by the traced reflected irradiance `tracedReflected`.
// `flatMirrorLight`: flat water's traced-unit mirror light there (FrameTraceResult::flatReflected
// where the flat mirror reaches the point, else 0), taken off without includeMirrorMean.
glm::vec3 referenceReflectedLight(const CausticLightUnits& units, const glm::vec3& albedo,
                                  double depthBelow, double tracedReflected, double flatMirrorLight,
                                  double viewDistance);

// The same for a local light's object caustics: the composite adds albedo * intensity *
// objectIntensity * [caustic (n.l)] * (view extinction), the water's absorption along the path
// inside the caustic; `tracedIrradiance` (intensity / m^2, absorbed) takes the place of all but
// albedo, objectIntensity and the view extinction.
glm::vec3 referenceLocalCausticLight(const CausticLightUnits& units, const glm::vec3& albedo,
                                     double depthBelow, const glm::dvec3& tracedIrradiance,
                                     double viewDistance);

}  // namespace ocean::reference
