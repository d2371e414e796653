// make_ocean_assets <outdir>: writes the sample's glTF models (see scene/asset_models.h).
// Run at build time by the ocean_assets target, so no model is downloaded or checked in.

#include <cstdio>
#include <filesystem>
#include <string>
#include <system_error>

#include "scene/asset_models.h"
#include "scene/gltf_writer.h"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: make_ocean_assets <outdir>\n");
    return 2;
  }
  const std::filesystem::path outDir(argv[1]);
  std::error_code ec;
  std::filesystem::create_directories(outDir, ec);
  if (ec) {
    std::fprintf(stderr, "make_ocean_assets: cannot create %s: %s\n", outDir.string().c_str(),
                 ec.message().c_str());
    return 1;
  }
  for (const ocean_scene::AssetModel& asset : ocean_scene::makeAssetModels()) {
    const std::string path = (outDir / asset.fileName).string();
    std::string error;
    if (!ocean_scene::writeGlb(asset.model, path, error)) {
      std::fprintf(stderr, "make_ocean_assets: %s\n", error.c_str());
      return 1;
    }
  }
  return 0;
}
