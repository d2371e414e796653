#include "local_water_setup.h"

#include <memory>

#include <scene/pool_scene.h>

#include "pool_water.h"
#include "wake_water.h"

namespace ocean {

bool attachLocalWater(const Preset& preset, const ocean_scene::Model& scene, Renderer& renderer,
                      std::string& error) {
  if (preset.scene == SceneKind::Wake) {
    std::unique_ptr<WakeWater> wake = WakeWater::create(WakeDesc{}, scene, error);
    if (!wake) return false;
    renderer.setLocalWater(std::move(wake));
    return true;
  }
  if (preset.scene != SceneKind::Pool) return true;
  std::unique_ptr<PoolWater> pool = PoolWater::create(ocean_scene::PoolSceneParams{}, scene, error);
  if (!pool) return false;
  renderer.setLocalWater(std::move(pool));
  return true;
}

}  // namespace ocean
