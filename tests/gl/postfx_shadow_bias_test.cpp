// SunShadowMap::bias (metres toward the light) and normalOffsetTexels (along the G-buffer
// normal) on the surfaces that defeat a depth-buffer bias: a plane's own shadow map, rendered
// exactly (the plane's depth at every texel centre, as a rasterizer writes it), must leave
// >= 0.999 of the unshadowed light on it everywhere — a vertical wall and 60 degree slopes
// facing toward and away from the sun, and a flat floor under a grazing sun — with the defaults
// and coarse texels (9 cm), in each depth convention the map may use.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include <plane_gbuffer.h>
#include <postfx/postfx.h>
#include <postfx/testing.h>

#include "gl_fixture.h"

namespace {

class PostfxShadowBiasTest : public testsupport::GlTest {};

constexpr int kSize = 64;          // G-buffer pixels per side (7 cm on the plane)
constexpr int kMapTexels = 128;    // shadow map texels per side over 12 m: 9.4 cm each
constexpr double kMapHalf = 6.0;   // m
constexpr double kDistance = 4.0;  // camera to plane, m

struct Case {
  const char* name;
  glm::dvec3 normal;
  double sunElevationDegrees;  // above the horizon, azimuth +x
};

struct Gl {
  GLuint texture = 0;
  ~Gl() { glDeleteTextures(1, &texture); }
};

// Depth of the plane (through `centre`, normal n) at every texel centre of an orthographic map
// looking along -toLight, in `convention`: what a host's shadow pass writes for that plane.
GLuint planeShadowMap(const glm::dmat4& worldToClip, postfx::DepthConvention convention,
                      const glm::dvec3& centre, const glm::dvec3& n, const glm::dvec3& toLight) {
  const glm::dmat4 clipToWorld = glm::inverse(worldToClip);
  std::vector<float> texels(size_t(kMapTexels) * kMapTexels);
  for (int j = 0; j < kMapTexels; ++j) {
    for (int i = 0; i < kMapTexels; ++i) {
      const glm::dvec2 ndc((i + 0.5) / kMapTexels * 2.0 - 1.0, (j + 0.5) / kMapTexels * 2.0 - 1.0);
      const glm::dvec4 start = clipToWorld * glm::dvec4(ndc, 0.0, 1.0);
      const glm::dvec3 origin = glm::dvec3(start) / start.w;
      const double t = glm::dot(centre - origin, n) / glm::dot(-toLight, n);
      const glm::dvec4 clip = worldToClip * glm::dvec4(origin - toLight * t, 1.0);
      const double z = clip.z / clip.w;
      texels[size_t(j) * kMapTexels + i] =
          float(convention == postfx::DepthConvention::ForwardNegOneToOne ? z * 0.5 + 0.5 : z);
    }
  }
  GLuint map = 0;
  glCreateTextures(GL_TEXTURE_2D, 1, &map);
  glTextureStorage2D(map, 1, GL_DEPTH_COMPONENT32F, kMapTexels, kMapTexels);
  glTextureSubImage2D(map, 0, 0, 0, kMapTexels, kMapTexels, GL_DEPTH_COMPONENT, GL_FLOAT,
                      texels.data());
  return map;
}

glm::dmat4 orthoFor(postfx::DepthConvention convention) {
  const double h = kMapHalf;
  if (convention == postfx::DepthConvention::ForwardNegOneToOne)
    return glm::orthoRH_NO(-h, h, -h, h, 0.0, 200.0);
  glm::dmat4 p = glm::orthoRH_ZO(-h, h, -h, h, 0.0, 200.0);
  if (convention == postfx::DepthConvention::ReverseZ) {  // z' = 1 - z
    p[2][2] = -p[2][2];
    p[3][2] = 1.0 - p[3][2];
  }
  return p;
}

std::vector<float> rawFactor(postfx::Feature features, const postfx::FrameDesc& frame) {
  postfx::CreateDesc create;
  create.features = features | postfx::Feature::Caustics | postfx::testing::RawCausticOutput;
  create.normalEncoding = postfx::NormalEncoding::WorldXyz;  // the PlaneGbuffer's
  postfx::Context* fx = nullptr;
  EXPECT_EQ(postfx::create(create, fx), postfx::Result::Ok) << postfx::lastError(nullptr);
  if (!fx) return {};
  EXPECT_EQ(postfx::dispatch(*fx, frame), postfx::Result::Ok) << postfx::lastError(fx);
  std::vector<float> raw(size_t(kSize) * kSize);
  glGetTextureImage(postfx::testing::rawCausticTexture(*fx), 0, GL_RED, GL_FLOAT,
                    GLsizei(raw.size() * sizeof(float)), raw.data());
  postfx::destroy(fx);
  return raw;
}

// Mean and lowest ratio of shadowed to unshadowed raw factor over the pixels that get light.
void lightKept(const std::vector<float>& shadowed, const std::vector<float>& unshadowed,
               double& mean, double& lowest, int& lit) {
  double sum = 0.0;
  lowest = 1.0;
  lit = 0;
  for (size_t i = 0; i < shadowed.size() && i < unshadowed.size(); ++i) {
    if (!(unshadowed[i] > 1e-3f)) continue;
    const double fraction = double(shadowed[i]) / double(unshadowed[i]);
    sum += fraction;
    lowest = std::min(lowest, fraction);
    ++lit;
  }
  mean = lit > 0 ? sum / lit : 0.0;
}

TEST_F(PostfxShadowBiasTest, SelfShadowingPlanesKeepTheirLight) {
  const double s60 = std::sin(glm::radians(60.0)), c60 = std::cos(glm::radians(60.0));
  const Case cases[] = {
      {"vertical wall facing the sun", {1.0, 0.0, 0.0}, 60.0},
      {"60 degree slope facing the sun", {s60, c60, 0.0}, 40.0},
      {"60 degree slope facing away", {-s60, c60, 0.0}, 60.0},
      {"flat floor, grazing sun", {0.0, 1.0, 0.0}, 2.0},
  };
  const postfx::DepthConvention conventions[] = {postfx::DepthConvention::ForwardZeroToOne,
                                                 postfx::DepthConvention::ForwardNegOneToOne,
                                                 postfx::DepthConvention::ReverseZ};
  Gl water;
  glCreateTextures(GL_TEXTURE_2D_ARRAY, 1, &water.texture);
  glTextureStorage3D(water.texture, 1, GL_RGBA32F, 4, 4, 1);  // flat water: omega = 1
  const float zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
  glClearTexImage(water.texture, 0, GL_RGBA, GL_FLOAT, zero);

  for (const Case& c : cases) {
    const glm::dvec3 centre(0.0, -6.0, 0.0);
    const glm::dvec3 n = glm::normalize(c.normal);
    const double e = glm::radians(c.sunElevationDegrees);
    const glm::dvec3 toSun(std::cos(e), std::sin(e), 0.0);
    const glm::dvec3 toLight =  // the refracted sun, as the header asks of the map
        -glm::refract(-toSun, glm::dvec3(0.0, 1.0, 0.0), 1.0 / 1.333);
    const glm::dvec3 imageUp = glm::normalize(glm::cross(glm::dvec3(0.0, 0.0, 1.0), n));
    const ocean::validation::PlaneView view =
        ocean::validation::planeView(kSize, kSize, kDistance, n, imageUp);
    ocean::validation::PlaneGbuffer gbuffer(kSize, kSize, view);
    Gl target;
    glCreateTextures(GL_TEXTURE_2D, 1, &target.texture);
    glTextureStorage2D(target.texture, 1, GL_RGBA32F, kSize, kSize);

    postfx::FrameDesc frame;
    frame.depth = {gbuffer.depth(), GL_DEPTH_COMPONENT32F};
    frame.normal = {gbuffer.normal(), GL_RGBA16F};
    frame.albedo = {gbuffer.albedo(), GL_RGBA8};
    frame.target = {target.texture, GL_RGBA32F};
    frame.camera.position = centre + n * kDistance;
    frame.camera.view = glm::mat4(view.view);
    frame.camera.projection = view.projection;
    frame.sun.direction = toSun;
    frame.water.texture = {water.texture, GL_RGBA32F};
    frame.water.cascadeCount = 1;
    frame.caustics.surfaceFadeDepth = 0.0f;
    const std::vector<float> unshadowed = rawFactor(postfx::Feature::None, frame);

    for (postfx::DepthConvention convention : conventions) {
      const glm::dmat4 worldToClip =
          orthoFor(convention) *
          glm::lookAt(centre + toLight * 100.0, centre, glm::dvec3(0.0, 0.0, 1.0));
      Gl map;
      map.texture = planeShadowMap(worldToClip, convention, centre, n, toLight);
      frame.shadow.depth = {map.texture, GL_DEPTH_COMPONENT32F};
      frame.shadow.worldToLightClip = worldToClip;
      frame.shadow.depthConvention = convention;  // bias and normal offset: the defaults
      double mean = 0.0, lowest = 0.0;
      int lit = 0;
      lightKept(rawFactor(postfx::Feature::ShadowMask, frame), unshadowed, mean, lowest, lit);
      // The harness sees acne: without either defence the plane shadows itself.
      postfx::FrameDesc bare = frame;
      bare.shadow.bias = 0.0f;
      bare.shadow.normalOffsetTexels = 0.0f;
      double bareMean = 0.0, bareLowest = 0.0;
      int bareLit = 0;
      lightKept(rawFactor(postfx::Feature::ShadowMask, bare), unshadowed, bareMean, bareLowest,
                bareLit);
      std::printf(
          "%-32s n.L %.3f, %-18s light kept: mean %.5f, lowest pixel %.5f (%d pixels); "
          "no bias, no offset: mean %.3f, lowest %.3f\n",
          c.name, glm::dot(n, toLight), postfx::toString(convention), mean, lowest, lit, bareMean,
          bareLowest);
      EXPECT_EQ(lit, kSize * kSize) << c.name << ": every pixel faces the light";
      EXPECT_GE(mean, 0.999) << c.name << ", " << postfx::toString(convention);
      EXPECT_GE(lowest, 0.999) << c.name << ", " << postfx::toString(convention) << ": acne";
      EXPECT_LT(bareLowest, 0.9) << c.name << ": the harness must be able to see acne";
    }
  }
}

}  // namespace
