#include "render/octahedral.h"

#include <cmath>

#include "shared/shading_normal.h"

namespace vkpt::internal {
namespace {

// The point of [-1,1]² a unit vector maps to: projected onto the octahedron
// |x| + |y| + |z| = 1, the lower half folded outward across the square's diagonals.
glm::vec2 OctahedralProjection(glm::vec3 n) {
  n /= std::abs(n.x) + std::abs(n.y) + std::abs(n.z);
  if (n.z >= 0.0f) return {n.x, n.y};
  return {(1.0f - std::abs(n.y)) * shader::SignNotZero(n.x), (1.0f - std::abs(n.x)) * shader::SignNotZero(n.y)};
}

}  // namespace

uint32_t EncodeOctahedral(glm::vec3 unit) {
  const glm::vec2 p = OctahedralProjection(unit) * 32767.0f;
  const glm::vec2 lo = glm::floor(p), hi = glm::ceil(p);
  uint32_t best = 0;
  float bestDistance = INFINITY;
  // Rounding each coordinate to the nearest grid point is not always nearest on the
  // sphere (the projection is not conformal); trying all four neighbours is. Compared
  // by chord length: a cosine this close to 1 has no float bits left to tell them apart.
  for (int corner = 0; corner < 4; ++corner) {
    glm::vec2 q((corner & 1) ? hi.x : lo.x, (corner & 2) ? hi.y : lo.y);
    uint32_t code = glm::packSnorm2x16(q / 32767.0f);
    float d = glm::length(shader::DecodeOctahedral(code) - unit);
    if (d < bestDistance) {
      bestDistance = d;
      best = code;
    }
  }
  return best;
}

}  // namespace vkpt::internal
