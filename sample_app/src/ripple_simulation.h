#pragma once
// A GPU ripple simulation after Evan Wallace's webgl-water: a heightfield of water over a
// rectangle, stepped by the discrete 2D wave equation with damping (compute shaders, GL 4.5).
// Its output is a postfx::LocalWater texture: RG = slopes (dh/du, dh/dv, m/m) along the
// rectangle's local axes, B = height above the level (m), A = vertical velocity (m/s); texel
// column i at u = ((i + 0.5) / N - 0.5) size.x, row j at v = ((j + 0.5) / N - 0.5) size.y (row 0
// at v = -size.y / 2), as postfx/local_water.h reads it.
//
// The scheme: symplectic Euler, v += dt (c^2 laplacian(h) + nu laplacian(v)),
// v *= exp(-damping dt), h += dt v, with
// reflecting edges (a neighbour outside is the texel itself: no flux through the walls, so a step
// keeps the sum of heights). It is stable for c dt sqrt(1/dx^2 + 1/dz^2) <= 1; the step is chosen
// at half that (Courant number 0.5) and rounded to a whole number of steps per second, so the
// simulation's time is exact in steps. Heights are clamped to +-maxHeight and a non-finite texel
// is reset to rest, so no input, however extreme, leaves NaN or a blow-up behind.
#include <epoxy/gl.h>

#include <glm/glm.hpp>

#include <memory>
#include <string>
#include <vector>

#include <glkit/handle.h>
#include <glkit/program.h>

namespace ocean {

struct RippleDesc {
  // Texels along each side, [16, 2048]. 256 over 8 m resolves ripples of ~12 cm (4 texels).
  int resolution = 256;
  // The rectangle the texture covers, metres along local u and v, each in [0.05, 1e4].
  glm::dvec2 size{8.0, 8.0};
  // Wave speed, m/s, (0, 50]. The equation is non-dispersive: 1.2 m/s is the phase speed of
  // deep-water gravity waves ~0.9 m long (sqrt(g lambda / 2 pi)), the ripples a drop or a ball
  // makes in a pool; shallow-water waves 2 m deep would travel at 4.4 m/s.
  double waveSpeed = 1.2;
  // Exponential decay rate of the velocity, 1/s, [0, 100]. Only the velocity is damped, so a
  // ripple's amplitude decays at damping / 2: 0.4 halves it in ~3.5 s (webgl-water damps its
  // velocity by 0.995 a step).
  double damping = 0.4;
  // Heights are clamped to +-maxHeight (m), (0, 100]: the guard that keeps extreme drops finite.
  double maxHeight = 0.3;
  // Diffusion of the velocity, m^2/s, [0, 1e3] (the step shortens to keep it stable): damps a
  // wave of wavenumber k
  // at nu k^2 / 2, so with 1e-3 the grid's shortest waves (2 texels of 3 cm) die in ~0.2 s, a
  // 12 cm ripple in ~0.8 s, a 0.5 m wave lives ~13 s. Numerical, not water's own 1e-6:
  // webgl-water's scheme lets grid-scale noise (from drops and the ball's rim) ring on as sparkle.
  // Keeps the volume (its Laplacian sums to zero like the heights').
  double viscosity = 1e-3;
  // Width (m) of an absorbing band along the edges, [0, half the shorter side]; 0 (default):
  // reflecting walls (a pool). Inside it the velocity's damping rises quadratically to 20/s at
  // the edge (a sponge layer), so waves leave the rectangle instead of bouncing back: open water
  // (a wake's region) whose edge is not a wall. The band removes the water that reaches it, so
  // the step keeps the volume only without it.
  double absorbingEdge = 0.0;
};

class RippleSimulation {
 public:
  // Builds the programs and textures (the GL context must be current); nullptr with a message
  // naming the field when desc is out of range or GL fails.
  static std::unique_ptr<RippleSimulation> create(const RippleDesc& desc, std::string& error);
  RippleSimulation(const RippleSimulation&) = delete;
  RippleSimulation& operator=(const RippleSimulation&) = delete;

  const RippleDesc& desc() const { return desc_; }
  // The fixed physical time step (s) and its inverse; a step of the equation is exactly this.
  double stepSeconds() const { return 1.0 / double(stepsPerSecond_); }
  int stepsPerSecond() const { return stepsPerSecond_; }

  // Adds a raised-cosine bump, strength * (1 + cos(pi r / radius)) / 2 for r < radius, at
  // `centre` (local u, v, m; may lie outside, then only its part inside counts). radius is
  // clamped to [one texel, the longer side], strength to +-maxHeight; false (and nothing
  // changes) when any value is not finite.
  bool addDrop(glm::dvec2 centre, double radius, double strength);
  // A sphere moved from `from` to `to` (local u, height above the level, v; m): each column's
  // surface rises by the length of sphere below the level it gains (webgl-water's moveSphere,
  // with the physical sign and scale: water the sphere pushes out of a column raises its surface
  // by what it occupies). radius in (0, the longer side]; false when anything is not finite.
  bool moveSphere(glm::dvec3 from, glm::dvec3 to, double radius);
  // Runs `count` steps of stepSeconds() each (count clamped to [0, 100000]).
  void step(int count);
  // Back to rest: zero height and velocity everywhere (the texture is then exactly zero).
  void reset();
  // The rectangle moved by `texels` (whole texels along u, v): the water stays where it was in
  // the world, so texel (i, j) takes what was at (i + texels.x, j + texels.y), and what comes
  // in from outside is at rest (a camera- or object-following simulation, like a dynamic-wave
  // grid that scrolls). |texels| beyond the resolution clears it.
  void shift(glm::ivec2 texels);

  // GL_TEXTURE_2D, GL_RGBA32F, resolution x resolution, linear filter, clamp to edge: RG =
  // slopes, B = height, A = velocity. Owned by the simulation; valid until it is destroyed.
  // Brings it up to date first (one dispatch, only when a drop, sphere or step changed the
  // heights since): the operations above leave it stale, so that many of them cost one update.
  GLuint texture();
  // The texture's texels, row 0 first (tests, tools), up to date; reads back from the GPU.
  std::vector<glm::vec4> read();

 private:
  RippleSimulation() = default;
  void bindState(GLuint program);
  void updateSlopes();
  glm::vec2 texelSize() const;  // metres along u, v

  RippleDesc desc_;
  int stepsPerSecond_ = 0;
  glkit::Program stepProgram_, dropProgram_, sphereProgram_, slopeProgram_, shiftProgram_;
  glkit::Texture state_[2];  // RG32F: height (m), velocity (m/s)
  int current_ = 0;
  bool stale_ = false;     // the output lags the state
  glkit::Texture output_;  // RGBA32F
};

}  // namespace ocean
