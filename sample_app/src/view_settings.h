#pragma once
// Everything the view lets the user change while it runs, as one plain copy: the overlay edits
// it, live_settings.h hands it to the plugin and the renderer.
#include <postfx/postfx.h>
#include <postfx/water/optics.h>

#include "camera.h"

namespace ocean {

struct ViewSettings {
  postfx::CausticsSettings caustics;
  postfx::GodRaySettings godRays;
  postfx::ObjectCausticsSettings objectCaustics;
  Sun sun;
  postfx::water::Optics optics;  // what the renderer's fog and the plugin's passes are given
};

}  // namespace ocean
