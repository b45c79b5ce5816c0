// Writes shaders/shared/ggx_albedo_table.inc: the directional albedo tables of the GGX
// lobe and the rough dielectric that shared/ggx_albedo.h interpolates (see there for what
// they hold), as the start of kAlbedoTables' initializer (albedo_tables.h).
//
//   vkpt-make-ggx-table > shaders/shared/ggx_albedo_table.inc
//
// Each entry integrates the lobe of shared/microfacet.h itself — the very float code the
// renderers run — by sampling its visible normals on a stratified 128 × 128 grid: the
// weight f cos θi / pdf of a sample is then smooth (G2 / G1), so the sums converge to a
// few parts in 10⁶. Deterministic: no random numbers, sums in double.
#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <thread>
#include <vector>

#include "shared/albedo_tables.h"
#include "shared/fresnel.h"
#include "shared/layout.h"
#include "shared/microfacet.h"
#include "shared/transmission.h"

namespace {

using namespace vkpt::shader;

constexpr int kPhiSteps = 64;    // grid points in u1 (azimuth)
constexpr int kTailSteps = 512;  // grid points in x, u2 = 1 − (1 − x)⁴

constexpr float kMinMu = 1e-4f;  // the row for cos θ = 0 holds the limit, taken here

struct Albedo {
  double e = 0.0, e5 = 0.0;
};

// E and E5 at cos θo = mu.
Albedo Integrate(float mu, float alpha) {
  const vec3 wo(std::sqrt(1.0f - mu * mu), 0.0f, mu);
  Albedo sum;
  for (int i = 0; i < kPhiSteps; ++i)
    for (int j = 0; j < kTailSteps; ++j) {
      double x = (j + 0.5) / kTailSteps;
      double jacobian = 4.0 * std::pow(1.0 - x, 3.0);  // du2/dx
      float u1 = (float(i) + 0.5f) / kPhiSteps;
      vec3 h = SampleGgxVisibleNormal(wo, alpha, u1, float(1.0 - std::pow(1.0 - x, 4.0)));
      vec3 wi = 2.0f * dot(wo, h) * h - wo;
      float pdf = GgxReflectionPdf(wo, wi, alpha);
      if (!(pdf > 0.0f)) continue;
      double w = jacobian * GgxReflection(wo, wi, alpha) * wi.z / pdf;
      double schlick = std::pow(1.0 - std::min(1.0, double(dot(wo, h))), 5.0);
      sum.e += w;
      sum.e5 += w * schlick;
    }
  sum.e /= double(kPhiSteps) * kTailSteps;
  sum.e5 /= double(kPhiSteps) * kTailSteps;
  return sum;
}

// The rough dielectric's albedo at cos θo = mu: the energy reflected (Fd f_ss) and
// transmitted ((1 − Fd) f_t, times etap² for the radiance bending concentrates) by the
// lobes of bsdf.h with specular 1, from outside a volume of this ior (`entering`) or
// inside it. Each visible normal h contributes both events, weighted Fd(ωo·h) and
// 1 − Fd: the weights f cos θi / pdf of each are smooth (G2 / G1).
double IntegrateGlass(float mu, float alpha, float ior, bool entering) {
  const vec3 wo(std::sqrt(1.0f - mu * mu), 0.0f, mu);
  const float etap = entering ? ior : 1.0f / ior;
  const float r = (ior - 1.0f) / (ior + 1.0f);
  double sum = 0.0;
  for (int i = 0; i < kPhiSteps; ++i)
    for (int j = 0; j < kTailSteps; ++j) {
      double x = (j + 0.5) / kTailSteps;
      double jacobian = 4.0 * std::pow(1.0 - x, 3.0);
      float u1 = (float(i) + 0.5f) / kPhiSteps;
      vec3 h = SampleGgxVisibleNormal(wo, alpha, u1, float(1.0 - std::pow(1.0 - x, 4.0)));
      double fresnel = DielectricFresnel(vec3(r * r), 1.0f, dot(wo, h), etap).x;
      double w = 0.0;
      vec3 reflected = 2.0f * dot(wo, h) * h - wo;
      float pdf = reflected.z > 0.0f ? GgxReflectionPdf(wo, reflected, alpha) : 0.0f;
      if (pdf > 0.0f) w += fresnel * GgxReflection(wo, reflected, alpha) * reflected.z / pdf;
      vec3 refracted = Refract(wo, h, etap);
      pdf = refracted.z < 0.0f ? GgxRefractionPdf(wo, refracted, h, etap, alpha) : 0.0f;
      if (pdf > 0.0f)
        w += (1.0 - fresnel) * GgxRefraction(wo, refracted, h, etap, alpha) * -refracted.z / pdf * etap * etap;
      sum += jacobian * w;
    }
  return sum / (double(kPhiSteps) * kTailSteps);
}

// 2 ∫₀¹ g(μ) μ dμ for g piecewise linear in s = sqrt(μ) through (s_i = i / (n − 1), g_i),
// as ggx_albedo.h interpolates it: with μ = s², 4 ∫₀¹ g(s) s³ ds, exact per interval, so
// the average matches the interpolated rows that the renderers read.
double CosineAverage(const std::vector<double>& g) {
  const int n = int(g.size());
  const double h = 1.0 / (n - 1);
  double sum = 0.0;
  for (int i = 0; i + 1 < n; ++i) {
    double a = i * h, b = a + h;
    double slope = (g[i + 1] - g[i]) / h;  // g(s) = g_i + slope (s − a) on [a, b]
    sum += g[i] * (std::pow(b, 4) - std::pow(a, 4)) +
           slope * (0.8 * (std::pow(b, 5) - std::pow(a, 5)) - a * (std::pow(b, 4) - std::pow(a, 4)));
  }
  return sum;
}

// The rough dielectric's pairs (E entering, E leaving), ior outermost, spaced evenly in
// z = sqrt((ior − 1) / (ior + 1)) as Blender's tables are, then cos θ (in sqrt) as in the
// GGX table and roughness in sqrt.
std::vector<Albedo> GlassTable() {
  constexpr int iors = int(kGlassAlbedoIors), cosines = int(kGlassAlbedoCosines);
  constexpr int roughnesses = int(kGlassAlbedoRoughnesses), block = cosines * roughnesses;
  const float zMax = std::sqrt((kGlassAlbedoMaxIor - 1.0f) / (kGlassAlbedoMaxIor + 1.0f));
  // At ior 1 itself Walter's refraction lobe is 0/0 (ωi = −ωo); the renderers draw that
  // case as a thin wall anyway. Its block is the next one's (ior 1.0004). The blocks are
  // shared out among threads; each entry is the same whichever computes it.
  std::vector<Albedo> glass(size_t(iors) * block);
  std::atomic<int> next{1};
  auto work = [&] {
    for (int k; (k = next++) < iors;) {
      const float z = zMax * float(k) / (iors - 1), z2 = z * z;
      const float ior = (1.0f + z2) / (1.0f - z2);
      std::fprintf(stderr, "glass table: ior %.4f (%d of %d)\n", ior, k + 1, iors);
      for (int x = 0; x < cosines; ++x)
        for (int y = 0; y < roughnesses; ++y) {
          float s = float(x) / (cosines - 1);
          float mu = std::max(s * s, kMinMu);
          float t = float(y) / (roughnesses - 1);
          float alpha = GgxAlpha(t * t);
          glass[size_t(k) * block + x * roughnesses + y] = {IntegrateGlass(mu, alpha, ior, true),
                                                            IntegrateGlass(mu, alpha, ior, false)};
        }
    }
  };
  std::vector<std::thread> threads;
  for (unsigned i = 0; i < std::max(1u, std::thread::hardware_concurrency()); ++i) threads.emplace_back(work);
  for (std::thread& t : threads) t.join();
  std::copy(glass.begin() + block, glass.begin() + 2 * block, glass.begin());
  return glass;
}

}  // namespace

