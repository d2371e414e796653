// What the volume caustics' vertex and fragment steps share: the rays' segments (written by
// object_caustics_trace.comp after the landings) and the camera's frame, camera-relative.
#ifndef POSTFX_VOLUME_CAUSTICS_COMMON_GLSL
#define POSTFX_VOLUME_CAUSTICS_COMMON_GLSL
#include "shared/common.h"
#include "postfx/object_caustics/postfx_object_caustics_block.h"

// Layer of a channel's segment start (then end, then power): after every channel's landings.
int segmentLayer(int channel) {
  return (u.receiver.w > 0.5 ? 6 : 2) + 3 * channel;
}

// The water level relative to the camera (m).
float cameraRelativeLevel() {
  return u.cameraOffset.w - u.cameraOffset.y;
}

// Camera-relative world -> view space (viewToWorld is a rotation).
vec3 worldToView(vec3 p) {
  return transpose(mat3(u.viewToWorld)) * p;
}

#endif
