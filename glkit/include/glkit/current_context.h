#pragma once
// Whether the calling thread has a current GL context. Every GL call through libepoxy without
// one aborts the process inside epoxy, and a library must never abort its host: entry points
// check this first and return an error instead.
namespace glkit {

// Asks EGL and GLX (whichever the process has loaded) without going through epoxy.
bool hasCurrentContext();

}  // namespace glkit
