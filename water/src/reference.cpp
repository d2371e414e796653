#include <postfx/water/reference.h>

#include <array>
#include <cmath>
#include <numbers>
#include <utility>

namespace postfx::water {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

// The eight real fields the textures are built from, in this order.
enum Field { H, Hx, Hz, Dx, Dz, Dxx, Dzz, Dxz, FieldCount };

void inverseFft2d(std::vector<std::complex<double>>& grid, int n) {
  for (int row = 0; row < n; ++row) inverseFft(grid.data() + static_cast<size_t>(row) * n, n, 1);
  for (int column = 0; column < n; ++column) inverseFft(grid.data() + column, n, n);
}

}  // namespace

void inverseFft(std::complex<double>* data, int count, int stride) {
  auto at = [&](int i) -> std::complex<double>& {
    return data[static_cast<ptrdiff_t>(i) * stride];
  };
  for (int i = 1, j = 0; i < count; ++i) {
    int bit = count >> 1;
    for (; j & bit; bit >>= 1) j ^= bit;
    j ^= bit;
    if (i < j) std::swap(at(i), at(j));
  }
  for (int length = 2; length <= count; length <<= 1) {
    const int half = length / 2;
    for (int start = 0; start < count; start += length) {
      for (int p = 0; p < half; ++p) {
        // Twiddles from the angle each time (not by repeated multiplication) to keep error flat.
        const std::complex<double> w = std::polar(1.0, kTwoPi * p / length);
        const std::complex<double> even = at(start + p);
        const std::complex<double> odd = at(start + p + half) * w;
        at(start + p) = even + odd;
        at(start + p + half) = even - odd;
      }
    }
  }
}

SurfaceFields evaluateReference(const InitialSpectrum& spectrum, const OceanDesc& desc, int cascade,
                                double timeSeconds) {
  const int n = spectrum.resolution;
  const size_t count = static_cast<size_t>(n) * n;
  const uint32_t phase = loopPhase(timeSeconds, desc.loopPeriod);
  const double dk = kTwoPi / desc.tileSize[cascade];
  const double chop = desc.choppiness;
  const std::complex<double> i1(0.0, 1.0);

  std::array<std::vector<std::complex<double>>, FieldCount> grids;
  for (auto& grid : grids) grid.assign(count, {});
  for (int m = 0; m < n; ++m) {
    for (int i = 0; i < n; ++i) {
      const size_t mode = spectrum.index(cascade, i, m);
      // The same integer phase the GPU computes: exact modulo 2^32, then centred on 0.
      const uint32_t units = spectrum.cycles[mode] * phase;
      const double angle = static_cast<double>(static_cast<int32_t>(units)) * kTwoPi * 0x1.0p-32;
      const std::complex<double> rotation = std::polar(1.0, angle);
      const std::complex<double> h =
          spectrum.a[mode] * std::conj(rotation) + spectrum.b[mode] * rotation;
      const double kx = signedFrequency(i, n) * dk, kz = signedFrequency(m, n) * dk;
      const double k = std::hypot(kx, kz);
      const double inv = k > 0.0 ? 1.0 / k : 0.0;
      const size_t at = static_cast<size_t>(m) * n + i;
      grids[H][at] = h;
      grids[Hx][at] = i1 * kx * h;
      grids[Hz][at] = i1 * kz * h;
      // Choppy displacement D = i lambda k/|k| h pulls points toward crests (sharp crests).
      grids[Dx][at] = i1 * chop * kx * inv * h;
      grids[Dz][at] = i1 * chop * kz * inv * h;
      grids[Dxx][at] = -chop * kx * kx * inv * h;
      grids[Dzz][at] = -chop * kz * kz * inv * h;
      grids[Dxz][at] = -chop * kx * kz * inv * h;
    }
  }
  for (auto& grid : grids) inverseFft2d(grid, n);

  SurfaceFields fields;
  fields.slope.resize(count);
  fields.displacement.resize(count);
  for (size_t t = 0; t < count; ++t) {
    const double dxx = grids[Dxx][t].real(), dzz = grids[Dzz][t].real();
    const double dxz = grids[Dxz][t].real();
    const double jacobian = (1.0 + dxx) * (1.0 + dzz) - dxz * dxz;
    const double h = grids[H][t].real();
    fields.slope[t] = {grids[Hx][t].real(), grids[Hz][t].real(), h, jacobian};
    fields.displacement[t] = {grids[Dx][t].real(), h, grids[Dz][t].real(), 0.0};
  }
  return fields;
}

}  // namespace postfx::water
