#pragma once
// A surfaceless EGL context with OpenGL 4.5 core: all a headless host needs to drive the plugin
// (Mesa's llvmpipe is enough).
#include <string>

struct HeadlessGl {
  void* display = nullptr;
  void* context = nullptr;
  ~HeadlessGl();
};

// Creates and makes current; on failure returns false and says why in `error`.
bool createHeadlessGl(HeadlessGl& gl, std::string& error);
