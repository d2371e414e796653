#pragma once
// The animated water surface: a multi-cascade Tessendorf FFT ocean evaluated on the GPU with
// compute shaders every update().
//
// Texture contract (other modules rely on it exactly):
// - World convention: y is up; the surface is y = level + h(x, z). The water origin is the world
//   point the tiles repeat from (the host reduces positions modulo the tile size in double).
// - slopeTexture(): GL_TEXTURE_2D_ARRAY, GL_RGBA16F, layer c = cascade c, N x N, mipmapped,
//   GL_LINEAR_MIPMAP_LINEAR, GL_REPEAT. Texel = (dh/dx, dh/dz, h [m], J), J the Jacobian
//   determinant of the choppy horizontal map (1 undisturbed, < 0 where the surface folds).
//   Slopes are derivatives with respect to the undisplaced grid position (Tessendorf's
//   Lagrangian form); the surface normal is normalize(-sum_c dh/dx_c, 1, -sum_c dh/dz_c).
// - displacementTexture(): same layout, texel = (Dx [m], h [m], Dz [m], 0); the displaced
//   surface point of grid point (x, z) is (x + sum Dx, level + sum h, z + sum Dz).
// - Texel (i, j) centre holds the fields at world (x, z) = ((i + 0.5), (j + 0.5)) * L_c / N, so
//   sampling with uv = (x, z) / L_c is exact at texel centres; i runs along x (u), j along z (v).
// - Sum the cascades to get the sea: they own disjoint wavenumber bands.
#include <epoxy/gl.h>

#include <memory>
#include <string>
#include <vector>

#include <postfx/water/ocean_desc.h>
#include <postfx/water/result.h>
#include <postfx/water/spectrum.h>

namespace postfx::water {

class Ocean {
 public:
  // Validates `desc` against its ranges and the GL limits, compiles the shaders and allocates the
  // textures. Needs a current GL 4.5 context. On failure returns the error, sets `error`, leaves
  // `out` null and holds no GL object. Reads glGetError() once after allocating (a pending host
  // error would be reported as GlError), so call it with the host's errors drained.
  static Result create(const OceanDesc& desc, std::unique_ptr<Ocean>& out, std::string& error);
  ~Ocean();
  Ocean(const Ocean&) = delete;
  Ocean& operator=(const Ocean&) = delete;

  // Records the GPU work that brings both textures (all mip levels) to `timeSeconds`. Any finite
  // time is fine (it is reduced modulo loopPeriod in double). NaN or infinite time returns
  // InvalidArgument and changes nothing. Leaves the bound program, image units and shader
  // storage bindings as it found them; binds no texture unit.
  Result update(double timeSeconds, std::string& error);
  Result update(double timeSeconds);

  GLuint slopeTexture() const { return slope_; }
  GLuint displacementTexture() const { return displacement_; }
  int resolution() const { return desc_.resolution; }
  int cascadeCount() const { return desc_.cascadeCount; }
  double tileSize(int cascade) const { return desc_.tileSize[cascade]; }
  const OceanDesc& desc() const { return desc_; }
  // Expected statistics of each cascade's waves (for postfx::WaterSurface's cascade fields).
  const CascadeWaveStats& waveStats(int cascade) const { return waveStats_[cascade]; }
  // GPU memory the module allocated, bytes (buffers and textures with all mip levels).
  size_t gpuBytes() const { return gpuBytes_; }

 private:
  explicit Ocean(const OceanDesc& desc) : desc_(desc) {}
  Result initialise(std::string& error);

  OceanDesc desc_;
  std::vector<CascadeWaveStats> waveStats_;
  GLuint spectrumBuffer_ = 0;  // static per-mode amplitudes and cycle counts
  GLuint scratch_ = 0;         // RGBA32F array: row-transformed signals, 2 layers per cascade
  GLuint slope_ = 0, displacement_ = 0;
  GLuint rowProgram_ = 0, columnProgram_ = 0;
  size_t gpuBytes_ = 0;
};

}  // namespace postfx::water
