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
#include "pattern_comparison.h"

namespace ocean {
namespace {

struct ExrImage {
  int width = 0, height = 0, channels = 0;
  std::vector<std::string> names;
  std::vector<float> pixels;  // interleaved, top row first (as the file stores it)
  // What lit it (render and reference write these; "" for a file without them).
  std::string caustics, objectCaustics;
  float exposure = 1.0f;  // the sample's, "ocean:exposure" (1 for a file without it)

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
  image.caustics = spec.get_string_attribute("ocean:caustics");
  image.objectCaustics = spec.get_string_attribute("ocean:objectCaustics");
  image.exposure = exposureFromAttribute(spec.get_string_attribute("ocean:exposure"));
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

// The sample's tone mapping (shaders/sample/tonemap.frag, after the exposure): ACES fit, sRGB.
float srgbEncode(float c) {
  c = std::clamp(c, 0.0f, 1.0f);
  return c < 0.0031308f ? c * 12.92f : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
}
glm::vec3 toneMap(const glm::vec3& x) {
  const glm::vec3 a = glm::clamp((x * (2.51f * x + 0.03f)) / (x * (2.43f * x + 0.59f) + 0.14f),
                                 glm::vec3(0.0f), glm::vec3(1.0f));
  return {srgbEncode(a.r), srgbEncode(a.g), srgbEncode(a.b)};
}

// The pattern-only agreement (reference::comparePatterns), a few lines; `what` names the light
// ("pattern", "reflected pattern").
void printPattern(const char* what, const reference::PatternComparison& p) {
  std::printf(
      "compare: %s (added light / flat water's, %zu pixels with flat light >= 1/4 of its "
      "median): correlation %.4f, relative RMSE %.4f; contrast (std/mean) plugin %.3f, "
      "reference %.3f; p99 plugin %.3f, reference %.3f; mean plugin %.4f, reference %.4f\n",
      what, p.pixels, p.correlation, p.relativeRmse, p.methodContrast, p.referenceContrast,
      p.methodP99, p.referenceP99, p.methodMean, p.referenceMean);
  const reference::PatternSpectrum& s = p.spectrum;
  if (s.patchSize == 0) {
    std::printf("compare: sharpness: no patch of 32x32 compared pixels\n");
    return;
  }
  std::printf(
      "compare: sharpness over the %dx%d patch at (%d, %d): plugin / reference power per "
      "octave of period (pixels):",
      s.patchSize, s.patchSize, s.patchX, s.patchY);
  for (const reference::SpectrumOctave& o : s.octaves)
    std::printf(" %g-%g: %.2f", o.minPeriodPixels, o.maxPeriodPixels, o.ratio);
  std::printf("; 4-64 px %.2f (%s); largest narrow peak %.2f at %.1f px\n", s.fineRatio,
              s.verdict.c_str(), s.peak, s.peakPeriodPixels);
}

// The frames must belong together: the reference never holds the plugin's caustics, so neither
// may the frame without caustics (nor flat water's, in the casters' shadows), and a plugin
// frame with object caustics needs a reference that traced them. Files without the attributes
// (written by something else) are taken as they are.
bool framesBelongTogether(const Options& options, const ExrImage& plugin, const ExrImage& traced,
                          const ExrImage& base, const ExrImage* flat, std::string& error) {
  if (base.caustics == "plugin" || base.objectCaustics == "plugin") {
    error = "--base '" + options.baseImage + "' has the plugin's " +
            (base.caustics == "plugin" ? "seabed" : "object") +
            " caustics in it: render it with --no-caustics --no-object-caustics";
    return false;
  }
  if (flat != nullptr && flat->objectCaustics == "plugin") {
    error = "--flat '" + options.flatImage +
            "' has the plugin's object caustics in it: render it with --no-object-caustics";
    return false;
  }
  if (plugin.objectCaustics == "plugin" && traced.objectCaustics == "off") {
    error = "--plugin '" + options.pluginImage + "' has object caustics but --reference '" +
            options.referenceImage +
            "' did not trace them (it was run with --no-object-caustics): run both alike";
    return false;
  }
  return true;
}

}  // namespace

int runCompare(const Options& options) {
  std::string error;
  if (!checkOutputPath(options.out, error)) return commandFailed(error);
  ExrImage plugin, traced, base, flat;
  const bool withPattern = !options.flatImage.empty();
  if (!readExr("--plugin", options.pluginImage, plugin, error) ||
      !readExr("--reference", options.referenceImage, traced, error) ||
      !readExr("--base", options.baseImage, base, error) ||
      (withPattern && !readExr("--flat", options.flatImage, flat, error))) {
    return commandFailed(error);
  }
  auto sizeOf = [](const ExrImage& image) {
    return std::to_string(image.width) + "x" + std::to_string(image.height);
  };
  auto sameSize = [&](const ExrImage& image) {
    return image.width == traced.width && image.height == traced.height;
  };
  if (!sameSize(plugin) || !sameSize(base) || (withPattern && !sameSize(flat))) {
    return commandFailed("the images differ in size (plugin " + sizeOf(plugin) + ", reference " +
                         sizeOf(traced) + ", base " + sizeOf(base) +
                         (withPattern ? ", flat " + sizeOf(flat) : std::string()) + ")");
  }
  if (!framesBelongTogether(options, plugin, traced, base, withPattern ? &flat : nullptr, error))
    return commandFailed(error);
  const int litChannel = traced.channel("caustic.lit");
  if (litChannel < 0)
    return commandFailed("--reference '" + options.referenceImage +
                         "' has no caustic.lit channel (write it with ocean_sample reference)");
  const int width = traced.width, height = traced.height;
  const size_t n = size_t(width) * size_t(height);
  std::vector<double> methodLight(n), referenceLight(n), flatLight(withPattern ? n : 0);
  std::vector<std::uint8_t> lit(n);
  // The object caustics' region (the casters' shadows and where their traced light falls), when
  // the reference traced casters.
  const int regionChannel = traced.channel("caustic.objectRegion");
  std::vector<std::uint8_t> region(regionChannel >= 0 ? n : 0);
  size_t regionPixels = 0;
  // The pixels above the water flat water's mirror light reaches, when the reference traced the
  // reflected light.
  const int mirrorChannel = traced.channel("caustic.reflectedLit");
  std::vector<std::uint8_t> mirror(mirrorChannel >= 0 ? n : 0);
  size_t mirrorPixels = 0;
  for (size_t i = 0; i < n; ++i) {
    lit[i] = traced.pixels[i * size_t(traced.channels) + size_t(litChannel)] > 0.5f ? 1 : 0;
    if (regionChannel >= 0) {
      region[i] = traced.pixels[i * size_t(traced.channels) + size_t(regionChannel)] > 0.5f ? 1 : 0;
      regionPixels += region[i];
    }
    if (mirrorChannel >= 0) {
      mirror[i] = traced.pixels[i * size_t(traced.channels) + size_t(mirrorChannel)] > 0.5f ? 1 : 0;
      mirrorPixels += mirror[i];
    }
    methodLight[i] = luminance(rgb(plugin, i) - rgb(base, i));
    referenceLight[i] = luminance(rgb(traced, i) - rgb(base, i));
    if (withPattern) flatLight[i] = luminance(rgb(flat, i) - rgb(base, i));
    const bool finite = std::isfinite(methodLight[i]) && std::isfinite(referenceLight[i]) &&
                        (!withPattern || std::isfinite(flatLight[i]));
    if ((lit[i] || (regionChannel >= 0 && region[i]) || (mirrorChannel >= 0 && mirror[i])) &&
        !finite)
      return commandFailed("a lit pixel of the inputs is NaN or infinite (pixel " +
                           std::to_string(i % size_t(width)) + ", " +
                           std::to_string(i / size_t(width)) + " from the top)");
  }
  const reference::CausticComparison c =
      reference::compareAddedLight(methodLight, referenceLight, lit);
  // A night scene (the sun below the horizon) has only its lights' object caustics to compare.
  if (c.pixels == 0 && regionPixels == 0 && mirrorPixels == 0)
    return commandFailed(
        "no lit underwater pixel, no object caustics and no mirror-lit pixel to compare");
  reference::PatternComparison pattern, mirrorPattern;
  if (withPattern && c.pixels > 0) {
    pattern =
        reference::comparePatterns(methodLight, referenceLight, flatLight, lit, width, height);
    // Above the water alone (the seabed's caustics off in every frame): no underwater pattern.
    if (pattern.pixels == 0 && mirrorPixels == 0)
      return commandFailed("no lit underwater pixel has flat-water light in --flat '" +
                           options.flatImage +
                           "' (render it with --caustics-model ray-deviation "
                           "--tau 0 and the same scene options)");
  }
  if (withPattern && mirrorPixels > 0) {
    mirrorPattern =
        reference::comparePatterns(methodLight, referenceLight, flatLight, mirror, width, height);
    if (mirrorPattern.pixels == 0)
      return commandFailed("no mirror-lit pixel has flat-water light in --flat '" +
                           options.flatImage + "' (render it with --flat-water)");
  }
  // The pattern panels show the light under the water or above it, whichever covers more pixels.
  const reference::PatternComparison& shown =
      pattern.pixels >= mirrorPattern.pixels ? pattern : mirrorPattern;

  // One scale for every added-light panel: the reference's 99th percentile over lit pixels.
  std::vector<double> litReference;
  for (size_t i = 0; i < n; ++i)
    if (c.pixels > 0 ? lit[i] != 0 : (regionPixels > 0 ? region[i] != 0 : mirror[i] != 0))
      litReference.push_back(referenceLight[i]);
  const size_t k = (litReference.size() - 1) * 99 / 100;
  std::nth_element(litReference.begin(), litReference.begin() + long(k), litReference.end());
  const double scale = std::max(litReference[k], 1e-12);
  const double patternScale = std::max(shown.referenceP99, 1e-12);

  // 3 x 2 panels (3 x 3 with the pattern), written bottom row first (GL order) as writeImage
  // expects.
  const int rows = withPattern ? 3 : 2;
  const int outWidth = 3 * width, outHeight = rows * height;
  std::vector<uint8_t> rgba(size_t(outWidth) * size_t(outHeight) * 4, 255);
  auto put = [&](int panelX, int panelY, int x, int yTop, const glm::vec3& colour) {
    const int row = outHeight - 1 - (panelY * height + yTop);
    uint8_t* p = &rgba[(size_t(row) * size_t(outWidth) + size_t(panelX * width + x)) * 4];
    for (int ch = 0; ch < 3; ++ch)
      p[ch] = uint8_t(std::lround(255.0f * std::clamp(colour[ch], 0.0f, 1.0f)));
  };
  auto grey = [](double v, double s) { return glm::vec3(srgbEncode(float(v / s))); };
  auto signedColour = [](double d, double s) {
    const float v = float(d / s);
    return glm::vec3(srgbEncode(v), 0.0f, srgbEncode(-v));
  };
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const size_t i = size_t(y) * size_t(width) + size_t(x);
      // All three at the plugin frame's exposure: one scale for the eye to compare.
      put(0, 0, x, y, toneMap(glm::max(rgb(plugin, i), glm::vec3(0.0f)) * plugin.exposure));
      put(1, 0, x, y, toneMap(glm::max(rgb(traced, i), glm::vec3(0.0f)) * plugin.exposure));
      put(2, 0, x, y, toneMap(glm::max(rgb(base, i), glm::vec3(0.0f)) * plugin.exposure));
      put(0, 1, x, y, grey(methodLight[i], scale));
      put(1, 1, x, y, grey(referenceLight[i], scale));
      put(2, 1, x, y, signedColour(methodLight[i] - referenceLight[i], scale));
      if (!withPattern) continue;
      const bool compared = !shown.compared.empty() && shown.compared[i] != 0;
      const double pm = compared ? shown.methodPattern[i] : 0.0;
      const double pr = compared ? shown.referencePattern[i] : 0.0;
      put(0, 2, x, y, compared ? grey(pm, patternScale) : glm::vec3(0.0f));
      put(1, 2, x, y, compared ? grey(pr, patternScale) : glm::vec3(0.0f));
      put(2, 2, x, y, compared ? signedColour(pm - pr, patternScale) : glm::vec3(0.0f));
    }
  }
  if (!writeImage(options.out, outWidth, outHeight, rgba, nullptr, error))
    return commandFailed(error);
  if (c.pixels > 0) {
    std::printf(
        "compare: %zu lit underwater pixels: relative RMSE %.4f, correlation %.4f (added light, "
        "luminance; mean plugin %.4g, reference %.4g)\n",
        c.pixels, c.relativeRmse, c.correlation, c.methodMean, c.referenceMean);
  } else {
    std::printf("compare: no sunlit underwater pixel\n");
  }
  if (withPattern && pattern.pixels > 0) printPattern("pattern", pattern);
  if (mirrorPixels > 0) {
    const reference::CausticComparison m =
        reference::compareAddedLight(methodLight, referenceLight, mirror);
    std::printf(
        "compare: above the water (%zu pixels flat water's mirror light reaches): reflected light "
        "correlation %.4f, relative RMSE %.4f, flux plugin / reference %.3f\n",
        m.pixels, m.correlation, m.relativeRmse,
        m.referenceMean != 0.0 ? m.methodMean / m.referenceMean : 0.0);
    if (withPattern) printPattern("reflected pattern", mirrorPattern);
  }
  if (regionPixels > 0) {
    const reference::CausticComparison o =
        reference::compareAddedLight(methodLight, referenceLight, region);
    std::printf(
        "compare: object caustics (%zu pixels: the casters' shadows and where their traced light "
        "falls): correlation %.4f, relative RMSE %.4f, flux plugin / reference %.3f (mean added "
        "light plugin %.4g, reference %.4g)\n",
        o.pixels, o.correlation, o.relativeRmse,
        o.referenceMean != 0.0 ? o.methodMean / o.referenceMean : 0.0, o.methodMean,
        o.referenceMean);
  } else if (regionChannel >= 0) {
    std::printf("compare: object caustics: the reference has no caster in view\n");
  }
  std::printf(
      "compare: %s (top: plugin | reference | no caustics; then added light plugin | "
      "reference | difference%s)\n",
      options.out.c_str(),
      withPattern ? "; then the pattern (added light / flat water's) likewise" : "");
  return 0;
}

}  // namespace ocean
