#include "postfx_object_caustics_util.h"

#include <cmath>

namespace postfxtest {

SceneSpec ObjectHost::defaultSpec() {
  SceneSpec spec;
  spec.width = 160;
  spec.height = 96;
  spec.depthConvention = 0;
  spec.camera = {0.0, 4.0, 5.0};
  spec.lookDirection = {0.0, -0.75, -1.0};
  spec.floorY = 0.0;
  spec.sphere = false;
  return spec;
}

ObjectHost::ObjectHost(const glm::dvec3& sun, double receiverHalf, const SceneSpec& spec)
    : towardSun(glm::normalize(sun)),
      scene(spec),
      receivers(towardSun, glm::dvec3(0.0), receiverHalf, 0.0, 1024) {
  water = makeWaterTexture(16, 1, 0.0);
}

ObjectHost::~ObjectHost() {
  glDeleteTextures(1, &water);
}

postfx::FrameDesc ObjectHost::frame(const postfx::CasterMesh* casters, int count,
                                    const postfx::ObjectCausticsSettings& settings) const {
  postfx::FrameDesc f = makeFrame(scene, water, 1, glm::dvec3(0.0), -50.0);
  f.sun.direction = towardSun;
  f.objectCaustics.casters = casters;
  f.objectCaustics.casterCount = count;
  f.objectCaustics.receivers = receivers.desc();
  f.objectCaustics.settings = settings;
  return f;
}

bool allFinite(const std::vector<glm::dvec3>& values) {
  for (const glm::dvec3& v : values)
    if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z)) return false;
  return true;
}

}  // namespace postfxtest
