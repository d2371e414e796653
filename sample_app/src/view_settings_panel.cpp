#include "view_settings_panel.h"

#include <imgui.h>

#include <glm/gtc/type_ptr.hpp>

namespace ocean {
namespace {

// Slider ends are a convenient span, not the accepted range: Ctrl+click types any value, and
// the plugin's validation (with its k...Range constants) answers it.
constexpr ImGuiSliderFlags kLog = ImGuiSliderFlags_Logarithmic;

bool sliderDouble(const char* label, double& value, double lo, double hi, const char* format,
                  ImGuiSliderFlags flags = 0) {
  return ImGui::SliderScalar(label, ImGuiDataType_Double, &value, &lo, &hi, format, flags);
}

// An RGB coefficient per metre as three draggable numbers.
bool dragRgb(const char* label, postfx::water::Rgb& rgb) {
  double values[3] = {rgb.r, rgb.g, rgb.b};
  const double lo = 0.0, hi = 10.0;
  if (!ImGui::DragScalarN(label, ImGuiDataType_Double, values, 3, 0.001f, &lo, &hi, "%.3f"))
    return false;
  rgb = {values[0], values[1], values[2]};
  return true;
}

// A radian angle shown in degrees.
bool sliderDegrees(const char* label, double& radians, double loDegrees, double hiDegrees) {
  double degrees = glm::degrees(radians);
  if (!sliderDouble(label, degrees, loDegrees, hiDegrees, "%.1f deg")) return false;
  radians = glm::radians(degrees);
  return true;
}

bool causticsModel(postfx::CausticsModel& model) {
  static const postfx::CausticsModel kModels[] = {postfx::CausticsModel::TileIrradiance,
                                                  postfx::CausticsModel::RayDeviation,
                                                  postfx::CausticsModel::WavefrontAreaRatio};
  static const char* const kNames[] = {"tile irradiance", "ray deviation", "wavefront area ratio"};
  int current = 0;
  for (int i = 0; i < 3; ++i)
    if (kModels[i] == model) current = i;
  if (!ImGui::Combo("model", &current, kNames, 3)) return false;
  model = kModels[current];
  return true;
}

bool caustics(postfx::CausticsSettings& s, const ViewFeatures& features) {
  bool changed = ImGui::Checkbox("seabed caustics (C)", &s.enabled);
  changed |= causticsModel(s.model);
  if (s.model == postfx::CausticsModel::WavefrontAreaRatio && !features.physicalCaustics)
    ImGui::TextDisabled(
        "the wavefront area ratio needs --caustics-model wavefront-area-ratio at start");
  changed |= ImGui::SliderFloat("intensity##caustics", &s.intensity, 0.0f, 4.0f);
  changed |= ImGui::SliderFloat("surface fade (m)", &s.surfaceFadeDepth, 0.0f, 10.0f);
  changed |= ImGui::SliderFloat("lod bias", &s.lodBias, -4.0f, 8.0f);
  changed |= ImGui::SliderFloat("min cascade contrast", &s.minCascadeContrast, 0.0f, 1.0f);
  changed |=
      ImGui::SliderFloat("max receiver depth (m)", &s.maxReceiverDepth, 0.5f, 100.0f, "%.1f", kLog);
  changed |= ImGui::SliderFloat("max irradiance", &s.maxIrradiance, 1.0f, 1024.0f, "%.0f", kLog);
  if (s.model == postfx::CausticsModel::TileIrradiance) {
    changed |= ImGui::SliderInt("tile resolution", &s.tileResolution, 32, 1024, "%d", kLog);
    changed |= ImGui::SliderInt("tile depth layers", &s.tileDepthLayers, 4, 8);
    changed |= ImGui::SliderFloat("tile min modulation", &s.tileMinModulation, 0.0f, 2.0f);
  } else if (s.model == postfx::CausticsModel::RayDeviation) {
    changed |= ImGui::SliderFloat("tau", &s.tau, 0.0f, 10000.0f, "%.0f", kLog);
    changed |= ImGui::SliderFloat("reflection weight", &s.reflectionWeight, 0.0f, 1.0f);
  } else {
    changed |= ImGui::SliderInt("grid resolution", &s.gridResolution, 64, 1024, "%d", kLog);
    changed |= ImGui::SliderFloat("window size (m)", &s.windowSize, 1.0f, 256.0f, "%.1f", kLog);
    changed |= ImGui::SliderInt("depth layers", &s.depthLayers, 1, 8);
  }
  return changed;
}

bool godRays(postfx::GodRaySettings& s) {
  bool changed = ImGui::Checkbox("god rays (G)", &s.enabled);
  changed |= ImGui::SliderInt("samples", &s.sampleCount, 4, 64);
  changed |= ImGui::SliderFloat("intensity##godrays", &s.intensity, 0.0f, 4.0f);
  static const char* const kResolutions[] = {"full", "half", "quarter"};
  int current = s.resolution == postfx::GodRayResolution::Full   ? 0
                : s.resolution == postfx::GodRayResolution::Half ? 1
                                                                 : 2;
  if (ImGui::Combo("resolution", &current, kResolutions, 3)) {
    s.resolution = current == 0   ? postfx::GodRayResolution::Full
                   : current == 1 ? postfx::GodRayResolution::Half
                                  : postfx::GodRayResolution::Quarter;
    changed = true;
  }
  changed |= ImGui::SliderFloat("grid spacing (m)", &s.gridSpacing, 0.05f, 5.0f, "%.2f", kLog);
  changed |= ImGui::SliderFloat("surface fade (m)##godrays", &s.surfaceFadeDistance, 0.0f, 10.0f);
  changed |= ImGui::SliderFloat("depth fade (m)", &s.depthFadeDistance, 0.0f, 200.0f);
  changed |= ImGui::SliderFloat("max distance (m)", &s.maxDistance, 1.0f, 500.0f, "%.0f", kLog);
  changed |= ImGui::Checkbox("dither", &s.dither);
  return changed;
}

bool objectCaustics(postfx::ObjectCausticsSettings& s, const ViewFeatures& features) {
  if (!features.objectCaustics) {
    ImGui::TextDisabled("started with --no-object-caustics");
    return false;
  }
  bool changed = ImGui::Checkbox("object caustics", &s.enabled);
  changed |= ImGui::SliderInt("map size", &s.mapSize, 16, 4096, "%d", kLog);
  changed |= ImGui::SliderInt("ray grid", &s.gridSize, 16, 2048, "%d", kLog);
  changed |= ImGui::SliderInt("hit iterations", &s.iterations, 1, 8);
  changed |= ImGui::SliderInt("exit iterations", &s.exitIterations, 1, 8);
  changed |= ImGui::SliderFloat("splat radius (texels)", &s.splatRadius, 0.5f, 8.0f);
  changed |= ImGui::SliderFloat("footprint scale", &s.footprintScale, 1.0f, 8.0f);
  changed |= ImGui::SliderFloat("intensity##object", &s.intensity, 0.0f, 4.0f);
  changed |= ImGui::Checkbox("temporal filter", &s.temporalFilter);
  changed |= ImGui::SliderFloat("temporal weight", &s.temporalWeight, 0.0f, 0.95f);
  return changed;
}

bool sunAndWater(Sun& sun, postfx::water::Optics& optics) {
  bool changed = sliderDegrees("sun elevation", sun.elevation, 1.0, 90.0);
  changed |= sliderDegrees("sun azimuth", sun.azimuth, 0.0, 360.0);
  changed |= ImGui::DragFloat3("sun irradiance", glm::value_ptr(sun.irradiance), 0.01f, 0.0f, 20.0f,
                               "%.2f");
  changed |= sliderDouble("water ior", optics.ior, 1.0, 2.0, "%.3f");
  changed |= sliderDouble("ior spread", optics.iorSpread, 0.0, 0.05, "%.4f");
  changed |= dragRgb("absorption (1/m)", optics.absorption);
  changed |= dragRgb("scattering (1/m)", optics.scattering);
  return changed;
}

}  // namespace

bool editViewSettings(ViewSettings& settings, const ViewFeatures& features) {
  // Room for the labels beside the widgets in the overlay's 400 px.
  ImGui::PushItemWidth(190.0f);
  bool changed = false;
  if (ImGui::CollapsingHeader("Seabed caustics", ImGuiTreeNodeFlags_DefaultOpen))
    changed |= caustics(settings.caustics, features);
  if (ImGui::CollapsingHeader("God rays", ImGuiTreeNodeFlags_DefaultOpen))
    changed |= godRays(settings.godRays);
  if (ImGui::CollapsingHeader("Object caustics"))
    changed |= objectCaustics(settings.objectCaustics, features);
  if (ImGui::CollapsingHeader("Sun and water"))
    changed |= sunAndWater(settings.sun, settings.optics);
  ImGui::PopItemWidth();
  return changed;
}

}  // namespace ocean
