// Soft shadow maps, one micro-patch (Atty et al. 2006 §3.3-3.4): the shader's back-projection
// (shaders/shared/ssm_patch.glsl) against the analytic clipped-rectangle area of the CPU
// oracle (tests/support/rect_visibility.h, world space, double precision), and the penumbra
// extent of §3.3 against the oracle's zero/non-zero occlusion just outside/inside it.
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "gl/gpu_layout_ssm.h"
#include "gl/shader_program.h"
#include "support/gl_test.h"
#include "support/rect_visibility.h"

namespace {

struct Placement {
  RectLight light;
  double zLight;  // projection point behind the light centre (Eq 3.1)
  ParallelRect patch;
  glm::dvec3 wsReceiver;
};

glm::dvec3 randomUnit(std::mt19937& rng) {
  std::normal_distribution<double> n;
  return glm::normalize(glm::dvec3(n(rng), n(rng), n(rng)));
}

// Random light frames, patches and receivers; patches from far inside to fully outside the
// light's view, receivers in front of and behind the patch.
Placement randomPlacement(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(0, 1);
  Placement p;
  RectLight& light = p.light;
  light.forward = randomUnit(rng);
  light.right = glm::normalize(glm::cross(light.forward, randomUnit(rng)));
  light.up = glm::cross(light.right, light.forward);
  light.center = 4.0 * glm::dvec3(u(rng) - 0.5, u(rng) - 0.5, u(rng) - 0.5);
  light.halfWidth = 0.1 + 1.4 * u(rng);
  light.halfHeight = 0.1 + 1.4 * u(rng);
  p.zLight = 0.2 + 2 * u(rng);
  const double patchDepth = 0.05 + 3 * u(rng);
  const double size = u(rng) < 0.3 ? 0.5 + 2 * u(rng) : 0.01 + 0.5 * u(rng);
  p.patch = {light.center + patchDepth * light.forward + (6 * u(rng) - 3) * light.right +
                 (6 * u(rng) - 3) * light.up,
             size * (0.5 + u(rng)), size * (0.5 + u(rng))};
  const double receiverDepth = u(rng) < 0.1 ? patchDepth * u(rng) : patchDepth + 0.01 + 5 * u(rng);
  p.wsReceiver = light.center + receiverDepth * light.forward + (10 * u(rng) - 5) * light.right +
                 (10 * u(rng) - 5) * light.up;
  return p;
}

// Light view space of ssm_patch.glsl: from the projection point, (right, up, forward).
glm::dvec3 toLightView(const Placement& p, const glm::dvec3& ws) {
  const glm::dvec3 rel = ws - (p.light.center - p.zLight * p.light.forward);
  return {glm::dot(rel, p.light.right), glm::dot(rel, p.light.up), glm::dot(rel, p.light.forward)};
}

gpu::SsmPatchQuery toQuery(const Placement& p) {
  const glm::dvec3 c = toLightView(p, p.patch.center);
  const glm::dvec3 r = toLightView(p, p.wsReceiver);
  gpu::SsmPatchQuery q{};
  q.patchRect = glm::vec4(c.x - p.patch.halfWidth, c.y - p.patch.halfHeight,
                          c.x + p.patch.halfWidth, c.y + p.patch.halfHeight);
  q.depths = glm::vec4(c.z, p.zLight, p.light.halfWidth, p.light.halfHeight);
  q.lsReceiver = glm::vec4(r, r.z);  // virtual plane through the receiver
  return q;
}

std::vector<gpu::SsmPatchResult> runQueries(const std::vector<gpu::SsmPatchQuery>& queries) {
  headlessContext();
  static ShaderProgram program{{{GL_COMPUTE_SHADER, "tests/ssm_patch_query.comp"}}};
  GlBuffer queryBuffer, resultBuffer;
  queryBuffer.upload(queries.data(), queries.size() * sizeof(gpu::SsmPatchQuery));
  std::vector<gpu::SsmPatchResult> results(queries.size());
  resultBuffer.upload(results.data(), results.size() * sizeof(gpu::SsmPatchResult));
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, SSM_QUERY_BINDING, queryBuffer.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, SSM_RESULT_BINDING, resultBuffer.id());
  program.use();
  glUniform1i(0, int(queries.size()));
  glDispatchCompute(GLuint((queries.size() + 63) / 64), 1, 1);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  glGetNamedBufferSubData(resultBuffer.id(), 0,
                          GLsizeiptr(results.size() * sizeof(gpu::SsmPatchResult)), results.data());
  return results;
}

}  // namespace

