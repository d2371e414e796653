#pragma once
// What third-party libraries print (private to the loader). libpng, reached through
// OpenImageIO, reports a damaged image on the process's stderr with its default handlers
// ("libpng error: Invalid IHDR data"), and Draco or tinygltf could do the same; the loader
// never prints, so while one of them runs, file descriptor 2 is pointed at a memory file and
// what arrived there is handed back to be named in the loader's own message.
//
// Not thread-safe: descriptor 2 is the process's. The sample loads its models on one thread
// before any other starts; a line another thread writes meanwhile would be captured too.

#include <string>

namespace ocean_scene::gltf {

class StderrCapture {
 public:
  StderrCapture();   // flushes stderr and redirects descriptor 2 (nothing happens if it cannot)
  ~StderrCapture();  // restores descriptor 2
  StderrCapture(const StderrCapture&) = delete;
  StderrCapture& operator=(const StderrCapture&) = delete;

  // Restores descriptor 2 and returns what was written meanwhile, as one line (safeOneLine,
  // at most kMaxQuotedChars characters); "" when nothing was.
  std::string take();

 private:
  int saved_ = -1;    // the descriptor 2 to restore
  int captive_ = -1;  // the memory file that stands in for it
};

}  // namespace ocean_scene::gltf
