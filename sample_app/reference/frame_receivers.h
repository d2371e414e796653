#pragma once
// The surfaces a camera sees, one receiver per pixel, as the traced frame reference gathers
// light on them: each pixel's camera-relative world position and G-buffer normal, and how to
// project a point back to its pixel.
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace ocean::reference {

struct FrameReceivers {
  int width = 0, height = 0;
  glm::dvec3 camera{0.0};       // world position (m); every position below is relative to it
  glm::dmat3 worldToView{1.0};  // rotation only; the view looks down -z
  glm::dvec4 projection{1.0, 1.0, 0.0, 0.0};  // P[0][0], P[1][1], P[2][0], P[2][1]
  double level = 0.0;                         // water level, world y (m)
  // Row-major, bottom row first (GL order), width * height entries each.
  std::vector<glm::dvec3> position;  // camera-relative world (m)
  std::vector<glm::dvec3> normal;    // unit world normal from the G-buffer
  std::vector<std::uint8_t> valid;   // 1: a surface under the water level is drawn here
  // 1: a surface above the water level is drawn here (the receivers of the light the water
  // reflects up, FrameTraceDesc::reflected). Empty: none.
  std::vector<std::uint8_t> above;

  size_t size() const { return static_cast<size_t>(width) * static_cast<size_t>(height); }
  // Angle one pixel subtends at the centre of the view (rad).
  double radiansPerPixel() const { return 2.0 / (std::abs(projection.y) * height); }
  // Depth of a receiver below the water level (m).
  double depthBelow(size_t i) const { return level - (camera.y + position[i].y); }
  // Continuous pixel coordinates (pixel (i, j) covers [i, i+1) x [j, j+1)) of a camera-relative
  // point; false behind the camera.
  bool project(const glm::dvec3& relative, glm::dvec2& pixel) const;
};

// Receivers from a read-back G-buffer: `viewPositions` (view space, per pixel, from the depth
// reconstruction) and world normals; `sky` marks pixels where nothing was drawn. A pixel is a
// valid receiver when it is not sky, its position is finite, its normal is unit and it lies
// below the water level; `above` when it is all that but lies above the level.
FrameReceivers makeFrameReceivers(int width, int height, const glm::dvec3& camera,
                                  const glm::dmat3& worldToView, const glm::dvec4& projection,
                                  double level, const std::vector<glm::dvec3>& viewPositions,
                                  const std::vector<glm::dvec3>& normals,
                                  const std::vector<std::uint8_t>& sky);

}  // namespace ocean::reference
