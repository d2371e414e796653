#include "view_overlay.h"

#include <epoxy/gl.h>
// epoxy loads GL; GLFW must not pull in the system GL header after it.
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

namespace ocean {
namespace {

// One row per pass the context has, the pass's last and median GPU time, then their total:
// the numbers the plugin's timer ring has read back (a few frames old, never waited for).
void timings(const postfx::FrameStats& stats) {
  const ImGuiTableFlags flags = ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingFixedFit;
  if (!ImGui::BeginTable("timings", 4, flags)) return;
  ImGui::TableSetupColumn("pass");
  ImGui::TableSetupColumn("last ms");
  ImGui::TableSetupColumn("median ms");
  ImGui::TableSetupColumn("samples");
  ImGui::TableHeadersRow();
  double lastTotal = 0.0, medianTotal = 0.0;
  for (int i = 0; i < postfx::kPassCount; ++i) {
    const postfx::Pass pass = postfx::Pass(i);
    const postfx::PassStats& s = stats.pass(pass);
    if (!s.present) continue;
    lastTotal += s.lastMs;
    medianTotal += s.medianMs;
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    ImGui::TextUnformatted(postfx::toString(pass));
    ImGui::TableNextColumn();
    if (s.skipped)
      ImGui::TextDisabled("skipped");
    else
      ImGui::Text("%.3f", s.lastMs);
    ImGui::TableNextColumn();
    ImGui::Text("%.3f", s.medianMs);
    ImGui::TableNextColumn();
    ImGui::Text("%u", s.samples);
  }
  ImGui::TableNextRow();
  ImGui::TableNextColumn();
  ImGui::TextUnformatted("total (sum)");
  ImGui::TableNextColumn();
  ImGui::Text("%.3f", lastTotal);
  ImGui::TableNextColumn();
  ImGui::Text("%.3f", medianTotal);
  ImGui::EndTable();
  ImGui::Text("dispatched %llu, read back %llu, dropped %llu",
              static_cast<unsigned long long>(stats.framesDispatched),
              static_cast<unsigned long long>(stats.framesResolved),
              static_cast<unsigned long long>(stats.framesDropped));
  if (stats.clampedFluxFraction >= 0.0)
    ImGui::Text("flux clamped by max irradiance: %.4f", stats.clampedFluxFraction);
}

}  // namespace

std::unique_ptr<ViewOverlay> ViewOverlay::create(GLFWwindow* window, std::string& error) {
  std::unique_ptr<ViewOverlay> overlay(new ViewOverlay());
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGuiIO& io = ImGui::GetIO();
  // The view reads and writes only the files it is given: no saved layout, no log.
  io.IniFilename = nullptr;
  io.LogFilename = nullptr;
  ImGui::StyleColorsDark();
  if (!ImGui_ImplGlfw_InitForOpenGL(window, /*install_callbacks=*/true)) {
    ImGui::DestroyContext();
    error = "Dear ImGui cannot attach to the GLFW window";
    return nullptr;
  }
  if (!ImGui_ImplOpenGL3_Init("#version 450 core")) {
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
    error = "Dear ImGui's OpenGL 3 backend cannot load GL (libGL.so.1)";
    return nullptr;
  }
  overlay->started_ = true;
  return overlay;
}

ViewOverlay::~ViewOverlay() {
  if (!started_) return;
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
}

bool ViewOverlay::capturesKeyboard() const {
  return ImGui::GetIO().WantCaptureKeyboard;
}

bool ViewOverlay::capturesMouse() const {
  return ImGui::GetIO().WantCaptureMouse;
}

bool ViewOverlay::draw(const postfx::FrameStats& stats, const ViewStatus& status,
                       const ViewFeatures& features, ViewSettings& settings) {
  ImGui_ImplOpenGL3_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  ImGui::NewFrame();
  ImGui::SetNextWindowPos(ImVec2(8, 8), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSize(ImVec2(400, 0), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowBgAlpha(0.8f);
  bool changed = false;
  if (ImGui::Begin("postfx (H hides)")) {
    ImGui::Text("%s  t = %.2f s%s  %.1f fps", status.preset, status.timeSeconds,
                status.paused ? " (paused, T)" : "", double(ImGui::GetIO().Framerate));
    ImGui::TextUnformatted("GPU time per pass");
    timings(stats);
    if (status.refusal != nullptr && !status.refusal->empty()) {
      ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.45f, 0.4f, 1.0f));
      ImGui::TextWrapped("refused, showing the last accepted settings: %s",
                         status.refusal->c_str());
      ImGui::PopStyleColor();
    }
    changed = editViewSettings(settings, features);
  }
  ImGui::End();
  ImGui::Render();
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
  return changed;
}

}  // namespace ocean
