// The derivations behind the continuity limits. Notation: h = 1e-4 the step; omega = exp(-tau
// a^2) with sup |d omega / da| = sqrt(2 tau / e) =: W; a = dot(ray, reference) moves by at most
// |d ray|; theta_t the refracted sun's angle from the vertical (c = cos, tn = tan); D the
// deepest receiver or sample below the level; G = sup |grad of the summed water slopes| (1/m);
// the water normal moves by at most |d slopes|, and a ray refracted / reflected by it by at most
// 3 |d normal| (|d refract / d n| <= 1 + 2 eta <= 3 for eta = 1/IOR <= 1, |d reflect / d n| <=
// 2). Every other factor of the output lies in [0, 1]. The output is divided by its full scale
// (caustics: E0 * intensity; god rays: E0 * intensity * sigma_s / sigma_t), so each limit is
// the sum of the factors' Lipschitz constants times h. The mean over the image of a per-pixel
// sup bound bounds the mean change.
#include "extreme_bounds.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace extreme {
namespace {

constexpr double kE = 2.718281828459045;

double omegaSlope(double tau) {
  return std::sqrt(2.0 * tau / kE);
}

// Spacing of half floats near |v|: the rounding of an RGBA16F texel.
double halfUlp(double v) {
  const double a = std::max(std::abs(v), 6.1e-5);  // smallest normal half
  return std::ldexp(1.0, static_cast<int>(std::floor(std::log2(a))) - 10);
}

std::string fmt(const char* text, double value) {
  std::ostringstream s;
  s << text << value;
  return s.str();
}

}  // namespace

size_t nonFiniteCount(const Output& out) {
  size_t n = 0;
  for (const glm::vec4& p : out.light)
    for (int c = 0; c < 4; ++c) n += std::isfinite(p[c]) ? 0 : 1;
  for (float v : out.raw) n += std::isfinite(v) ? 0 : 1;
  return n;
}

Excess boundExcess(const Output& out, Pass pass) {
  Excess e;
  auto note = [&](double excess, size_t index, const char* what, double value) {
    if (excess > e.worst) {
      e.worst = excess;
      std::ostringstream s;
      s << what << " " << value << " at index " << index;
      e.where = s.str();
    }
  };
  if (pass == Pass::Water) {
    // RGBA16F storage rounds by at most 2^-11 relative.
    for (size_t i = 0; i < out.light.size(); ++i) {
      for (int c = 0; c < 4; ++c) {
        const double limit = double(out.texelBound[i][c]) * (1.0 + std::ldexp(1.0, -10));
        note(std::abs(double(out.light[i][c])) / limit - 1.0, i, "water texel",
             double(out.light[i][c]));
      }
    }
    return e;
  }
  // Float arithmetic of factors that are each <= 1; the half-resolution god rays pass through
  // an RGBA16F texture (2^-11 relative).
  const double tolerance = pass == Pass::GodRaysHalf ? std::ldexp(1.0, -10) : 1e-5;
  for (size_t i = 0; i < out.light.size(); ++i) {
    for (int c = 0; c < 3; ++c) {
      const double v = out.light[i][c];
      const double scale = std::max<double>(out.fullScale[c], 1e-30);
      note(-v / scale, i, "negative light", v);
      note((v - double(out.bound[c]) * (1.0 + tolerance)) / scale, i,
           "light above the model's bound", v);
    }
  }
  for (size_t i = 0; i < out.raw.size(); ++i) {
    note(-double(out.raw[i]), i, "raw factor below 0", out.raw[i]);
    note(double(out.raw[i]) - 1.0, i, "raw factor above 1", out.raw[i]);
  }
  return e;
}

// God-ray samples on the world grid jump when the grid rotates (sun, IOR) or when a march end
// passes a plane (water level): per pixel the sum of rho*omega over the samples is
// discontinuous, by design of the god-ray grid's quadrature (the image mean is what stays smooth).
// For those sweeps the light model itself is checked, with samples evenly along each ray (fixed
// positions for a fixed range).
bool continuityNeedsUniformSampling(Pass pass, Sweep sweep) {
  return isGodRayPass(pass) &&
         (sweep == Sweep::SunElevation || sweep == Sweep::Ior || sweep == Sweep::WaterLevel);
}

