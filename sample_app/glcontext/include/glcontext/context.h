#pragma once
// GL contexts for the sample app and the tests: a headless EGL (surfaceless) OpenGL 4.5 core
// context, and a KHR_debug message log the caller reads (nothing is printed here).
#include <epoxy/gl.h>

#include <memory>
#include <mutex>
#include <string>
#include <vector>

namespace glcontext {

struct DebugMessage {
  GLenum source, type, severity;
  GLuint id;
  std::string text;
};

// Collects KHR_debug messages from the context it is installed on. Thread-safe.
class DebugLog {
 public:
  // Installs the callback on the current context (synchronous output, so a message arrives
  // inside the call that caused it).
  void install();
  std::vector<DebugMessage> take();  // returns and clears what was collected
  size_t errorCount() const;         // GL_DEBUG_TYPE_ERROR messages since the last take()

 private:
  static void GLAPIENTRY callback(GLenum source, GLenum type, GLuint id, GLenum severity,
                                  GLsizei length, const GLchar* message, const void* user);
  mutable std::mutex mutex_;
  std::vector<DebugMessage> messages_;
};

class HeadlessContext {
 public:
  // Creates and makes current an EGL surfaceless OpenGL 4.5 core context (debug context when
  // `debug`). Returns null and sets `error` on failure.
  static std::unique_ptr<HeadlessContext> create(bool debug, std::string& error);
  ~HeadlessContext();
  HeadlessContext(const HeadlessContext&) = delete;
  HeadlessContext& operator=(const HeadlessContext&) = delete;

  void makeCurrent();
  DebugLog& debugLog() { return log_; }
  std::string renderer() const;  // GL_RENDERER, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)"

 private:
  HeadlessContext() = default;
  void* display_ = nullptr;
  void* context_ = nullptr;
  DebugLog log_;
};

std::string debugMessageString(const DebugMessage& message);

}  // namespace glcontext
