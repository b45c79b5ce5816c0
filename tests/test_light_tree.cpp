// The light tree (host/render/light_tree.h, shaders/shared/light_tree.h): its nodes bound
// their lights, every light that can reach a point keeps a positive pmf there, its samples
// follow its pmf (χ²), and renders with it agree in statistics with the power-proportional
// choice — while a tree whose orientation bounds are too narrow is caught.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "cpu/light_importances_sse2.h"  // first: the walk below takes the CPU's importances
#include "cpu/path_tracer.h"
#include "gltf/gltf_loader.h"
#include "render/light_table.h"
#include "render/light_tree.h"
#include "render/render_scene.h"
#include "render/scene_access.h"
#include "shared/light_tree.h"
#include "shared/sampling.h"
#include "test_util.h"

namespace vkpt::internal {
namespace {

using shader::FrameParams;

struct Rng {
  std::mt19937 engine;
  explicit Rng(uint32_t seed) : engine(seed) {}
  double Uniform() { return (engine() >> 8) * 0x1p-24; }
  double Between(double lo, double hi) { return lo + (hi - lo) * Uniform(); }
  glm::dvec3 InBox(double lo, double hi) { return {Between(lo, hi), Between(lo, hi), Between(lo, hi)}; }
  glm::dvec3 Direction() {
    double z = Between(-1.0, 1.0), phi = Between(0.0, 2.0 * shader::kPi), r = std::sqrt(1.0 - z * z);
    return {r * std::cos(phi), r * std::sin(phi), z};
  }
};

// `triangles` small emissive triangles in [0, 10]³ of random orientation, half of them
// two-sided, of emission over a factor 128, and `punctual` point and spot lights (spots of
// varied cones), over a floor below them that the camera looks down on.
Scene ManyLightScene(uint32_t triangles, uint32_t punctual, uint32_t seed) {
  Rng rng(seed);
  std::vector<Material> materials(9);
  for (uint32_t k = 0; k < 8; ++k) {
    materials[k].baseColor = glm::vec3(0.5f);
    materials[k].emission = glm::vec3(std::exp2(float(k)) * 0.1f) * glm::vec3(1.0f, 0.8f + 0.05f * k, 0.6f);
    materials[k].doubleSided = k % 2 == 1;
  }
  materials[8].baseColor = glm::vec3(0.7f);
  std::vector<SceneTriangle> tris;
  for (uint32_t i = 0; i < triangles; ++i) {
    glm::dvec3 c = rng.InBox(0.0, 10.0), n = rng.Direction();
    glm::dvec3 u = glm::normalize(glm::cross(n, std::abs(n.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0)));
    glm::dvec3 v = glm::cross(n, u);
    double size = rng.Between(0.05, 0.3);
    tris.push_back({glm::vec3(c), glm::vec3(c + size * u), glm::vec3(c + size * v), uint32_t(rng.Uniform() * 8)});
  }
  tris.push_back({{-5, -1, -5}, {15, -1, 15}, {15, -1, -5}, 8});
  tris.push_back({{-5, -1, -5}, {-5, -1, 15}, {15, -1, 15}, 8});
  Scene s = test::MakeScene(tris, materials);
  for (uint32_t i = 0; i < punctual; ++i) {
    PunctualLight l;
    l.type = i % 2 ? PunctualLight::Type::kSpot : PunctualLight::Type::kPoint;
    l.position = glm::vec3(rng.InBox(0.0, 10.0));
    l.direction = glm::vec3(glm::normalize(rng.Direction() - glm::dvec3(0, 1.5, 0)));
    l.intensity = glm::vec3(float(rng.Between(0.5, 20.0)));
    double outer = rng.Between(0.2, 1.4);
    l.cosOuter = float(std::cos(outer));
    l.cosInner = float(std::cos(outer * rng.Between(0.0, 0.9)));
    s.lights.push_back(l);
    s.bounds.Extend(l.position);
  }
  Camera cam = DefaultCamera(s.bounds);
  s.cameras.push_back(cam);
  return s;
}

RenderScene WithTree(const Scene& s) {
  RenderScene rs = PrepareRenderScene(s);
  ChooseLightSampler(rs, LightSampler::kTree);
  return rs;
}

LightBounds BoundsOfLight(const RenderScene& rs, uint32_t k) {
  return LightBoundsOf(rs, rs.lights[k], rs.lightPower[k]);
}

// Accurate for small angles too, where acos of the dot product is not.
double Angle(glm::dvec3 a, glm::dvec3 b) {
  a = glm::normalize(a);
  b = glm::normalize(b);
  return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b));
}

