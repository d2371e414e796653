// The extreme-case table: one line per stiff input. `passes` says which passes the row runs on
// (each pair is its own ctest entry); `sweep` names the parameter stepped by 1e-4 for the
// continuity check (None where the row sits on a discontinuity the model has by design, said in
// a comment). Defaults of every knob: extreme_case.h.
#include "extreme_case.h"

namespace extreme {
namespace {

using K = Knobs;

// Bad texels: every input texture, every kind of broken value.
template <Input I, BadValue V>
void bad(K& k) {
  k.badInput = I;
  k.badValue = V;
}

}  // namespace

const std::vector<Row>& rows() {
  static const std::vector<Row> table = {
      // Sun elevation 0..90 deg, grazing down to 0.01 deg, and below the horizon.
      // Exactly at the zenith ray deviation's reference vector (normal of the plane of incidence)
      // is
      // undefined and takes a fixed fallback, so the zenith frame is a point discontinuity of the
      // model for any azimuth but that fallback's: no sweep there; the approach is swept below.
      {"sun_90deg", kPlugin, [](K& k) { k.sunElevationDeg = 90.0; }},
      {"sun_89_9deg", kPlugin, [](K& k) { k.sunElevationDeg = 89.9; }, Sweep::SunElevation},
      {"sun_60deg", kPlugin, [](K& k) { k.sunElevationDeg = 60.0; }, Sweep::SunElevation},
      {"sun_40deg", kPlugin, [](K&) {}, Sweep::SunElevation},
      {"sun_10deg", kPlugin, [](K& k) { k.sunElevationDeg = 10.0; }, Sweep::SunElevation},
      {"sun_1deg", kPlugin, [](K& k) { k.sunElevationDeg = 1.0; }, Sweep::SunElevation},
      {"sun_0_1deg", kPlugin, [](K& k) { k.sunElevationDeg = 0.1; }, Sweep::SunElevation},
      {"sun_0_01deg", kPlugin, [](K& k) { k.sunElevationDeg = 0.01; }, Sweep::SunElevation},
      // At 0 deg the pass switches off; continuous only if the host's irradiance goes to 0 too.
      {"sun_0deg", kPlugin,
       [](K& k) {
         k.sunElevationDeg = 0.0;
         k.irradianceBySine = true;
       },
       Sweep::SunElevation},
      {"sun_below_horizon", kPlugin, [](K& k) { k.sunElevationDeg = -5.0; }, Sweep::SunElevation},
      // Tightening tau over its whole range.
      {"tau_0", kPlugin, [](K& k) { k.tau = 0.0f; }, Sweep::Tau},
      {"tau_1e6", kPlugin, [](K& k) { k.tau = 1e6f; }, Sweep::Tau},
      // IOR = 1 (no refraction: the grid's up axis is the sun itself), and the top of the range.
      {"ior_1", kPlugin, [](K& k) { k.ior = 1.0f; }, Sweep::Ior},
      // Snell's law is singular at IOR 1 and a grazing sun (dtheta_t/dn infinite): no sweep.
      {"ior_1_grazing", kPlugin,
       [](K& k) {
         k.ior = 1.0f;
         k.sunElevationDeg = 0.01;
       }},
      // ... and a sun 1e-40 rad above the horizon: the unrefracted ray is horizontal to double
      // precision and its slope 1e40 overflows float.
      {"ior_1_sun_1e_40rad", kPlugin,
       [](K& k) {
         k.ior = 1.0f;
         k.sunElevationDeg = 1e-38;
       }},
      {"ior_2_9", kPlugin, [](K& k) { k.ior = 2.9f; }, Sweep::Ior},
      // Absorption 0 and 1e3 /m; no scattering.
      {"absorption_0", kPlugin, [](K& k) { k.absorption = 0.0f; }, Sweep::Absorption},
      {"absorption_1e3", kPlugin, [](K& k) { k.absorption = 1e3f; }, Sweep::Tau},
      {"scattering_0", kGodRays, [](K& k) { k.scattering = 0.0f; }, Sweep::Absorption},
      {"clear_water_0", kGodRays,
       [](K& k) {
         k.absorption = 0.0f;
         k.scattering = 0.0f;
       },
       Sweep::Tau},
      // Water depth 0: the receiver exactly at the level, seen from above.
      {"depth_0", kPlugin,
       [](K& k) {
         k.cameraBelowLevel = -1.0;
         k.floorBelowLevel = 0.0;
       },
       Sweep::WaterLevel},
      // ... without the surface fade the model is a step at the level by design: no sweep.
      {"depth_0_no_fade", kPlugin,
       [](K& k) {
         k.cameraBelowLevel = -1.0;
         k.floorBelowLevel = 0.0;
         k.surfaceFade = 0.0f;
       }},
      // The camera at the water plane +- 1e-6 m, and exactly on it.
      {"camera_1e6m_below_plane", kPlugin, [](K& k) { k.cameraBelowLevel = 1e-6; },
       Sweep::WaterLevel},
      {"camera_1e6m_above_plane", kPlugin, [](K& k) { k.cameraBelowLevel = -1e-6; },
       Sweep::WaterLevel},
      {"camera_on_plane", kPlugin, [](K& k) { k.cameraBelowLevel = 0.0; }, Sweep::WaterLevel},
      // Total internal reflection seen from below: under the water looking up at the surface.
      {"looking_up_at_surface", kPlugin,
       [](K& k) {
         k.cameraBelowLevel = 3.0;
         k.lookDirection = {0.0, 0.9, -1.0};
       },
       Sweep::WaterLevel},
      // The scene 1e6 m from the origin (camera, water and floor moved together).
      {"scene_1e6m_away", kPlugin,
       [](K& k) {
         k.worldOffset = {1e6, 0.0, -1e6};
       },
       Sweep::WaterLevel},
      {"scene_1e6m_away_deep", kPlugin,
       [](K& k) {
         k.worldOffset = {-1e6, -1e6, 1e6};
       },
       Sweep::Tau},
      // The water module's own texture at t = 1e7 s, through the plugin and on its own.
      {"ocean_time_1e7s", kPlugin, [](K& k) { k.oceanTime = 1e7; }, Sweep::Time},
      {"water_time_0", kWater, [](K& k) { k.oceanTime = 0.0; }, Sweep::Time},
      {"water_time_1e7s", kWater, [](K& k) { k.oceanTime = 1e7; }, Sweep::Time},
      {"water_time_1e12s", kWater, [](K& k) { k.oceanTime = 1e12; }, Sweep::Time},
      // NaN / Inf / zero texels in every input texture (a share of the texels, see the runner).
      // Depth textures clamp uploads to [0, 1] (NaN and -Inf arrive as 0, +Inf as 1): the
      // broken depth rows test what a host can actually hand over (sky / near-plane texels).
      {"depth_nan", kPlugin, bad<Input::Depth, BadValue::NaN>},
      {"depth_inf", kPlugin, bad<Input::Depth, BadValue::PosInf>},
      {"depth_neg_inf", kPlugin, bad<Input::Depth, BadValue::NegInf>},
      {"depth_zero", kPlugin, bad<Input::Depth, BadValue::Zero>},
      {"normal_nan", kCaustics, bad<Input::Normal, BadValue::NaN>},
      {"normal_inf", kCaustics, bad<Input::Normal, BadValue::PosInf>},
      {"normal_neg_inf", kCaustics, bad<Input::Normal, BadValue::NegInf>},
      {"normal_zero", kCaustics, bad<Input::Normal, BadValue::Zero>},
      {"albedo_nan", kCaustics, bad<Input::Albedo, BadValue::NaN>},
      {"albedo_inf", kCaustics, bad<Input::Albedo, BadValue::PosInf>},
      {"albedo_neg_inf", kCaustics, bad<Input::Albedo, BadValue::NegInf>},
      {"albedo_zero", kCaustics, bad<Input::Albedo, BadValue::Zero>},
      {"water_nan", kPlugin, bad<Input::WaterTexture, BadValue::NaN>},
      {"water_inf", kPlugin, bad<Input::WaterTexture, BadValue::PosInf>},
      {"water_neg_inf", kPlugin, bad<Input::WaterTexture, BadValue::NegInf>},
      {"water_zero", kPlugin, bad<Input::WaterTexture, BadValue::Zero>},
      {"shadow_nan", passBit(Pass::CausticsShadow) | kGodRays,
       bad<Input::ShadowMap, BadValue::NaN>},
      {"shadow_inf", passBit(Pass::CausticsShadow) | kGodRays,
       bad<Input::ShadowMap, BadValue::PosInf>},
      {"shadow_neg_inf", passBit(Pass::CausticsShadow) | kGodRays,
       bad<Input::ShadowMap, BadValue::NegInf>},
      {"shadow_zero", passBit(Pass::CausticsShadow) | kGodRays,
       bad<Input::ShadowMap, BadValue::Zero>},
  };
  return table;
}

}  // namespace extreme
