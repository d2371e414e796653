#pragma once
// Optical properties of the water body, as the caustics and god-ray passes need them. A plain
// struct the host fills and hands to whichever pass consumes it; the Ocean does not use it.

namespace postfx::water {

struct Rgb {
  double r, g, b;
};

struct Optics {
  double level = 0.0;  // m, world y of the undisturbed surface (double: far-from-origin worlds)
  double ior = 1.333;  // refractive index of water relative to air (n_air = 1)
  // Dispersion of the IOR across the visible range (dn between ~450 nm and ~650 nm), for
  // coloured caustics: n_blue = ior + iorSpread / 2, n_red = ior - iorSpread / 2.
  double iorSpread = 0.006;
  // Beer-Lambert absorption coefficient per channel, 1/m. Clear ocean water (Pope & Fry 1997,
  // at ~650/550/450 nm): red is absorbed within metres, blue travels tens of metres.
  Rgb absorption = {0.45, 0.07, 0.03};
  // Scattering coefficient per channel, 1/m (clear ocean, particles and molecules); with
  // absorption it gives the extinction sigma_t = absorption + scattering.
  Rgb scattering = {0.02, 0.03, 0.04};
  // Henyey-Greenstein asymmetry of in-water scattering, [-1, 1]; seawater is strongly forward.
  double phaseAsymmetry = 0.9;
};

}  // namespace postfx::water
