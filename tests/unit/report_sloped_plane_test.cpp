// The sloped receiver of the report's slope rows (sample_app/validation/sloped_plane.h) on cases
// with known answers: every pixel's world point, found by intersecting its view ray with the plane,
// lies in the horizontal bin its block is averaged into; and under flat water the seabed
// reference traced onto the plane's clamped height field gives the flat-water flux per unit
// horizontal area, n.L / (L.y n.y), in every bin.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include <seabed_reference.h>
#include <sloped_plane.h>

namespace {

using ocean::reference::ReferenceDesc;

class FlatWater final : public ocean::reference::Surface {
 public:
  ocean::reference::SurfaceSample sample(double, double) const override { return {}; }
  double maxHeight() const override { return 0.0; }
  double maxSlope() const override { return 0.0; }
  double featureSize() const override { return 1.0; }
};

ocean::validation::SlopedPlane makePlane(double slope, int facing) {
  ocean::validation::SlopedPlaneDesc d;
  d.width = 48;
  d.height = 32;
  d.binPixels = 4;
  d.slopeDegrees = slope;
  d.facing = facing;
  d.centre = {3.0, -6.5, -2.0};
  d.viewDistance = 4.0;
  return ocean::validation::slopedPlane(d, 0.0);
}

TEST(SlopedPlane, PixelsFillTheirBins) {
  for (double slope : {0.0, 30.0, 60.0}) {
    for (int facing : {1, -1}) {
      const ocean::validation::SlopedPlane plane = makePlane(slope, facing);
      const int w = plane.desc.width, h = plane.desc.height, b = plane.desc.binPixels;
      const glm::dmat3 viewToWorld = glm::transpose(glm::dmat3(plane.view.view));
      const glm::dvec3 centre = plane.desc.centre;
      double worst = 0.0;  // distance of a pixel's point from its bin's centre, in bin sizes
      for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i) {
          const double ndcX = (i + 0.5) / w * 2.0 - 1.0, ndcY = (j + 0.5) / h * 2.0 - 1.0;
          const glm::dvec3 dir = viewToWorld * glm::dvec3(ndcX / plane.view.projection[0][0],
                                                          ndcY / plane.view.projection[1][1], -1.0);
          const double t =
              glm::dot(centre - plane.camera, plane.normal) / glm::dot(dir, plane.normal);
          const glm::dvec3 p = plane.camera + t * dir;
          // binned(): row j -> bin column j / b (x), pixel column i -> bin row i / b (z).
          const glm::dvec2 size = plane.bins.size();
          const double bx = plane.bins.origin.x + (j / b + 0.5) * size.x;
          const double bz = plane.bins.origin.y + (i / b + 0.5) * size.y;
          worst = std::max({worst, std::abs(p.x - bx) / size.x, std::abs(p.z - bz) / size.y});
        }
      std::printf(
          "slope %2.0f facing %+d: pixel points within %.4f bin sizes of their bin's centre\n",
          slope, facing, worst);
      // A block of b pixels: the outermost pixel centres sit (b - 1) / (2 b) from the centre.
      EXPECT_NEAR(worst, (b - 1.0) / (2.0 * b), 1e-9);
    }
  }
}

TEST(SlopedPlane, FlatWaterFluxPerHorizontalArea) {
  ReferenceDesc desc;
  desc.towardSun = glm::normalize(glm::dvec3(0.5, 1.0, 0.0));  // 27 degrees from the zenith
  desc.targetRelativeError = 0.01;
  desc.progress = false;
  const glm::dvec3 towardLight = -ocean::reference::refractSunRay(desc.towardSun, 0, 0, desc.ior);
  for (double slope : {0.0, 45.0, 60.0}) {
    for (int facing : {1, -1}) {
      const ocean::validation::SlopedPlane plane = makePlane(slope, facing);
      desc.bins = plane.bins;
      desc.receivers = {plane.receiver(0.0)};
      const ocean::reference::ReferenceResult r =
          ocean::reference::traceSeabedCaustics(FlatWater(), desc);
      const double expected = plane.flatWaterFlux(towardLight);
      const ocean::reference::ReceiverResult& out = r.receivers[0];
      double worst = 0.0;
      for (size_t i = 0; i < out.irradiance.size(); ++i) {
        worst =
            std::max(worst, std::abs(out.irradiance[i] / expected - 1.0) / out.relativeError[i]);
      }
      std::printf(
          "slope %2.0f facing %+d: flat water %.4f per horizontal m^2 expected, worst bin "
          "%.2f stated errors away (median error %.2f %%)\n",
          slope, facing, expected, worst, 100.0 * out.medianRelativeError);
      // Stratified rays: the stated error (1/sqrt(hits)) is conservative, so 4 of them bound
      // every one of the 96 bins.
      EXPECT_LT(worst, 4.0);
      if (slope == 0.0) {
        EXPECT_NEAR(expected, 1.0, 1e-12);
      }
    }
  }
}

}  // namespace
