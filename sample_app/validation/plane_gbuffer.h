#pragma once
// The report's synthetic receiver: one plane seen face-on by a pinhole camera looking along its
// normal, as a G-buffer (every pixel at the same view depth, the plane's normal, white) with the
// camera matrices that make it so. Used where the compared quantity lives on a plane (seabed
// caustics on a flat or sloped floor, the object caustics' receiver) and the G-buffer only has
// to give every pixel that plane. Seen face-on, pixel rows and columns are straight, evenly
// spaced lines on the plane, so blocks of pixels map to a regular grid there (and on any plane
// it is projected onto along an image axis, such as the horizontal grid of a reference).
#include <glm/glm.hpp>

#include "synthetic_gbuffer.h"

namespace ocean::validation {

// The camera at the origin looks along -normal with image up = `imageUp` (orthogonal to the
// normal), 60 degree vertical field of view, reverse-Z with an infinite far plane (depth
// convention 0).
struct PlaneView {
  glm::dmat4 view{1.0}, projection{1.0};
  glm::dvec3 normal{0.0, 1.0, 0.0};  // the plane's, toward the camera
  double distance = 1.0;             // from the camera to the plane, m
  double focal = 0.0;                // projection[1][1]
  double aspect = 1.0;               // width / height
  // Size on the plane of one pixel (square pixels), m.
  double pixelSize(int height) const { return 2.0 * distance / focal / height; }
};
PlaneView planeView(int width, int height, double distance, const glm::dvec3& normal,
                    const glm::dvec3& imageUp);
// A horizontal floor seen straight down, image up = world -z (view x = world x, view y = -world z).
PlaneView topDownView(int width, int height, double floorDistance);

// Depth GL_DEPTH_COMPONENT32F, normals GL_RGBA16F world xyz (normal encoding 1), albedo RGBA8
// white; no target.
class PlaneGbuffer {
 public:
  PlaneGbuffer(int width, int height, const PlaneView& view);
  GLuint depth() const { return gbuffer_.depth(); }
  GLuint normal() const { return gbuffer_.normal(); }
  GLuint albedo() const { return gbuffer_.albedo(); }

 private:
  SyntheticGbuffer gbuffer_;
};

}  // namespace ocean::validation