// §3.4: the occluded fraction equals the clipped area of the back-projected rectangle, for
// patches inside, across the edge of and outside the light's view, and receivers in front
// of the patch (nothing hidden).
TEST(SsmPatch, BackProjectionEqualsAnalyticClippedArea) {
  std::mt19937 rng(9);
  std::vector<Placement> placements;
  std::vector<gpu::SsmPatchQuery> queries;
  for (int i = 0; i < 20000; ++i) {
    placements.push_back(randomPlacement(rng));
    queries.push_back(toQuery(placements.back()));
  }
  const auto results = runQueries(queries);
  int none = 0, partial = 0, full = 0, inFront = 0;
  double worst = 0;
  for (size_t i = 0; i < placements.size(); ++i) {
    const Placement& p = placements[i];
    const double exact = hiddenFraction(p.light, p.patch, p.wsReceiver);
    const double shader = results[i].occlusion.x;
    worst = std::max(worst, std::abs(shader - exact));
    EXPECT_NEAR(shader, exact, 2e-5) << "placement " << i;
    if (queries[i].lsReceiver.z <= queries[i].depths.x) ++inFront;
    else if (exact == 0) ++none;
    else if (exact > 1 - 1e-12) ++full;
    else ++partial;
  }
  std::printf("placements: %d hide nothing, %d partly, %d all of the light, %d receivers in "
              "front; largest difference %.3g\n", none, partial, full, inFront, worst);
  EXPECT_GT(none, 1000);
  EXPECT_GT(partial, 1000);
  EXPECT_GT(full, 200);
  EXPECT_GT(inFront, 500);
}

// §3.3: the penumbra extent at a depth is exactly where the patch starts to hide part of the
// light: just outside each side nothing is hidden, just inside something is.
TEST(SsmPatch, PenumbraExtentBoundsTheOcclusion) {
  std::mt19937 rng(17);
  std::vector<Placement> placements;
  std::vector<gpu::SsmPatchQuery> queries;
  while (placements.size() < 4000) {
    Placement p = randomPlacement(rng);
    const gpu::SsmPatchQuery q = toQuery(p);
    if (q.lsReceiver.z <= q.depths.x + 0.05f) continue;  // the extent is below the patch
    placements.push_back(p);
    queries.push_back(q);
  }
  const auto results = runQueries(queries);
  int checked = 0;
  for (size_t i = 0; i < placements.size(); ++i) {
    const Placement& p = placements[i];
    const glm::vec4 e = results[i].extent;
    const glm::dvec3 view = toLightView(p, p.wsReceiver);
    const glm::dvec3 origin = p.light.center - p.zLight * p.light.forward;
    const auto world = [&](double x, double y) {
      return origin + x * p.light.right + y * p.light.up + view.z * p.light.forward;
    };
    const double eps = 1e-3 * (1.0 + std::max(e.z - e.x, e.w - e.y));
    const double mx = 0.5 * (e.x + e.z), my = 0.5 * (e.y + e.w);
    const glm::dvec2 sides[4][2] = {{{e.x - eps, my}, {e.x + eps, my}},
                                    {{e.z + eps, my}, {e.z - eps, my}},
                                    {{mx, e.y - eps}, {mx, e.y + eps}},
                                    {{mx, e.w + eps}, {mx, e.w - eps}}};
    for (const auto& side : sides) {
      EXPECT_EQ(hiddenFraction(p.light, p.patch, world(side[0].x, side[0].y)), 0.0)
          << "placement " << i << ": hidden just outside the extent";
      EXPECT_GT(hiddenFraction(p.light, p.patch, world(side[1].x, side[1].y)), 0.0)
          << "placement " << i << ": nothing hidden just inside the extent";
      ++checked;
    }
  }
  EXPECT_EQ(checked, 16000);
}
