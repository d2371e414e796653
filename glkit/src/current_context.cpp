#include <glkit/current_context.h>

#include <dlfcn.h>

namespace glkit {
namespace {

// Calls `function` ("...GetCurrentContext") in `library` if the process has already loaded it.
// RTLD_NOLOAD: a library nobody loaded cannot hold a current context, so it is never loaded
// here. (epoxy dlopens libEGL/libGL privately, so RTLD_DEFAULT lookups would miss them.)
bool currentIn(const char* library, const char* function) {
  void* handle = dlopen(library, RTLD_LAZY | RTLD_NOLOAD);
  if (handle == nullptr) return false;
  bool current = false;
  if (void* symbol = dlsym(handle, function)) {
    current = reinterpret_cast<void* (*)()>(symbol)() != nullptr;
  }
  dlclose(handle);
  return current;
}

}  // namespace

bool hasCurrentContext() {
  return currentIn("libEGL.so.1", "eglGetCurrentContext") ||
         currentIn("libGLX.so.0", "glXGetCurrentContext") ||
         currentIn("libGL.so.1", "glXGetCurrentContext");
}

}  // namespace glkit
