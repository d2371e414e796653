// ocean_sample compare: the plugin's added caustic light against the traced reference's, pixel
// by pixel over the lit underwater pixels, and a side-by-side picture (see --help).
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <glm/glm.hpp>

#include "caustic_comparison.h"
#include "commands.h"
#include "image_output.h"

namespace ocean {
namespace {

struct ExrImage {
  int width = 0, height = 0, channels = 0;
  std::vector<std::string> names;
  std::vector<float> pixels;  // interleaved, top row first (as the file stores it)

  int channel(const std::string& name) const {
    const auto it = std::find(names.begin(), names.end(), name);
    return it == names.end() ? -1 : static_cast<int>(it - names.begin());
  }
};

bool readExr(const std::string& what, const std::string& path, ExrImage& image,
             std::string& error) {
  if (path.empty()) {
    error = "compare needs " + what;
    return false;
  }
  auto input = OIIO::ImageInput::open(path);
  if (!input) {
    error = "cannot read " + what + " '" + path + "': " + OIIO::geterror();
    return false;
  }
  const OIIO::ImageSpec& spec = input->spec();
  image.width = spec.width;
  image.height = spec.height;
  image.channels = spec.nchannels;
  image.names = spec.channelnames;
  if (image.width <= 0 || image.height <= 0 || image.channels <= 0) {
    error = what + " '" + path + "' has no pixels";
    return false;
  }
  image.pixels.resize(size_t(image.width) * size_t(image.height) * size_t(image.channels));
  if (!input->read_image(0, 0, 0, image.channels, OIIO::TypeDesc::FLOAT, image.pixels.data())) {
    error = "cannot read " + what + " '" + path + "': " + input->geterror();
    return false;
  }
  for (const char* name : {"R", "G", "B"}) {
    if (image.channel(name) < 0) {
      error = what + " '" + path + "' has no " + name + " channel";
      return false;
    }
  }
  return true;
}

glm::vec3 rgb(const ExrImage& image, size_t i) {
  const float* p = &image.pixels[i * size_t(image.channels)];
  return {p[image.channel("R")], p[image.channel("G")], p[image.channel("B")]};
}

double luminance(const glm::vec3& c) {
  return 0.2126 * double(c.r) + 0.7152 * double(c.g) + 0.0722 * double(c.b);
}

// The sample's tone mapping (shaders/sample/tonemap.frag at exposure 1): ACES fit, then sRGB.
float srgbEncode(float c) {
  c = std::clamp(c, 0.0f, 1.0f);
  return c < 0.0031308f ? c * 12.92f : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
}
glm::vec3 toneMap(const glm::vec3& x) {
  const glm::vec3 a = glm::clamp((x * (2.51f * x + 0.03f)) / (x * (2.43f * x + 0.59f) + 0.14f),
                                 glm::vec3(0.0f), glm::vec3(1.0f));
  return {srgbEncode(a.r), srgbEncode(a.g), srgbEncode(a.b)};
}

}  // namespace

int runCompare(const Options& options) {
  std::string error;
  if (!checkOutputPath(options.out, error)) return commandFailed(error);
  ExrImage plugin, traced, base;
  if (!readExr("--plugin", options.pluginImage, plugin, error) ||
      !readExr("--reference", options.referenceImage, traced, error) ||
      !readExr("--base", options.baseImage, base, error)) {
    return commandFailed(error);
  }
  if (plugin.width != traced.width || plugin.height != traced.height ||
      base.width != traced.width || base.height != traced.height) {
    return commandFailed("the three images differ in size (plugin " + std::to_string(plugin.width) +
                         "x" + std::to_string(plugin.height) + ", reference " +
                         std::to_string(traced.width) + "x" + std::to_string(traced.height) +
                         ", base " + std::to_string(base.width) + "x" +
                         std::to_string(base.height) + ")");
  }
  const int litChannel = traced.channel("caustic.lit");
  if (litChannel < 0)
    return commandFailed("--reference '" + options.referenceImage +
                         "' has no caustic.lit channel (write it with ocean_sample reference)");
  const int width = traced.width, height = traced.height;
  const size_t n = size_t(width) * size_t(height);
  std::vector<double> methodLight(n), referenceLight(n);
  std::vector<std::uint8_t> lit(n);
  for (size_t i = 0; i < n; ++i) {
    lit[i] = traced.pixels[i * size_t(traced.channels) + size_t(litChannel)] > 0.5f ? 1 : 0;
    methodLight[i] = luminance(rgb(plugin, i) - rgb(base, i));
    referenceLight[i] = luminance(rgb(traced, i) - rgb(base, i));
    if (lit[i] && !(std::isfinite(methodLight[i]) && std::isfinite(referenceLight[i])))
      return commandFailed("a lit pixel of the inputs is NaN or infinite (pixel " +
                           std::to_string(i % size_t(width)) + ", " +
                           std::to_string(i / size_t(width)) + " from the top)");
  }
  const reference::CausticComparison c =
      reference::compareAddedLight(methodLight, referenceLight, lit);
  if (c.pixels == 0) return commandFailed("no lit underwater pixel to compare");

  // One scale for every added-light panel: the reference's 99th percentile over lit pixels.
  std::vector<double> litReference;
  for (size_t i = 0; i < n; ++i)
    if (lit[i]) litReference.push_back(referenceLight[i]);
  const size_t k = (litReference.size() - 1) * 99 / 100;
  std::nth_element(litReference.begin(), litReference.begin() + long(k), litReference.end());
  const double scale = std::max(litReference[k], 1e-12);

  // 3 x 2 panels, written bottom row first (GL order) as writeImage expects.
  const int outWidth = 3 * width, outHeight = 2 * height;
  std::vector<uint8_t> rgba(size_t(outWidth) * size_t(outHeight) * 4, 255);
  auto put = [&](int panelX, int panelY, int x, int yTop, const glm::vec3& colour) {
    const int row = outHeight - 1 - (panelY * height + yTop);
    uint8_t* p = &rgba[(size_t(row) * size_t(outWidth) + size_t(panelX * width + x)) * 4];
    for (int ch = 0; ch < 3; ++ch)
      p[ch] = uint8_t(std::lround(255.0f * std::clamp(colour[ch], 0.0f, 1.0f)));
  };
  auto grey = [&](double v) { return glm::vec3(srgbEncode(float(v / scale))); };
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const size_t i = size_t(y) * size_t(width) + size_t(x);
      put(0, 0, x, y, toneMap(glm::max(rgb(plugin, i), glm::vec3(0.0f))));
      put(1, 0, x, y, toneMap(glm::max(rgb(traced, i), glm::vec3(0.0f))));
      put(2, 0, x, y, toneMap(glm::max(rgb(base, i), glm::vec3(0.0f))));
      put(0, 1, x, y, grey(methodLight[i]));
      put(1, 1, x, y, grey(referenceLight[i]));
      const float d = float((methodLight[i] - referenceLight[i]) / scale);
      put(2, 1, x, y, glm::vec3(srgbEncode(d), 0.0f, srgbEncode(-d)));
    }
  }
  if (!writeImage(options.out, outWidth, outHeight, rgba, nullptr, error))
    return commandFailed(error);
  std::printf(
      "compare: %zu lit underwater pixels: relative RMSE %.4f, correlation %.4f (added light, "
      "luminance; mean plugin %.4g, reference %.4g); %s (top: plugin | reference | no "
      "caustics; bottom: added light plugin | reference | difference)\n",
      c.pixels, c.relativeRmse, c.correlation, c.methodMean, c.referenceMean, options.out.c_str());
  return 0;
}

}  // namespace ocean