// Checks the subtree at `node` over lights [first, end) and returns its depth.
uint32_t CheckSubtree(const RenderScene& rs, uint32_t node, uint32_t first, uint32_t end, std::vector<int>& visits) {
  EXPECT_LT(node, rs.lightTree.size());
  if (node >= rs.lightTree.size()) return 0;
  ++visits[node];
  const shader::LightTreeNode& n = rs.lightTree[node];
  const double thetaO = std::atan2(double(n.sinThetaO), double(n.cosThetaO));
  const glm::dvec3 axis(n.axis);
  double intensity = 0.0;
  for (uint32_t k = first; k < end; ++k) {
    LightBounds b = BoundsOfLight(rs, k);
    intensity += b.intensity;
    for (int corner = 0; corner < 8; ++corner) {
      glm::dvec3 x((corner & 1) ? b.hi.x : b.lo.x, (corner & 2) ? b.hi.y : b.lo.y, (corner & 4) ? b.hi.z : b.lo.z);
      EXPECT_LE(glm::length(x - glm::dvec3(n.center)), double(n.radius)) << "node " << node << " light " << k;
    }
    if (n.cosThetaO > -1.0f) {
      EXPECT_LE(Angle(axis, b.axis) + std::acos(b.cosThetaO), thetaO) << "node " << node << " light " << k;
    }
    EXPECT_LE(double(n.cosThetaE), b.cosThetaE) << "node " << node << " light " << k;
    if (b.twoSided) {
      EXPECT_NE(n.split & shader::kLightNodeTwoSided, 0u) << "node " << node << " light " << k;
    }
  }
  EXPECT_NEAR(n.intensity, intensity, 1e-5 * intensity) << "node " << node;
  if (end - first == 1) return 0;
  const uint32_t split = n.split & ~shader::kLightNodeTwoSided;
  EXPECT_GT(split, first);
  EXPECT_LT(split, end);
  if (split <= first || split >= end) return 0;
  uint32_t left = CheckSubtree(rs, node + 1, first, split, visits);
  uint32_t right = CheckSubtree(rs, node + 2 * (split - first), split, end, visits);
  return 1 + std::max(left, right);
}

TEST(LightTree, NodesBoundTheirLightsDepthFirst) {
  for (uint32_t seed : {1u, 2u}) {
    Scene s = ManyLightScene(300, 40, seed);
    RenderScene rs = WithTree(s);
    ASSERT_EQ(rs.treeLights, rs.lights.size());  // no directional light nor environment
    ASSERT_EQ(rs.treeLights, 300u + 40u) << "every triangle is its own light";
    ASSERT_EQ(rs.lightTree.size(), 2 * rs.treeLights - 1);
    std::vector<int> visits(rs.lightTree.size(), 0);
    uint32_t depth = CheckSubtree(rs, 0, 0, rs.treeLights, visits);
    EXPECT_EQ(depth, rs.lightTreeDepth);
    EXPECT_LE(depth, kLightTreeMaxSahDepth + 10);
    for (size_t i = 0; i < visits.size(); ++i) EXPECT_EQ(visits[i], 1) << "node " << i;
    // The table's light of each emissive triangle still is that triangle's (or, for a
    // spatial-split copy, its first copy's).
    for (const shader::Triangle& t : rs.triangles)
      if (t.light != shader::kInvalidIndex) {
        EXPECT_EQ(rs.triangles[rs.lights[t.light].triangle].sourceIndex, t.sourceIndex);
      }
    std::printf("seed %u: %u lights, %zu nodes, depth %u\n", seed, rs.treeLights, rs.lightTree.size(), depth);
  }
}

// Whether a point of light k of the table emits towards p (from x, a random point of it).
bool Emits(const RenderScene& rs, uint32_t k, glm::dvec3 p, Rng& rng, glm::dvec3* from) {
  const shader::Light& l = rs.lights[k];
  glm::dvec3 x(l.position);
  if (l.type == shader::kLightTriangle || l.type == shader::kLightTwoSidedTriangle) {
    const shader::Triangle& t = rs.triangles[l.triangle];
    glm::vec2 b = shader::SampleUniformTriangle(float(rng.Uniform()), float(rng.Uniform()));
    x = glm::dvec3(t.v0) + double(b.x) * glm::dvec3(t.e1) + double(b.y) * glm::dvec3(t.e2);
  }
  *from = x;
  glm::dvec3 w = glm::normalize(p - x);
  double c = glm::dot(glm::dvec3(l.direction), w);
  switch (l.type) {
    case shader::kLightTriangle: return c > 0.0;
    case shader::kLightTwoSidedTriangle: return c != 0.0;
    case shader::kLightSpot: return c > l.cosOuter;
    default: return true;
  }
}