Continuity continuity(Pass pass, Sweep sweep, const Knobs& k, const Output& base,
                      const Output& moved) {
  Continuity r;
  const double h = kStep;
  const size_t n = base.light.size();
  if (pass == Pass::Water) {
    // Slopes only (R, G): |d slope/dt| <= sum over the cascade's modes of w |k| (|a| + |b|),
    // plus one half-float spacing for the rounding of each texel.
    double change = 0.0, limit = 0.0;
    for (size_t i = 0; i < n; ++i) {
      for (int c = 0; c < 2; ++c) {
        change += std::abs(double(moved.light[i][c]) - double(base.light[i][c]));
        limit += double(base.texelRate[i]) * h +
                 halfUlp(double(std::max(std::abs(base.light[i][c]), std::abs(moved.light[i][c]))));
      }
    }
    r.change = change / double(2 * n);
    r.limit = limit / double(2 * n);
    r.derivation = "sum_modes w|k|(|a|+|b|) h + half-float spacing";
    return r;
  }

  // Mean relative change, each channel against the base's full scale. A channel whose full
  // scale is 0 (no scattering) must not change at all.
  double change = 0.0;
  for (size_t i = 0; i < n; ++i) {
    for (int c = 0; c < 3; ++c) {
      const double d = std::abs(double(moved.light[i][c]) - double(base.light[i][c]));
      change += base.fullScale[c] > 0.0f ? d / double(base.fullScale[c]) : (d > 0.0 ? 1e30 : 0.0);
    }
  }
  r.change = change / double(3 * n);

  const Facts& f = base.facts;
  const double W = omegaSlope(k.tau), c = std::max(f.cosRefracted, 1e-12), tn = f.tanRefracted,
               D = f.maxDepth, G = f.slopeGradient;
  const double sigmaA = double(k.absorption), sigmaT = sigmaA + double(k.scattering);
  const double fade = k.surfaceFade > 0.0f ? 1.5 / double(k.surfaceFade) : 1e30;  // sup smoothstep'
  const double depthFade = 1.0 / 40.0;  // GodRaySettings::depthFadeDistance default
  const double sine = k.irradianceBySine ? 1.0 : 0.0;
  const bool god = isGodRayPass(pass);
  const double dispersion = pass == Pass::CausticsDispersion ? 1.0038 : 1.0;
  double K = 0.0;
  switch (sweep) {
    case Sweep::None:
      return r;
    case Sweep::Tau:
      // |d omega / d ln tau| = tau a^2 e^{-tau a^2} <= 1/e; at tau < 1 the step is absolute and
      // |d omega / d tau| = a^2 <= 1. God rays: a weighted mean with tau-free weights.
      K = 1.0;
      r.derivation = "|d omega/d ln tau| <= 1/e, a^2 <= 1";
      break;
    case Sweep::SunElevation:
      // The refracted and reflected rays turn by at most the sun's step (d theta_t / d theta_i
      // = eta cos(theta_i) / cos(theta_t) <= 1): W. The upward lookup along the refracted ray
      // moves by D d(tan theta_t) = D / c^2 per radian: 3 W G D / c^2. Sun-path transmittance
      // exp(-sigma d / c): x e^{-x} tn <= tn / e. Caustics: n.l moves by <= 1. Host irradiance
      // E0 sin(e): 1.
      K = W * (1.0 + 3.0 * G * D / (c * c)) + tn / kE + (god ? 0.0 : 1.0) + sine;
      r.derivation = "W(1 + 3GD/c^2) + tn/e + n.l + sin";
      break;
    case Sweep::Ior:
      // eta = 1/n moves by h/n^2 <= h; |d refract / d eta| <= 1 + 1/c; theta_t moves by <= h/c
      // so the lookup by D h / c^3; transmittance tn / (e c^2); n.l 1/c.
      K = dispersion * (W * (1.0 + 1.0 / c + 3.0 * G * D / (c * c * c)) + tn / (kE * c * c) +
                        (god ? 0.0 : 1.0 / c));
      r.derivation = "W(1 + 1/c + 3GD/c^3) + tn/(e c^2) + n.l/c";
      break;
    case Sweep::Time:
      // The summed slopes move by at most sum w|k|(|a|+|b|) h (spectrum).
      K = 3.0 * W * f.slopeRate;
      r.derivation = "3 W sup|d slope/dt|";
      break;
    case Sweep::Absorption:
      if (!god) {
        // T = exp(-sigma D / c): max(sigma, 1) |dT/d sigma| <= max(1/e, D/c).
        K = sigmaA >= 1.0 ? 1.0 / kE : D / c;
        r.derivation = "max(sigma,1)|dT/d sigma|";
      } else {
        // f = (sigma_t0/sigma_t)(1 - e^{-sigma_t L}) gamma: 1/sigma_t + L for the first two;
        // gamma's weights e^{-sigma_t t} move it by <= Cov(t, S) <= L/4; the sun path by D/c.
        const double L = f.maxMarch;
        K = (1.0 / std::max(sigmaT, 1e-30) + L + L / 4.0 + D / c) * std::max(sigmaA, 1.0);
        r.derivation = "1/sigma_t + L + L/4 + D/c";
      }
      break;
    case Sweep::WaterLevel:
      if (!god) {
        // Surface fade smoothstep' <= 1.5/F; transmittance sigma/c; lookup moves by tn h.
        K = fade + sigmaA / c + 3.0 * W * G * tn;
        r.derivation = "1.5/F + sigma/c + 3 W G tn";
      }
      break;
  }
  if (!(sweep == Sweep::WaterLevel && god)) {
    r.limit = K * h;
    return r;
  }

  // God rays, water level, evenly spaced samples: per pixel, the underwater range's length L
  // moves by dL <= h / |d_y| (its end on the surface is levelRel / d_y); f = A gamma with
  // A = 1 - e^{-sigma_t L} <= min(1, sigma_t L), |dA/dL| <= sigma_t; the samples move by <= dL
  // (source gradient G_S) and their normalised weights by <= 2 sigma_t dL; the source at a
  // fixed point moves with the level by K_S h.
  const double gradS = fade + depthFade + sigmaT / c + 3.0 * W * G * (1.0 + tn);
  const double levelS = fade + depthFade + sigmaT / c + 3.0 * W * G * tn;
  const int w = f.width, hgt = f.height;
  std::vector<double> pixel(n, 0.0);
  for (size_t i = 0; i < n; ++i) {
    const double dy = f.rayUp[i], dist = f.hitDistance[i];
    const double lr = k.cameraBelowLevel;
    double t0 = 0.0, t1 = dist;
    const double tSurface = std::abs(dy) > 1e-12 ? lr / dy : 1e30;
    if (lr < 0.0) {
      t0 = dy < 0.0 ? tSurface : dist;
    } else if (dy > 0.0) {
      t1 = std::min(t1, tSurface);
    }
    const double L = std::max(t1 - t0, 0.0);
    const double dL = std::min(h / std::max(std::abs(dy), 1e-12), dist);
    const double A = std::min(1.0, sigmaT * (L + dL));
    pixel[i] = sigmaT * dL + A * (levelS * h + (gradS + 2.0 * sigmaT) * dL);
  }
  double limit = 0.0;
  for (int y = 0; y < hgt; ++y) {
    for (int x = 0; x < w; ++x) {
      double b = pixel[static_cast<size_t>(y * w + x)];
      if (pass == Pass::GodRaysHalf) {
        // The upsample mixes the half-size texels around the pixel; texel i marched full-size
        // pixel 2i: take the largest of their bounds.
        const int bx = x >> 1, by = y >> 1;
        for (int j = 0; j < 2; ++j)
          for (int i = 0; i < 2; ++i) {
            const int sx = std::min(2 * (bx + i), w - 1), sy = std::min(2 * (by + j), hgt - 1);
            b = std::max(b, pixel[static_cast<size_t>(sy * w + sx)]);
          }
      }
      limit += b;
    }
  }
  r.limit = limit / double(n);
  r.derivation = fmt("per pixel sigma_t dL + A(K_S h + (G_S + 2 sigma_t) dL), G_S = ", gradS);
  return r;
}

}  // namespace extreme
