#include "multi_view.h"

#include <algorithm>
#include <cmath>

namespace ocean {

std::unique_ptr<MultiView> MultiView::create(Renderer& primary, const ocean_scene::Model& scene,
                                             int count, std::string& error) {
  std::unique_ptr<MultiView> multi(new MultiView());
  multi->views_.push_back(&primary);
  for (int i = 1; i < count; ++i) {
    auto view = Renderer::createView(primary.settings(), scene, primary, error);
    if (!view) return nullptr;
    multi->views_.push_back(view.get());
    multi->owned_.push_back(std::move(view));
  }
  return multi;
}

bool MultiView::render(const std::vector<FrameInput>& inputs, PluginSetup& plugin,
                       glcontext::DebugLog* debugLog, std::string& error) {
  // The primary first: it updates the ocean every view reads.
  const size_t count = std::min(inputs.size(), views_.size());
  std::vector<HostFrame> frames;
  frames.reserve(count);
  for (size_t i = 0; i < count; ++i) {
    if (i > 0) views_[i]->optics() = views_[0]->optics();  // edited live on the primary
    if (!views_[i]->beginFrame(inputs[i], error)) return false;
  }
  for (size_t i = 0; i < count; ++i) frames.push_back(views_[i]->hostFrame());
  if (!plugin.dispatchViews(frames, error)) return false;
  for (size_t i = 0; i < count; ++i) views_[i]->endFrame();
  if (debugLog != nullptr) {
    for (const auto& message : debugLog->take()) {
      if (message.type == GL_DEBUG_TYPE_ERROR) {
        error = glcontext::debugMessageString(message);
        return false;
      }
    }
  }
  return true;
}

std::vector<Camera> cubeFaceCameras(const glm::dvec3& position) {
  constexpr double kHalfPi = 1.57079632679489661923;
  constexpr double kVertical = kHalfPi - 1e-4;
  // yaw 0 looks toward -Z, yaw +pi/2 toward -X (Camera::forward).
  const double yawPitch[6][2] = {{-kHalfPi, 0.0},   {kHalfPi, 0.0},       {0.0, kVertical},
                                 {0.0, -kVertical}, {2.0 * kHalfPi, 0.0}, {0.0, 0.0}};
  std::vector<Camera> cameras(6);
  for (int f = 0; f < 6; ++f) {
    Camera& c = cameras[size_t(f)];
    c.position = position;
    c.yaw = yawPitch[f][0];
    c.pitch = yawPitch[f][1];
    c.fovY = kHalfPi;
  }
  return cameras;
}

std::vector<float> cubeCross(const std::vector<std::vector<float>>& faces, int size) {
  // Bottom row first (GL order), so the cross's top row (+Y above -Z... ) is row 2:
  //            [+Y]
  //   [-X] [-Z] [+X] [+Z]      (looking around from -X through the front -Z to +X and back)
  //            [-Y]
  // Face order in `faces`: +X, -X, +Y, -Y, +Z, -Z. Cells (column, row from the bottom).
  const int cells[6][2] = {{2, 1}, {0, 1}, {1, 2}, {1, 0}, {3, 1}, {1, 1}};
  const size_t width = size_t(size) * 4, rowFloats = size_t(size) * 4;
  std::vector<float> out(width * 4 * size_t(size) * 3, 0.0f);
  for (int f = 0; f < 6; ++f) {
    const std::vector<float>& face = faces[size_t(f)];
    for (int y = 0; y < size; ++y) {
      const size_t outRow = size_t(cells[f][1] * size + y);
      std::copy_n(face.begin() + ptrdiff_t(size_t(y) * rowFloats), rowFloats,
                  out.begin() + ptrdiff_t(outRow * width * 4 + size_t(cells[f][0]) * rowFloats));
    }
  }
  return out;
}

}  // namespace ocean
