#pragma once
// The extreme-case suite's vocabulary: the passes it exercises, the knobs a row turns, and the
// table of rows. A row is one stiff input, applied to every pass in its set; each (row, pass)
// pair is one gtest case and one ctest entry. A later pass (physical caustics, object caustics)
// adds a Pass value and its runner; a new stiff input is one line in extreme_table.cpp.
#include <glm/glm.hpp>
#include <ostream>
#include <string>
#include <vector>

namespace extreme {

enum class Pass {
  Caustics,            // seabed caustics, ray-deviation coefficient
  CausticsDispersion,  // ... with Feature::Dispersion (per-channel IOR) and TriplanarWalls
  CausticsShadow,      // ... with Feature::ShadowMask (synthetic sun shadow map)
  GodRaysFull,         // god rays, full resolution
  GodRaysHalf,         // god rays, half resolution + depth-aware upsample
  Water,               // the water module's FFT textures on their own
  Count
};
using PassSet = unsigned;
constexpr PassSet passBit(Pass p) {
  return 1u << static_cast<unsigned>(p);
}
inline constexpr PassSet kCaustics =
    passBit(Pass::Caustics) | passBit(Pass::CausticsDispersion) | passBit(Pass::CausticsShadow);
inline constexpr PassSet kGodRays = passBit(Pass::GodRaysFull) | passBit(Pass::GodRaysHalf);
inline constexpr PassSet kPlugin = kCaustics | kGodRays;
inline constexpr PassSet kWater = passBit(Pass::Water);
const char* passName(Pass pass);
bool isCausticPass(Pass pass);
bool isGodRayPass(Pass pass);

// The parameter a row steps by h = 1e-4 (in the unit given) for the continuity check.
enum class Sweep {
  None,
  SunElevation,  // radians, azimuth fixed
  Tau,           // relative: tau * (1 + h), or tau + h at tau < 1
  Absorption,    // 1/m, all channels: sigma_a + h * max(sigma_a, 1)
  WaterLevel,    // metres (the camera moves relative to the water by h)
  Ior,           // absolute, iorRgb scaled with it
  Time,          // seconds of water-module time
};
const char* sweepName(Sweep sweep);
inline constexpr double kStep = 1e-4;

// Which host input gets broken texels, and with what.
enum class Input { None, Depth, Normal, Albedo, WaterTexture, ShadowMap };
enum class BadValue { NaN, PosInf, NegInf, Zero };

// Everything a row can turn. Defaults: camera 1 m under the water looking down at a floor 3 m
// deep with a sphere straddling the depth range, sun 40 deg high, clear water.
struct Knobs {
  double sunElevationDeg = 40.0;
  double sunAzimuthDeg = 37.0;    // from +x toward +z
  bool irradianceBySine = false;  // host gives E = E0 * max(sin(elevation), 0) (surface irradiance)
  float tau = 800.0f;
  float reflectionWeight = 0.25f;
  float surfaceFade = 1.0f;       // caustics surfaceFadeDepth and god-ray surfaceFadeDistance (m)
  float ior = 1.333f;             // iorRgb = ior * (1, 1.0015, 1.0038) with Dispersion
  float absorption = 0.1f;        // grey sigma_a (1/m)
  float scattering = 0.05f;       // grey sigma_s (1/m)
  double cameraBelowLevel = 1.0;  // m; negative: camera above the water
  double floorBelowLevel = 3.0;   // m; 0: the receiver lies exactly at the water level
  glm::dvec3 lookDirection{0.0, -0.35, -1.0};
  bool sphere = true;             // a sphere 2.5 m across below the camera: walls, any slope
  glm::dvec3 worldOffset{0.0};    // the whole scene (camera, water, floor) moved (m)
  double waterAmplitude = 0.005;  // synthetic water texture (see extreme_runner.cpp)
  double oceanTime = -1.0;        // >= 0: the water module's texture at this time instead
  float gridSpacing = 0.75f;      // god rays
  int sampleCount = 16;           // god rays
  // God rays sampled evenly along each ray instead of on the world grid: set by the continuity
  // check of parameters that move the grid or the march's ends (see extreme_bounds.cpp).
  bool uniformSampling = false;
  Input badInput = Input::None;
  BadValue badValue = BadValue::NaN;
};

struct Row {
  const char* name;  // letters, digits and '_' (it becomes the gtest name)
  PassSet passes;
  void (*edit)(Knobs&);
  Sweep sweep = Sweep::None;
};

// The table (extreme_table.cpp).
const std::vector<Row>& rows();

struct Case {
  const Row* row = nullptr;
  Pass pass = Pass::Caustics;
  std::string name;  // row name + "_" + pass name
  Knobs knobs() const;
};
std::vector<Case> cases();
// gtest prints a failing case by its name.
void PrintTo(const Case& c, std::ostream* os);

// The knobs after one continuity step of `sweep`.
Knobs stepped(const Knobs& knobs, Sweep sweep);

}  // namespace extreme
