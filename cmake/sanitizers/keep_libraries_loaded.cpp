// Sanitizer builds only (POSTFX_SANITIZE): dlclose() does nothing, so the GL driver Mesa loads
// stays mapped until exit. LeakSanitizer checks at exit; a leak inside a library already
// unloaded has no module name to suppress it by, and Mesa's driver leaks by design at exit.
// Defined in the executable (postfx_sanitizer_runtime), it takes precedence over libc's for
// every caller.
extern "C" int dlclose(void* /*handle*/) {
  return 0;
}
