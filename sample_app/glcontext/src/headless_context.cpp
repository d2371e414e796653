#include <epoxy/egl.h>

#include <glcontext/context.h>

namespace glcontext {

namespace {
// The contexts alive on the process's one display: eglTerminate invalidates every context on a
// display, so only the last one to close may terminate it (a report's sweep opens and closes
// sessions of its own inside the command's).
int liveContexts = 0;

void terminateUnlessInUse(EGLDisplay display) {
  if (liveContexts == 0) eglTerminate(display);
}
}  // namespace

std::unique_ptr<HeadlessContext> HeadlessContext::create(bool debug, std::string& error) {
  EGLDisplay display = EGL_NO_DISPLAY;
  if (epoxy_has_egl_extension(EGL_NO_DISPLAY, "EGL_MESA_platform_surfaceless")) {
    display = eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
  }
  if (display == EGL_NO_DISPLAY) {
    // A vendor driver (e.g. NVIDIA) offers a device or default display instead.
    display = eglGetDisplay(EGL_DEFAULT_DISPLAY);
  }
  EGLint major = 0, minor = 0;
  if (display == EGL_NO_DISPLAY || eglInitialize(display, &major, &minor) != EGL_TRUE) {
    error = "EGL: no display could be initialized (is Mesa's libegl-mesa0 installed?)";
    return nullptr;
  }
  if (eglBindAPI(EGL_OPENGL_API) != EGL_TRUE) {
    error = "EGL: desktop OpenGL API not available";
    terminateUnlessInUse(display);
    return nullptr;
  }
  const EGLint configAttributes[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
  EGLConfig config = nullptr;
  EGLint configCount = 0;
  eglChooseConfig(display, configAttributes, &config, 1, &configCount);
  const EGLint contextAttributes[] = {EGL_CONTEXT_MAJOR_VERSION,
                                      4,
                                      EGL_CONTEXT_MINOR_VERSION,
                                      5,
                                      EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                      EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                      EGL_CONTEXT_OPENGL_DEBUG,
                                      debug ? EGL_TRUE : EGL_FALSE,
                                      EGL_NONE};
  EGLContext context = eglCreateContext(display, configCount > 0 ? config : EGL_NO_CONFIG_KHR,
                                        EGL_NO_CONTEXT, contextAttributes);
  if (context == EGL_NO_CONTEXT) {
    error = "EGL: could not create an OpenGL 4.5 core context";
    terminateUnlessInUse(display);
    return nullptr;
  }
  if (eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context) != EGL_TRUE) {
    error = "EGL: could not make the surfaceless context current";
    eglDestroyContext(display, context);
    terminateUnlessInUse(display);
    return nullptr;
  }
  std::unique_ptr<HeadlessContext> result(new HeadlessContext());
  result->display_ = display;
  result->context_ = context;
  ++liveContexts;
  if (debug) result->log_.install();
  return result;
}

HeadlessContext::~HeadlessContext() {
  auto* display = static_cast<EGLDisplay>(display_);
  eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  eglDestroyContext(display, static_cast<EGLContext>(context_));
  --liveContexts;
  terminateUnlessInUse(display);
}

void HeadlessContext::makeCurrent() {
  eglMakeCurrent(static_cast<EGLDisplay>(display_), EGL_NO_SURFACE, EGL_NO_SURFACE,
                 static_cast<EGLContext>(context_));
}

std::string HeadlessContext::renderer() const {
  const auto* text = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  return text != nullptr ? text : "unknown";
}

}  // namespace glcontext