// Of `trials` random (point, normal, light) triples where the light emits towards the
// point, how many get pmf 0 there: light sampling would never pick a light that lights it.
int UnreachedLights(const RenderScene& rs, int trials, uint32_t seed, const char* what) {
  Rng rng(seed);
  int reached = 0, unreached = 0;
  while (reached < trials) {
    glm::dvec3 p = rng.InBox(-3.0, 13.0), n = rng.Direction(), x;
    uint32_t k = uint32_t(rng.Uniform() * rs.treeLights);
    if (!Emits(rs, k, p, rng, &x) || std::abs(glm::dot(n, glm::normalize(x - p))) < 1e-3) continue;
    ++reached;
    float pmf = shader::LightTreePmf(rs, rs.treeLights, 1.0f, glm::vec3(p), glm::vec3(n), k);
    if (!(pmf > 0.0f) && ++unreached <= 3)
      std::printf("%s: light %u (type %u) lights (%.3f %.3f %.3f) but has pmf 0 there\n", what, k, rs.lights[k].type,
                  p.x, p.y, p.z);
  }
  return unreached;
}

// A mutant tree whose orientation bounds are too narrow: every node's cone is its axis
// alone (θo = 0), spread by only 30° (θe), whatever its lights' normals and spots.
RenderScene WithNarrowCones(RenderScene rs) {
  for (shader::LightTreeNode& n : rs.lightTree) {
    n.cosThetaO = 1.0f;
    n.sinThetaO = 0.0f;
    n.cosThetaE = float(std::cos(shader::kPi / 6.0));
  }
  return rs;
}

TEST(LightTree, EveryLightThatReachesAPointCanBeChosenThere) {
  RenderScene rs = WithTree(ManyLightScene(300, 40, 3));
  EXPECT_EQ(UnreachedLights(rs, 20000, 7, "tree"), 0);
  int mutant = UnreachedLights(WithNarrowCones(rs), 20000, 7, "mutant");
  std::printf("mutant with narrow cones: %d of 20000 reaching lights unreachable\n", mutant);
  EXPECT_GT(mutant, 100) << "a tree whose orientation bounds are too narrow must be caught";
}

// LightNodeImportancesSse2 (four nodes at once, the CPU's) gives what
// LightNodeImportance gives each node, exactly, at points far from, near and inside the
// nodes' spheres and at their centres (a point light's), with and without a surface normal;
// a lane of no node gives 0, and every importance is finite.
TEST(LightTree, FourNodeImportancesAreEachNodes) {
  RenderScene rs = WithTree(ManyLightScene(300, 40, 5));
  const uint32_t nodes = uint32_t(rs.lightTree.size());
  Rng rng(17);
  int compared = 0, positive = 0, nonFinite = 0, mismatches = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    glm::uvec4 ids;
    for (int lane = 0; lane < 4; ++lane) ids[lane] = uint32_t(rng.Uniform() * nodes);
    if (trial % 5 == 1) ids[1] = shader::kInvalidIndex;
    if (trial % 7 == 2) ids[3] = shader::kInvalidIndex;
    const shader::LightTreeNode& near = rs.lightTree[ids.x];
    glm::vec3 p = trial % 3 == 0 ? near.center + float(rng.Between(0.0, 2.0) * near.radius) * glm::vec3(rng.Direction())
                                 : glm::vec3(rng.InBox(-5.0, 15.0));
    if (trial % 11 == 3) p = near.center;
    const glm::vec3 n = trial % 4 == 0 ? glm::vec3(0.0f) : glm::vec3(rng.Direction());
    const shader::LightImportances four = LightNodeImportancesSse2(rs, ids, p, n);
    for (int lane = 0; lane < 4; ++lane) {
      const glm::vec2 one = ids[lane] == shader::kInvalidIndex
                                ? glm::vec2(0.0f)
                                : shader::LightNodeImportance(rs.lightTree[ids[lane]], p, n);
      ++compared;
      positive += one.x > 0.0f;
      nonFinite += !std::isfinite(one.x) || !std::isfinite(one.y);
      if ((four.bound[lane] != one.x || four.estimate[lane] != one.y) && ++mismatches <= 3)
        std::printf("node %u at (%g %g %g): four-wide (%.9g, %.9g), one (%.9g, %.9g)\n", ids[lane], p.x, p.y, p.z,
                    four.bound[lane], four.estimate[lane], one.x, one.y);
    }
  }
  std::printf("%d importances compared, %d positive\n", compared, positive);
  EXPECT_EQ(mismatches, 0);
  EXPECT_EQ(nonFinite, 0);
  EXPECT_GT(positive, compared / 4) << "the comparison must cover importances that are not 0";
}

