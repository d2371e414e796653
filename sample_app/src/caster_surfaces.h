#pragma once
// How the sample shows its glass and metal: forward passes over the lit, fogged frame after the
// plugin, as a deferred engine draws what the G-buffer cannot hold.
//   metal  drawn over its own G-buffer pixels (depth equal, added): the environment it mirrors
//          and the sun's highlight; its G-buffer albedo is only the diffuse share, so the
//          deferred light and the plugin's caustics hardly light it.
//   glass  left out of the G-buffer, so the frame holds what lies behind it (the plugin's
//          caustics on it too); drawn with its far side's normal and distance (a pass of its
//          own) as two-surface image-space refraction of that frame plus Fresnel reflection.
// The plugin's view of the casters does not change: they are in the shadow maps and its
// caster list as before.
#include <epoxy/gl.h>

#include <string>

#include <glkit/handle.h>
#include <glkit/program.h>
#include <glm/glm.hpp>

#include "gpu_scene.h"

namespace ocean {

class CasterSurfaces {
 public:
  // Allocates only what the scene needs: nothing without glass or metal.
  bool create(const GpuScene& scene, int width, int height, std::string& error);
  bool hasGlass() const { return glass_.id() != 0; }

  // Adds the metal's reflections into the framebuffer bound (the frame, with the G-buffer's
  // depth attached). Frame constants at binding 0.
  void drawMetal(const GpuScene& scene, const glm::dvec3& eye, GLuint shadowMap) const;
  // Draws the glass into `frameFbo` (its colour `frame`, with a depth buffer holding the
  // G-buffer's depth, which the glass then writes), refracting the frame as copied into
  // `frameCopy` (same size and format). Leaves `frameFbo` bound.
  void drawGlass(const GpuScene& scene, const glm::dvec3& eye, GLuint frame, GLuint frameCopy,
                 GLuint frameFbo, GLuint sceneDepth, GLuint shadowMap) const;

 private:
  int width_ = 0, height_ = 0;
  glkit::Program metal_, glassBack_, glass_;
  glkit::Texture backFaces_, backDepth_;
  glkit::Framebuffer backFbo_;
};

}  // namespace ocean
