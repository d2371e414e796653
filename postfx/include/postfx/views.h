#pragma once
// Several views in one frame: split-screen, a stereo pair, the six faces of a cube-map probe, a
// minimap. One dispatch() call carries the frame (sun, water, settings, casters: FrameDesc) and
// its views (camera, G-buffer, target, viewport: ViewDesc); the work that does not depend on the
// camera runs once for all of them:
//   per frame, shared:  Pass::TileIrradiance (the seabed light field, computed over the water's
//                       tile, not the screen), the object caustics' maps (the sun's caster maps,
//                       splats and temporal history, and each local light's), their timers;
//   per view:           Pass::WavefrontAreaRatio and Pass::ReflectedCaustics (their windows
//                       follow the view's camera),
//                       Pass::Floor, Pass::Caustics, Pass::GodRays (with the god-ray grid's
//                       pivot, which follows the camera), the object caustics' composite into the
//                       view's target, the view's raw output and reduced-resolution textures,
//                       and its timers.
// Each view's image is bit-identical to what a context of its own would draw for that camera
// after the same frames: nothing a view keeps (its pivot, its textures) is read by another, and
// the shared work is the same whatever the camera.
//
//   postfx::View* left = nullptr;  postfx::createView(*fx, left);      // once, like create()
//   postfx::ViewDesc views[2] = {{left, depthL, normalL, albedoL, hdrL, cameraL},
//                                {right, depthR, normalR, albedoR, hdrR, cameraR}};
//   postfx::dispatch(*fx, frame, views, 2);  // frame's own camera, G-buffer, target: not read
//   postfx::stats(*left).pass(postfx::Pass::Caustics) ... postfx::stats(*fx) for the shared ones
//   postfx::destroyView(*fx, left);
//
// Stereo: the caustics are a function of the world point (every lookup is world-anchored) and
// the god rays sample world-snapped planes, so both eyes see the same pattern. Leave
// GodRaySettings::dither off for stereo: its 4x4 phase is fixed on the screen, so it differs
// between the eyes at the same world point.
#include <postfx/postfx.h>

namespace postfx {

struct View;  // opaque: what one view keeps between frames

inline constexpr int kMaxViews = 16;  // views one dispatch() may carry

// A rectangle of the view's target, in pixels from its lower-left corner (GL's window
// convention). All four 0 (the default): the whole target ({5, 0, 0, 0} is refused: a size of
// 0 x 0 means the whole target only at the origin). Otherwise both sizes > 0 and the
// rectangle inside the target; the view's G-buffer is read at the same pixels (one G-buffer the
// size of the target, shared by split-screen views, or one per view) and nothing outside the
// rectangle is written. Views that share a target must not overlap.
struct Viewport {
  int x = 0, y = 0;
  int width = 0, height = 0;
};

struct ViewDesc {
  // From createView() on the same context, not destroyed; at most once per dispatch. Any other
  // pointer is refused without being read.
  View* view = nullptr;
  // As FrameDesc's fields of the same names (postfx/frame_desc.h): all the target's size.
  TextureRef depth;
  TextureRef normal;
  TextureRef albedo;
  TextureRef target;
  Camera camera;        // camera.projection maps the view to its viewport (aspect = its w / h)
  Viewport viewport{};  // default: the whole target
  // The view's own sun shadow map (Feature::ShadowMask; a cascade fitted to its camera), read
  // during dispatch() only; null: FrameDesc::shadow. Only the view's passes read it: the object
  // caustics' receivers (FrameDesc::objectCaustics) are the frame's, and must cover every view.
  const SunShadowMap* shadow = nullptr;
};

// A view's state (god-ray pivot, timers, its raw output and reduced-resolution textures, made on
// first use). NoContext without a current GL context; out is then null.
Result createView(Context& context, View*& out) noexcept;
// Frees the view's GPU memory and timers (current GL context required; without one they are
// leaked rather than abort). Null, or a view of another context, is ignored. destroy() frees the
// views still alive with their context.
void destroyView(Context& context, View* view) noexcept;

// Adds this frame's light into each view's target, the shared work once. `frame` gives everything
// but its depth, normal, albedo, target and camera, which each ViewDesc gives instead. Every view
// is validated (as dispatch(context, frame) validates its frame, and: viewCount in [1, kMaxViews],
// each view non-null, of this context, listed once, its viewport inside its target, no two views
// of one target overlapping) before any GL work: a refused frame draws into no view. A message
// about one view begins with "views[i]: ".
Result dispatch(Context& context, const FrameDesc& frame, const ViewDesc* views,
                int viewCount) noexcept;

// The view's own passes (Pass::WavefrontAreaRatio, Floor, Caustics, GodRays, ReflectedCaustics;
// the others read present = false), updated by each dispatch that carries the view. The shared
// passes (Pass::TileIrradiance, Pass::ObjectCaustics with every view's composite, the local lights)
// are timed once per frame in stats(context), with clampedFluxFraction.
const FrameStats& stats(const View& view) noexcept;

}  // namespace postfx
