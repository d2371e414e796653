#include "pattern_comparison.h"

#include "caustic_comparison.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>

namespace ocean::reference {
namespace {

using Complex = std::complex<double>;

// In-place radix-2 FFT of `n` values spaced `stride` apart (n a power of two).
void fft(Complex* data, int n, int stride) {
  for (int i = 1, j = 0; i < n; ++i) {
    int bit = n >> 1;
    for (; j & bit; bit >>= 1) j ^= bit;
    j ^= bit;
    if (i < j) std::swap(data[i * stride], data[j * stride]);
  }
  for (int len = 2; len <= n; len <<= 1) {
    const double angle = -2.0 * std::numbers::pi / len;
    const Complex step(std::cos(angle), std::sin(angle));
    for (int start = 0; start < n; start += len) {
      Complex w(1.0, 0.0);
      for (int k = 0; k < len / 2; ++k) {
        Complex& a = data[(start + k) * stride];
        Complex& b = data[(start + k + len / 2) * stride];
        const Complex t = w * b;
        b = a - t;
        a += t;
        w *= step;
      }
    }
  }
}

// Power spectrum of one pattern over the patch: the pattern minus its mean over the patch's
// compared pixels (others take the mean), Hann-windowed. Index ky * size + kx.
std::vector<double> patchPower(const std::vector<double>& pattern,
                               const std::vector<std::uint8_t>& compared, int width, int x0, int y0,
                               int size) {
  double sum = 0.0;
  size_t count = 0;
  for (int y = 0; y < size; ++y) {
    for (int x = 0; x < size; ++x) {
      const size_t i = size_t(y0 + y) * size_t(width) + size_t(x0 + x);
      if (!compared[i]) continue;
      sum += pattern[i];
      ++count;
    }
  }
  const double mean = count > 0 ? sum / double(count) : 0.0;
  std::vector<Complex> grid(size_t(size) * size_t(size));
  for (int y = 0; y < size; ++y) {
    const double wy = 0.5 - 0.5 * std::cos(2.0 * std::numbers::pi * (y + 0.5) / size);
    for (int x = 0; x < size; ++x) {
      const double wx = 0.5 - 0.5 * std::cos(2.0 * std::numbers::pi * (x + 0.5) / size);
      const size_t i = size_t(y0 + y) * size_t(width) + size_t(x0 + x);
      const double v = compared[i] ? pattern[i] - mean : 0.0;
      grid[size_t(y) * size_t(size) + size_t(x)] = wx * wy * v;
    }
  }
  for (int y = 0; y < size; ++y) fft(&grid[size_t(y) * size_t(size)], size, 1);
  for (int x = 0; x < size; ++x) fft(&grid[size_t(x)], size, size);
  std::vector<double> power(grid.size());
  for (size_t i = 0; i < grid.size(); ++i) power[i] = std::norm(grid[i]);
  return power;
}

// Radius of frequency (kx, ky) in cycles per patch.
double frequencyRadius(int kx, int ky, int size) {
  const int fx = kx < size / 2 ? kx : kx - size;
  const int fy = ky < size / 2 ? ky : ky - size;
  return std::sqrt(double(fx) * fx + double(fy) * fy);
}

// Power summed over bands of radius [size / 2^((b + 1) / perOctave), size / 2^(b / perOctave)):
// band b holds periods of 2^(b / perOctave + 1)... measured from the Nyquist period of 2 pixels.
std::vector<double> bandPowers(const std::vector<double>& power, int size, int perOctave,
                               int bands) {
  std::vector<double> sums(size_t(bands), 0.0);
  for (int ky = 0; ky < size; ++ky) {
    for (int kx = 0; kx < size; ++kx) {
      const double r = frequencyRadius(kx, ky, size);
      if (!(r > 0.0) || r > 0.5 * size) continue;
      // Period in pixels: size / r, >= 2; band = floor(perOctave * log2(period / 2)).
      const int band = int(std::floor(perOctave * std::log2(double(size) / r / 2.0)));
      if (band >= 0 && band < bands) sums[size_t(band)] += power[size_t(ky) * size_t(size) + kx];
    }
  }
  return sums;
}

double percentile99(std::vector<double> values) {
  if (values.empty()) return 0.0;
  const size_t k = (values.size() - 1) * 99 / 100;
  std::nth_element(values.begin(), values.begin() + long(k), values.end());
  return values[k];
}

}  // namespace

PatternSpectrum comparePatternSpectra(const std::vector<double>& method,
                                      const std::vector<double>& reference,
                                      const std::vector<std::uint8_t>& compared, int width,
                                      int height) {
  PatternSpectrum s;
  // Summed-area table of the compared pixels: the fraction of any square in O(1).
  std::vector<long> area(size_t(width + 1) * size_t(height + 1), 0);
  for (int y = 0; y < height; ++y) {
    long row = 0;
    for (int x = 0; x < width; ++x) {
      row += compared[size_t(y) * size_t(width) + size_t(x)] ? 1 : 0;
      area[size_t(y + 1) * size_t(width + 1) + size_t(x + 1)] =
          area[size_t(y) * size_t(width + 1) + size_t(x + 1)] + row;
    }
  }
  auto inside = [&](int x, int y, int size) {
    auto at = [&](int ax, int ay) { return area[size_t(ay) * size_t(width + 1) + size_t(ax)]; };
    return at(x + size, y + size) - at(x, y + size) - at(x + size, y) + at(x, y);
  };
  for (int size = 256; size >= 32 && s.patchSize == 0; size /= 2) {
    if (size > width || size > height) continue;
    const int step = std::max(size / 8, 1);
    long best = -1;
    for (int y = 0; y + size <= height; y += step) {
      for (int x = 0; x + size <= width; x += step) {
        const long n = inside(x, y, size);
        if (n > best) {
          best = n;
          s.patchX = x;
          s.patchY = y;
        }
      }
    }
    // Almost all compared: the few others (a pebble's shadow) take the mean.
    if (best >= long(0.97 * double(size) * size)) s.patchSize = size;
  }
  if (s.patchSize == 0) return s;
  const int size = s.patchSize;
  const std::vector<double> pm = patchPower(method, compared, width, s.patchX, s.patchY, size);
  const std::vector<double> pr = patchPower(reference, compared, width, s.patchX, s.patchY, size);
  const int octaves = int(std::log2(double(size))) - 1;  // periods 2 .. size pixels
  const std::vector<double> om = bandPowers(pm, size, 1, octaves);
  const std::vector<double> orr = bandPowers(pr, size, 1, octaves);
  double logSum = 0.0;
  int logCount = 0;
  for (int b = octaves - 1; b >= 0; --b) {  // coarsest first
    SpectrumOctave o;
    o.minPeriodPixels = 2.0 * std::exp2(b);
    o.maxPeriodPixels = 2.0 * std::exp2(b + 1);
    o.methodPower = om[size_t(b)];
    o.referencePower = orr[size_t(b)];
    o.ratio = o.referencePower > 0.0 ? o.methodPower / o.referencePower : 0.0;
    s.octaves.push_back(o);
    if (o.minPeriodPixels >= 4.0 && o.maxPeriodPixels <= 64.0 && o.ratio > 0.0) {
      logSum += std::log(o.ratio);
      ++logCount;
    }
  }
  s.fineRatio = logCount > 0 ? std::exp(logSum / logCount) : 0.0;
  s.verdict = s.fineRatio < 0.7 ? "too soft" : (s.fineRatio > 1.4 ? "too sharp" : "as sharp");

  constexpr int kPerOctave = 4;
  const int bands = octaves * kPerOctave;
  const std::vector<double> qm = bandPowers(pm, size, kPerOctave, bands);
  const std::vector<double> qr = bandPowers(pr, size, kPerOctave, bands);
  std::vector<double> ratio(size_t(bands), 0.0);
  for (int b = 0; b < bands; ++b)
    ratio[size_t(b)] =
        qr[size_t(b)] > 0.0 && qm[size_t(b)] > 0.0 ? qm[size_t(b)] / qr[size_t(b)] : 0.0;
  s.peak = 1.0;
  for (int b = kPerOctave; b < bands; ++b) {  // periods of 4 pixels and more
    if (!(ratio[size_t(b)] > 0.0)) continue;
    double around = 0.0;
    int n = 0;
    for (int d = -kPerOctave; d <= kPerOctave; ++d) {
      const int k = b + d;
      if (d == 0 || std::abs(d) == 1 || k < kPerOctave || k >= bands || !(ratio[size_t(k)] > 0.0))
        continue;
      around += std::log(ratio[size_t(k)]);
      ++n;
    }
    if (n < 2) continue;
    const double peak = ratio[size_t(b)] / std::exp(around / n);
    if (peak > s.peak) {
      s.peak = peak;
      s.peakPeriodPixels = 2.0 * std::exp2((b + 0.5) / kPerOctave);
    }
  }
  return s;
}

PatternComparison comparePatterns(const std::vector<double>& method,
                                  const std::vector<double>& reference,
                                  const std::vector<double>& flat,
                                  const std::vector<std::uint8_t>& mask, int width, int height) {
  PatternComparison c;
  const size_t n = size_t(width) * size_t(height);
  if (method.size() < n || reference.size() < n || flat.size() < n || mask.size() < n) return c;
  std::vector<double> flats;
  for (size_t i = 0; i < n; ++i)
    if (mask[i] && flat[i] > 0.0 && std::isfinite(flat[i])) flats.push_back(flat[i]);
  if (flats.empty()) return c;
  std::nth_element(flats.begin(), flats.begin() + long(flats.size() / 2), flats.end());
  c.flatMedian = flats[flats.size() / 2];
  const double floor = 0.25 * c.flatMedian;
  c.methodPattern.assign(n, 0.0);
  c.referencePattern.assign(n, 0.0);
  c.compared.assign(n, 0);
  std::vector<double> pm, pr;
  for (size_t i = 0; i < n; ++i) {
    if (!mask[i] || !(flat[i] >= floor)) continue;
    const double m = method[i] / flat[i], r = reference[i] / flat[i];
    if (!std::isfinite(m) || !std::isfinite(r)) continue;
    c.methodPattern[i] = m;
    c.referencePattern[i] = r;
    c.compared[i] = 1;
    pm.push_back(m);
    pr.push_back(r);
  }
  c.pixels = pm.size();
  if (c.pixels == 0) return c;
  const CausticComparison stats =
      compareAddedLight(c.methodPattern, c.referencePattern, c.compared);
  c.methodMean = stats.methodMean;
  c.referenceMean = stats.referenceMean;
  c.relativeRmse = stats.relativeRmse;
  c.correlation = stats.correlation;
  c.methodContrast = c.methodMean != 0.0 ? stats.methodStd / c.methodMean : 0.0;
  c.referenceContrast = c.referenceMean != 0.0 ? stats.referenceStd / c.referenceMean : 0.0;
  c.methodP99 = percentile99(pm);
  c.referenceP99 = percentile99(pr);
  c.spectrum =
      comparePatternSpectra(c.methodPattern, c.referencePattern, c.compared, width, height);
  return c;
}

}  // namespace ocean::reference
