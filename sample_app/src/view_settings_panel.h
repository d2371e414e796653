#pragma once
// The overlay's settings panel: every live setting of the view, as ImGui widgets. It edits a
// copy; the view hands the copy to the plugin, whose validation alone decides what is valid
// (a value typed past a slider's end with Ctrl+click is not clamped here but sent as typed).
#include "view_settings.h"

namespace ocean {

// What the context was created with: a feature it lacks is shown with the flag that adds it.
struct ViewFeatures {
  bool physicalCaustics = false;
  bool objectCaustics = false;
};

// Draws the panel's widgets into the current ImGui window; true when one of them changed
// `settings` this frame.
bool editViewSettings(ViewSettings& settings, const ViewFeatures& features);

}  // namespace ocean