// At random shading points the pmfs sum to 1, SampleLightTree reports the pmf that
// LightTreePmf computes for its choice, and its choices follow the pmfs (χ², family α 0.01).
TEST(LightTree, SamplesFollowThePmf) {
  RenderScene rs = WithTree(ManyLightScene(150, 20, 4));
  const int kPoints = 12, kSamples = 500000;
  Rng rng(11);
  for (int point = 0; point < kPoints; ++point) {
    glm::vec3 p(rng.InBox(-2.0, 12.0)), n(rng.Direction());
    std::vector<double> expected(rs.treeLights), observed(rs.treeLights, 0.0);
    double sum = 0.0;
    for (uint32_t k = 0; k < rs.treeLights; ++k) {
      double pmf = shader::LightTreePmf(rs, rs.treeLights, 1.0f, p, n, k);
      sum += pmf;
      expected[k] = pmf * kSamples;
    }
    EXPECT_NEAR(sum, 1.0, 1e-5) << "point " << point;
    int mismatched = 0;
    for (int i = 0; i < kSamples; ++i) {
      shader::LightTreeChoice c = shader::SampleLightTree(rs, rs.treeLights, 1.0f, p, n, float(rng.Uniform()));
      observed[c.light] += 1.0;
      mismatched += c.pmf != shader::LightTreePmf(rs, rs.treeLights, 1.0f, p, n, c.light);
      EXPECT_GE(c.u, 0.0f);
      EXPECT_LT(c.u, 1.0f);
    }
    EXPECT_EQ(mismatched, 0) << "point " << point;
    double statistic = 0.0;
    int dof = 0;
    double pValue = test::ChiSquareTest(observed, expected, &statistic, &dof);
    std::printf("point %d: χ² %.1f with %d dof, p %.4f\n", point, statistic, dof, pValue);
    EXPECT_GT(pValue, test::SidakAlpha(0.01, kPoints)) << "point " << point;
    if (point == 0) {  // the test's teeth: samples drawn 0.5 away do not follow this point's pmfs
      std::vector<double> elsewhere(rs.treeLights, 0.0), quarter = expected;
      for (double& e : quarter) e /= 4.0;
      for (int i = 0; i < kSamples / 4; ++i)
        elsewhere[shader::SampleLightTree(rs, rs.treeLights, 1.0f, p + glm::vec3(0.5f, 0.0f, 0.0f), n,
                                          float(rng.Uniform()))
                      .light] += 1.0;
      double mutantP = test::ChiSquareTest(elsewhere, quarter, &statistic, &dof);
      std::printf("mutant (samples from 0.5 away): χ² %.1f with %d dof, p %.3g\n", statistic, dof, mutantP);
      EXPECT_LT(mutantP, 1e-6) << "the χ² test must tell another point's choices apart";
    }
  }
}

// Image means of two renders of one scene agree: per channel |z| below the Šidák-corrected
// critical value of a family of `tests` at α = 0.01, or within 0.5 %. Returns the failures.
int DisagreeingChannels(const Image& a, const Image& b, int tests, const char* what) {
  const double alpha = test::SidakAlpha(0.01, tests);
  test::ZTest ta = test::MeanAndError(a, glm::dvec3(0.0)), tb = test::MeanAndError(b, glm::dvec3(0.0));
  int failures = 0;
  for (int c = 0; c < 3; ++c) {
    double diff = ta.mean[c] - tb.mean[c];
    double z = diff / std::sqrt(ta.stderr_[c] * ta.stderr_[c] + tb.stderr_[c] * tb.stderr_[c]);
    double rel = std::abs(diff) / std::max(ta.mean[c], tb.mean[c]);
    bool fail = test::NormalSurvivalTwoSided(std::abs(z)) < alpha && rel > 0.005;
    failures += fail;
    std::printf("%s, channel %d: %.5f (±%.5f) vs %.5f (±%.5f), z %.2f %s\n", what, c, ta.mean[c], ta.stderr_[c],
                tb.mean[c], tb.stderr_[c], z, fail ? "FAIL" : "ok");
  }
  return failures;
}

