#pragma once
// Several views of one world per frame (split-screen, the six faces of a cube-map probe), handed
// to the plugin in one dispatch: the primary renderer's ocean is updated once and shared, each
// view renders its own G-buffer, the plugin adds every view's light in one call (its shared
// pre-passes once), then each view finishes its frame.
#include <memory>
#include <string>
#include <vector>

#include <glcontext/context.h>

#include "plugin_setup.h"
#include "renderer.h"

namespace ocean {

class MultiView {
 public:
  // `primary` is view 0; `count` - 1 more views of the same size and world are made.
  static std::unique_ptr<MultiView> create(Renderer& primary, const ocean_scene::Model& scene,
                                           int count, std::string& error);

  int count() const { return int(views_.size()); }
  Renderer& view(int i) { return *views_[size_t(i)]; }
  // One frame of the first inputs.size() views (inputs[i] for view i, the same time in all);
  // the plugin draws all of them in one dispatch. debugLog: fail on any GL error the driver logged
  // (null: no check).
  bool render(const std::vector<FrameInput>& inputs, PluginSetup& plugin,
              glcontext::DebugLog* debugLog, std::string& error);

 private:
  std::vector<Renderer*> views_;
  std::vector<std::unique_ptr<Renderer>> owned_;  // views 1..
};

// The six faces of a cube-map probe at `position`, as cameras of a 90-degree field of view:
// +X, -X, +Y, -Y, +Z, -Z (the GL face order). The up and down faces look a hair (1e-4 rad) off
// the vertical: the sample's yaw-pitch camera has no roll to look straight along y.
std::vector<Camera> cubeFaceCameras(const glm::dvec3& position);
// The faces (RGBA, size x size each, bottom row first) laid out as a horizontal cross of
// 4 size x 3 size, bottom row first: -X, -Z, +X, +Z across the middle, +Y above -Z and -Y below
// it (as seen from inside the cube); the empty cells are 0.
std::vector<float> cubeCross(const std::vector<std::vector<float>>& faces, int size);

// Views laid side by side (each width x height, RGBA, bottom row first) into one image of
// count * width x height: view 0 on the left.
template <typename T>
std::vector<T> sideBySide(const std::vector<std::vector<T>>& views, int width, int height) {
  const size_t count = views.size(), row = size_t(width) * 4;
  std::vector<T> out(count * row * size_t(height));
  for (size_t v = 0; v < count; ++v)
    for (int y = 0; y < height; ++y)
      std::copy_n(views[v].begin() + ptrdiff_t(size_t(y) * row), row,
                  out.begin() + ptrdiff_t(size_t(y) * row * count + v * row));
  return out;
}

}  // namespace ocean