int main() {
  constexpr int n = int(kGgxAlbedoSize);
  std::vector<Albedo> table(n * n);
  for (int x = 0; x < n; ++x)
    for (int y = 0; y < n; ++y) {
      float s = float(x) / (n - 1);  // rows are spaced in sqrt(μ): E changes fastest at grazing
      float mu = std::max(s * s, kMinMu);
      float r = float(y) / (n - 1);
      table[x * n + y] = Integrate(mu, std::max(r * r, 1e-6f));
    }
  for (int y = 0; y < n; ++y) {  // the cosine-weighted averages, appended as row n
    std::vector<double> e(n), e5(n);
    for (int x = 0; x < n; ++x) {
      e[x] = table[x * n + y].e;
      e5[x] = table[x * n + y].e5;
    }
    table.push_back({CosineAverage(e), CosineAverage(e5)});
  }
  const std::vector<Albedo> glass = GlassTable();
  table.insert(table.end(), glass.begin(), glass.end());
  std::printf(
      "// Generated by scripts/make_ggx_albedo_table.cpp (vkpt-make-ggx-table); do not edit.\n"
      "// The start of kAlbedoTables' initializer (albedo_tables.h), in host/render/albedo_tables.cpp.\n"
      "// The GGX albedo table that shared/ggx_albedo.h interpolates: the pair (E, E5) at\n"
      "// [2 (i * kGgxAlbedoSize + j)] for cos θ = (i / %d)² and roughness j / %d, then the pairs\n"
      "// (E_avg, E5_avg) per roughness column at [2 (kGgxAlbedoSize² + j)], then the rough\n"
      "// dielectric's pairs (E entering, E leaving) at [2 (kGgxAlbedoSize (kGgxAlbedoSize + 1) +\n"
      "// (k * kGlassAlbedoCosines + i) * kGlassAlbedoRoughnesses + j)] for z = sqrt((ior − 1)/(ior + 1)) =\n"
      "// k/%d of its value at kGlassAlbedoMaxIor, cos θ = (i / %d)² and roughness (j / %d)².\n"
      "// clang-format off\n",
      n - 1, n - 1, int(kGlassAlbedoIors) - 1, int(kGlassAlbedoCosines) - 1, int(kGlassAlbedoRoughnesses) - 1);
  if (2 * table.size() != kGgxAlbedoFloats) {
    std::fprintf(stderr, "vkpt-make-ggx-table: %zu floats, but albedo_tables.h declares %u for it\n", 2 * table.size(),
                 kGgxAlbedoFloats);
    return 1;
  }
  for (size_t k = 0; k < table.size(); ++k)
    std::printf("%s%.7ff, %.7ff%s", k % 4 == 0 ? "    " : " ", table[k].e, table[k].e5,
                k % 4 == 3 || k + 1 == table.size() ? ",\n" : ",");
  std::printf("// clang-format on\n");
  return 0;
}