FrameParams Frame(const RenderScene& rs, const Scene& s, uint32_t size, uint32_t spp, uint32_t seed) {
  FrameParams p = test::TestFrame(rs, s, size, spp, seed, 6);
  p.rrDepth = 3;
  p.background = glm::vec3(0.0f);
  return p;
}

// The tree and the power-proportional choice estimate the same image (independent seeds)
// on the Cornell box (two lights), the generated hall of 2,000 emissive triangles, and a
// scene of emissive triangles with point and spot lights; the tree with narrow cones,
// which never picks some point and spot lights where they shine, is caught.
TEST(LightTree, RendersAgreeWithThePowerChoice) {
  struct Case {
    const char* name;
    Scene scene;
    uint32_t size, spp;
  };
  Case cases[] = {
      {"Cornell box", LoadGltf(test::SourcePath("scenes/cornell.gltf")), 24, 256 / test::kSampleDivisor},
      {"many_lights hall", LoadGltf(test::SourcePath("scenes/many_lights.gltf")), 24, 256 / test::kSampleDivisor},
      {"triangles, points and spots", ManyLightScene(200, 60, 5), 24, 256 / test::kSampleDivisor},
  };
  constexpr int kTests = 3 * 3 + 3;
  for (Case& c : cases) {
    RenderScene power = PrepareRenderScene(c.scene), tree = WithTree(c.scene);
    ASSERT_GT(tree.treeLights, 1u) << c.name;
    Image a = RenderCpu(power, Frame(power, c.scene, c.size, c.spp, 1)).image;
    Image b = RenderCpu(tree, Frame(tree, c.scene, c.size, c.spp, 2)).image;
    EXPECT_EQ(DisagreeingChannels(a, b, kTests, c.name), 0) << c.name;
  }
  Case& punctual = cases[2];
  RenderScene power = PrepareRenderScene(punctual.scene), mutant = WithNarrowCones(WithTree(punctual.scene));
  Image a = RenderCpu(power, Frame(power, punctual.scene, 24, 256, 3)).image;
  Image b = RenderCpu(mutant, Frame(mutant, punctual.scene, 24, 256, 4)).image;
  EXPECT_GT(DisagreeingChannels(a, b, kTests, "mutant: narrow cones"), 0)
      << "a tree whose orientation bounds are too narrow must be caught";
}

// Auto takes the tree from kLightTreeMinLights finite lights on; directional lights and
// the environment stay outside it, after its lights.
TEST(LightTree, AutoChoosesTheTreeForManyLights) {
  Scene few = ManyLightScene(7, 0, 6), many = ManyLightScene(8, 0, 6);  // 7 and 8 lights
  RenderScene a = PrepareRenderScene(few), b = PrepareRenderScene(many), c = PrepareRenderScene(many);
  ChooseLightSampler(a, LightSampler::kAuto);
  ChooseLightSampler(b, LightSampler::kAuto);
  ChooseLightSampler(c, LightSampler::kPower);
  EXPECT_EQ(a.treeLights, 0u);
  EXPECT_TRUE(a.lightTree.empty());
  EXPECT_EQ(b.treeLights, kLightTreeMinLights);
  EXPECT_EQ(c.treeLights, 0u);
  PunctualLight sun;
  sun.type = PunctualLight::Type::kDirectional;
  many.lights.insert(many.lights.begin(), sun);
  RenderScene d = PrepareRenderScene(many);
  ChooseLightSampler(d, LightSampler::kAuto);
  EXPECT_EQ(d.treeLights, kLightTreeMinLights);
  ASSERT_EQ(d.lights.size(), kLightTreeMinLights + 1);
  EXPECT_EQ(d.lights.back().type, shader::kLightDirectional);
  double total = 0.0;
  for (const shader::Light& l : d.lights) total += l.pmf;
  EXPECT_NEAR(total, 1.0, 1e-6);
}

}  // namespace
}  // namespace vkpt::internal
