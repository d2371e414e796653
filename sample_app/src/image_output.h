#pragma once
// Writes images through OpenImageIO. A failed write leaves no file behind: the image goes to a
// temporary name in the same directory and is renamed into place only when complete.
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace ocean {

// String attributes written into the file's header (e.g. "ocean:objectCaustics" = "plugin"):
// what produced the pixels, so that `compare` can refuse frames that do not belong together.
using ImageAttributes = std::vector<std::pair<std::string, std::string>>;

// "ocean:exposure": the linear exposure the frame was tone mapped with (9 significant digits),
// so that compare's side by side shows it as the sample did; exposureFromAttribute reads it
// back, 1 for a file without it or with a value that is not a positive finite number.
std::string exposureAttribute(float exposure);
float exposureFromAttribute(const std::string& text);

// RGBA8 pixels, bottom row first (GL order); `.png` (or any 8-bit format OIIO knows) by
// extension; `.exr` gets the linear float buffer instead when one is given.
bool writeImage(const std::string& path, int width, int height, const std::vector<uint8_t>& rgba8,
                const std::vector<float>* linearRgba, std::string& error,
                const ImageAttributes& attributes = {});

// An EXR of float channels with the given names (e.g. R, G, B, A, then extra ones), pixels
// interleaved, bottom row first (GL order).
bool writeExrChannels(const std::string& path, int width, int height,
                      const std::vector<std::string>& channelNames,
                      const std::vector<float>& interleaved, std::string& error,
                      const ImageAttributes& attributes = {});

// An animated GIF (`path` ends in .gif) of `frames`, each RGBA8 bottom row first, shown at
// `fps` frames per second and looping forever. GIF stores each frame's delay in whole
// hundredths of a second: the file holds animationFps(fps).
bool writeAnimation(const std::string& path, int width, int height,
                    const std::vector<std::vector<uint8_t>>& frames, double fps,
                    std::string& error);
// The rate a GIF stores for `fps`: 100 / round(100 / fps), its delays being whole centiseconds.
double animationFps(double fps);

// Checks the output path before any rendering: known extension (.png, .exr, or .gif for an
// animation), writable directory.
bool checkOutputPath(const std::string& path, std::string& error);

}  // namespace ocean
