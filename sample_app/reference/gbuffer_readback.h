#pragma once
// The G-buffer a frame handed the plugin, read back from GL once: per pixel the view-space
// position (the plugin's own reconstruction, shaders/shared/gbuffer_codec.h), the decoded world
// normal, linear albedo and whether anything was drawn. Row-major, bottom row first.
#include <cstdint>
#include <string>
#include <vector>

#include <postfx/postfx.h>
#include <glm/glm.hpp>

#include "frame_receivers.h"

namespace ocean::reference {

struct GBufferCopy {
  int width = 0, height = 0;
  std::vector<glm::dvec3> viewPosition;  // m, view space (camera looks down -z)
  std::vector<glm::dvec3> normal;        // world, decoded (unit, or 0 where broken)
  std::vector<glm::vec3> albedo;         // linear reflectance as the plugin reads it
  std::vector<std::uint8_t> sky;         // 1: nothing drawn (or a NaN depth)
};

// Needs a current GL context and the textures of `frame`; false with a message otherwise.
bool readGBuffer(const postfx::CreateDesc& create, const postfx::FrameDesc& frame, GBufferCopy& out,
                 std::string& error);

// The receivers of `frame` read back into `gbuffer`: its camera, projection and water level.
FrameReceivers receiversOf(const postfx::FrameDesc& frame, const GBufferCopy& gbuffer);

}  // namespace ocean::reference
