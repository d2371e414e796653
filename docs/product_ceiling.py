#!/usr/bin/env python3
# How far the default model's product of per-cascade fields can agree with light refracted by
# both cascades together, when each field is exact (docs/measurements.md, "The product's own
# ceiling"). A 16 m periodic sea: 24 coarse waves (16-2 m, slope rms 0.08) and 60 fine ones
# (2-0.1 m, slope rms 0.10), sun overhead, landing offset d (1 - 1/n) grad h to first order,
# 1024^2 photons per field binned at 6.25 cm. Prints, per depth, the correlation with the joint
# light of: the product as the plugin forms it, with the coarse pre-image iterated, with the
# coarse field warped by the fine field's flux-weighted mean offset, and with the coarse field
# convolved by the fine offsets' spread. Needs numpy (Debian: python3-numpy); deterministic.
#   python3 docs/product_ceiling.py [DEPTH_M ...]   (default 3 6.5 10)
import sys

import numpy as np

L, N, B = 16.0, 1024, 256  # tile (m), surface samples per side, bins per side
KAPPA = 0.25  # 1 - 1/n: landing offset per metre of depth and unit slope, sun overhead


def sea(rng, X, Z, kmin, kmax, slope_rms, count):
    """The slopes of `count` waves with wavenumbers in [kmin, kmax], whole periods per tile."""
    gx, gz = np.zeros((N, N)), np.zeros((N, N))
    for _ in range(count):
        while True:
            m = rng.integers(-int(kmax * L / 6.283), int(kmax * L / 6.283) + 1, 2)  # cycles
            k = 2 * np.pi / L * m
            kl = np.hypot(*k)
            if kmin <= kl <= kmax:
                break
        a, phase = 1.0 / kl, rng.uniform(0, 2 * np.pi)
        theta = k[0] * X + k[1] * Z + phase
        gx -= a * k[0] * np.sin(theta)
        gz -= a * k[1] * np.sin(theta)
    scale = slope_rms / np.sqrt(np.mean(gx**2 + gz**2))
    return gx * scale, gz * scale


def main():
    depths = [float(a) for a in sys.argv[1:]] or [3.0, 6.5, 10.0]
    rng = np.random.default_rng(1)
    x = (np.arange(N) + 0.5) / N * L
    X, Z = np.meshgrid(x, x, indexing="xy")
    cx, cz = sea(rng, X, Z, 2 * np.pi / 16, 2 * np.pi / 2.0, 0.08, 24)
    fx, fz = sea(rng, X, Z, 2 * np.pi / 2.0, 2 * np.pi / 0.1, 0.10, 60)
    flat = (N / B) ** 2

    def binned(ox, oz, weight=None):
        ix = (((X + ox) % L) / L * B).astype(int) % B
        iz = (((Z + oz) % L) / L * B).astype(int) % B
        H = np.zeros((B, B))
        np.add.at(H, (iz, ix), 1.0 if weight is None else weight)
        return H / flat

    def sample(F, px, pz):  # bilinear, periodic, metres
        u, v = px / L * B - 0.5, pz / L * B - 0.5
        i0, j0 = np.floor(u).astype(int), np.floor(v).astype(int)
        fu, fv = u - i0, v - j0
        g = lambda i, j: F[j % B, i % B]
        return (g(i0, j0) * (1 - fu) * (1 - fv) + g(i0 + 1, j0) * fu * (1 - fv) +
                g(i0, j0 + 1) * (1 - fu) * fv + g(i0 + 1, j0 + 1) * fu * fv)

    def surface(F, px, pz):  # nearest surface sample
        return F[(pz / L * N).astype(int) % N, (px / L * N).astype(int) % N]

    corr = lambda a, b: np.corrcoef(a.ravel(), b.ravel())[0, 1]
    centres = (np.arange(B) + 0.5) / B * L
    PX, PZ = np.meshgrid(centres, centres, indexing="xy")
    k = np.fft.fftfreq(B, d=L / B) * 2 * np.pi
    KX, KZ = np.meshgrid(k, k, indexing="xy")
    for d in depths:
        s = -d * KAPPA
        joint = binned(s * (cx + fx), s * (cz + fz))
        coarse = binned(s * cx, s * cz)
        fine = binned(s * fx, s * fz)
        with np.errstate(invalid="ignore", divide="ignore"):
            mean_x = np.nan_to_num(binned(s * fx, s * fz, s * fx) / fine)
            mean_z = np.nan_to_num(binned(s * fx, s * fz, s * fz) / fine)
        # The plugin: the coarse offset read at the receiver, the fine field where it sends it.
        zx, zz = PX - s * surface(cx, PX, PZ), PZ - s * surface(cz, PX, PZ)
        product = coarse * sample(fine, zx, zz)
        ux, uz = PX.copy(), PZ.copy()  # the coarse pre-image, iterated
        for _ in range(6):
            ux, uz = PX - s * surface(cx, ux, uz), PZ - s * surface(cz, ux, uz)
        iterated = coarse * sample(fine, PX - s * surface(cx, ux, uz), PZ - s * surface(cz, ux, uz))
        warped = (sample(coarse, PX - sample(mean_x, zx, zz), PZ - sample(mean_z, zx, zz)) *
                  sample(fine, zx, zz))
        spread = np.mean((s * fx) ** 2)
        diffused = np.real(np.fft.ifft2(np.fft.fft2(coarse) *
                                        np.exp(-0.5 * spread * (KX**2 + KZ**2))))
        print(f"{d:5.1f} m: product {corr(product, joint):.3f}, pre-image iterated "
              f"{corr(iterated, joint):.3f}, mean-offset warp {corr(warped, joint):.3f}, "
              f"coarse diffused by the fine spread {corr(diffused * sample(fine, zx, zz), joint):.3f}"
              f" (joint contrast {joint.std() / joint.mean():.3f})")


if __name__ == "__main__":
    main()
