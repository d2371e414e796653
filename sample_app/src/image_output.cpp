#include "image_output.h"

#include <OpenImageIO/imageio.h>

#include "atomic_file.h"

#include <unistd.h>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <system_error>

namespace ocean {

std::string exposureAttribute(float exposure) {
  char text[32];
  std::snprintf(text, sizeof(text), "%.9g", double(exposure));
  return text;
}

float exposureFromAttribute(const std::string& text) {
  char* end = nullptr;
  const float value = std::strtof(text.c_str(), &end);
  if (text.empty() || end != text.c_str() + text.size() || !std::isfinite(value) || !(value > 0))
    return 1.0f;
  return value;
}
namespace {

std::string extensionOf(const std::string& path) {
  std::string extension = std::filesystem::path(path).extension().string();
  for (char& c : extension) c = char(std::tolower(static_cast<unsigned char>(c)));
  return extension;
}

template <typename T>
bool writeFlipped(const std::string& path, int width, int height, const T* pixels,
                  OIIO::TypeDesc type, std::string& error,
                  const std::vector<std::string>* channelNames = nullptr,
                  const ImageAttributes& attributes = {}) {
  const int channels = channelNames ? static_cast<int>(channelNames->size()) : 4;
  auto output = OIIO::ImageOutput::create(path);
  if (!output) {
    error = "cannot write '" + path + "': " + OIIO::geterror();
    return false;
  }
  return writeThroughTemporary(
      path,
      [&](const std::string& temporary, std::string& why) {
        OIIO::ImageSpec spec(width, height, channels, type);
        if (channelNames) spec.channelnames = *channelNames;
        for (const auto& [name, value] : attributes) spec.attribute(name, value);
        if (!output->open(temporary, spec)) {
          why = "cannot write '" + path + "': " + output->geterror();
          return false;
        }
        // GL rows are bottom-up; images are top-down: start at the last row, negative stride.
        const auto rowBytes = OIIO::stride_t(sizeof(T) * channels * width);
        const T* lastRow = pixels + size_t(height - 1) * channels * width;
        const bool written = output->write_image(type, lastRow, OIIO::AutoStride, -rowBytes);
        const bool closed = output->close();
        if (!written || !closed) why = "cannot write '" + path + "': " + output->geterror();
        return written && closed;
      },
      error);
}

}  // namespace

bool checkOutputPath(const std::string& path, std::string& error) {
  const std::string extension = extensionOf(path);
  const std::string name = std::filesystem::path(path).filename().string();
  if (extension.empty() && (name == ".png" || name == ".exr" || name == ".gif")) {
    error = "output '" + path + "' has no file name before its extension";
    return false;
  }
  if (extension != ".png" && extension != ".exr" && extension != ".gif") {
    error = "output '" + path + "' must end in .png, .exr or .gif";
    return false;
  }
  std::filesystem::path directory = std::filesystem::path(path).parent_path();
  if (directory.empty()) directory = ".";
  std::error_code code;
  if (!std::filesystem::is_directory(directory, code) || access(directory.c_str(), W_OK) != 0) {
    error = "output directory '" + directory.string() + "' does not exist or is not writable";
    return false;
  }
  if (std::filesystem::is_directory(path, code)) {
    error = "output '" + path + "' is a directory";
    return false;
  }
  return probeWritable(path, error);
}

bool writeExrChannels(const std::string& path, int width, int height,
                      const std::vector<std::string>& channelNames,
                      const std::vector<float>& interleaved, std::string& error,
                      const ImageAttributes& attributes) {
  if (!checkOutputPath(path, error)) return false;
  if (extensionOf(path) != ".exr") {
    error = "output '" + path + "' must end in .exr";
    return false;
  }
  if (channelNames.empty() || width <= 0 || height <= 0 ||
      interleaved.size() != channelNames.size() * size_t(width) * size_t(height)) {
    error = "cannot write '" + path + "': no pixels or channels";
    return false;
  }
  return writeFlipped(path, width, height, interleaved.data(), OIIO::TypeDesc::FLOAT, error,
                      &channelNames, attributes);
}

bool writeImage(const std::string& path, int width, int height, const std::vector<uint8_t>& rgba8,
                const std::vector<float>* linearRgba, std::string& error,
                const ImageAttributes& attributes) {
  if (!checkOutputPath(path, error)) return false;
  if (extensionOf(path) == ".exr" && linearRgba != nullptr) {
    return writeFlipped(path, width, height, linearRgba->data(), OIIO::TypeDesc::FLOAT, error,
                        nullptr, attributes);
  }
  return writeFlipped(path, width, height, rgba8.data(), OIIO::TypeDesc::UINT8, error, nullptr,
                      attributes);
}

double animationFps(double fps) {
  const double delay = std::max(1.0, std::round(100.0 / fps));  // centiseconds
  return 100.0 / delay;
}

bool writeAnimation(const std::string& path, int width, int height,
                    const std::vector<std::vector<uint8_t>>& frames, double fps,
                    std::string& error) {
  if (!checkOutputPath(path, error)) return false;
  if (extensionOf(path) != ".gif") {
    error = "an animation is written as .gif, got '" + path + "'";
    return false;
  }
  const size_t bytes = size_t(width) * size_t(height) * 4;
  if (frames.empty() || width <= 0 || height <= 0) {
    error = "cannot write '" + path + "': no frames";
    return false;
  }
  for (const std::vector<uint8_t>& frame : frames) {
    if (frame.size() != bytes) {
      error = "cannot write '" + path + "': a frame of the wrong size";
      return false;
    }
  }
  auto output = OIIO::ImageOutput::create(path);
  if (!output || !output->supports("multiimage")) {
    error = "cannot write '" + path + "' as an animation: " + OIIO::geterror();
    return false;
  }
  const int delay = int(std::lround(100.0 / animationFps(fps)));
  return writeThroughTemporary(
      path,
      [&](const std::string& temporary, std::string& why) {
        OIIO::ImageSpec spec(width, height, 4, OIIO::TypeDesc::UINT8);
        const int rate[2] = {100, delay};
        spec.attribute("FramesPerSecond", OIIO::TypeRational, rate);
        spec.attribute("oiio:Movie", 1);
        spec.attribute("oiio:LoopCount", 0);
        std::vector<OIIO::ImageSpec> specs(frames.size(), spec);
        const auto rowBytes = OIIO::stride_t(4 * width);
        for (size_t f = 0; f < frames.size(); ++f) {
          const bool opened =
              f == 0 ? output->open(temporary, int(specs.size()), specs.data())
                     : output->open(temporary, spec, OIIO::ImageOutput::AppendSubimage);
          // GL rows are bottom-up; images are top-down: start at the last row.
          const uint8_t* lastRow = frames[f].data() + size_t(height - 1) * size_t(rowBytes);
          if (!opened ||
              !output->write_image(OIIO::TypeDesc::UINT8, lastRow, OIIO::AutoStride, -rowBytes)) {
            why = "cannot write '" + path + "': " + output->geterror();
            output->close();
            return false;
          }
        }
        if (!output->close()) {
          why = "cannot write '" + path + "': " + output->geterror();
          return false;
        }
        return true;
      },
      error);
}

}  // namespace ocean
