#pragma once
// Where a host's sun shadow map (or receiver map) looks from, read off its world-to-clip
// matrix: the plugin moves points toward that light by a distance in metres, so it must know
// the direction without the host saying it twice.
#include <glm/glm.hpp>

#include <postfx/conventions.h>

namespace postfx::detail {

struct ShadowLight {
  bool perspective = false;
  glm::dvec3 vector{0.0, 1.0, 0.0};  // orthographic: unit vector toward the light; perspective:
                                     // the light's position (the matrix's eye), same space
};

// A perspective map (clip w depends on the position) looks from its eye, where clip x, y and w
// vanish. An orthographic one looks along the direction that keeps clip x and y, oriented to
// growing clip z: away from the light in the forward conventions, toward it in reverse-Z.
// Needs no inverse: a map of constant depth (a test's flat occluder) still has a direction.
ShadowLight shadowLight(const glm::dmat4& worldToLightClip, DepthConvention convention);

// World size of one texel of a map `texels` wide, per unit of clip w, along the matrix's clip x
// and y rows: 2 / (|row| * texels) before the division by the size (so 2 / |row|).
glm::dvec2 clipUnitsToMetres(const glm::dmat4& worldToLightClip);

}  // namespace postfx::detail
