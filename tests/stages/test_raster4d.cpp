// Stage `raster4d` (Wang et al. 2020) against an independent oracle, Embree: the reference
// with `uniform` sampling traces exactly raster4d's light samples (cell centres), so every
// (pixel, light sample) bit must agree but for ties at edges (docs/raster4d.md: >= 99.99%). The
// paper's optimizations are toggles that must not change a single bit.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "reference/reference_request.h"
#include "reference/reference_trace.h"
#include "scene/scene_builtin.h"
#include "scene/scene_stress.h"
#include "support/gl_test.h"
#include "support/temp_directory.h"

namespace {

constexpr int kWidth = 128, kHeight = 96;

std::vector<std::string> raster4dSets(int m, std::vector<std::string> more = {}) {
  more.push_back("raster4d.enabled=true");
  more.push_back("raster4d.samples=" + std::to_string(m));
  return more;
}

// Every bit of the masks (m rows of ceil(m / 32) words per pixel, GL pixel order).
std::vector<std::uint32_t> readMasks(const PipelineRun& run) {
  const GlBuffer& masks = *run.frame->buffers.at("raster4d.masks");
  GLint64 bytes = 0;
  glGetNamedBufferParameteri64v(masks.id(), GL_BUFFER_SIZE, &bytes);
  std::vector<std::uint32_t> words(size_t(bytes) / 4);
  glGetNamedBufferSubData(masks.id(), 0, bytes, words.data());
  return words;
}

bool maskBit(const std::vector<std::uint32_t>& masks, size_t pixel, int m, int row, int column) {
  const int words = (m + 31) / 32;
  const std::uint32_t word = masks[(pixel * m + row) * words + column / 32];
  return (word >> (column % 32)) & 1u;
}

// Why a bit differs: the segment from `origin` to `target` against every occluder triangle in
// double precision (Moller-Trumbore); the largest margin min(u, v, 1 - u - v) over the
// triangles it crosses between its ends. A hit by more than round-off means a real miss by
// one side; a margin within ~1e-6 of 0 means the segment grazes an edge or vertex (a tie).
double closestHitMargin(const Scene& scene, const glm::dvec3& origin, const glm::dvec3& target) {
  double best = -INFINITY;
  const glm::dvec3 direction = target - origin;
  for (const SceneObject& object : scene.objects) {
    if (object.receiverOnly) continue;
    const Mesh& mesh = object.mesh;
    for (size_t t = 0; t < mesh.indices.size(); t += 3) {
      const glm::dvec3 a(mesh.positions[mesh.indices[t]]), b(mesh.positions[mesh.indices[t + 1]]),
          c(mesh.positions[mesh.indices[t + 2]]);
      const glm::dvec3 e1 = b - a, e2 = c - a, q = glm::cross(direction, e2);
      const double det = glm::dot(e1, q);
      if (std::fabs(det) < 1e-300) continue;
      const glm::dvec3 s = origin - a, r = glm::cross(s, e1);
      const double u = glm::dot(s, q) / det, v = glm::dot(direction, r) / det;
      const double along = glm::dot(e2, r) / det;
      if (along <= 0 || along >= 1) continue;
      best = std::max(best, std::min({u, v, 1 - u - v}));
    }
  }
  return best;
}

struct Agreement {
  double pairs = 0, onlyRaster4d = 0, onlyEmbree = 0;  // occluded for one of the two only
  double both = 0;                                      // occluded for both
  int pixels = 0, behindLight = 0;
  double rate() const { return pairs > 0 ? 1.0 - (onlyRaster4d + onlyEmbree) / pairs : 0.0; }
};

// Compares raster4d's masks with the reference's rays, pixel by pixel and sample by sample.
Agreement compareWithEmbree(const std::string& scene, int m, int width = kWidth,
                            int height = kHeight) {
  PipelineRun run(makeBuiltinScene(scene), raster4dSets(m), width, height);
  const std::vector<std::uint32_t> masks = readMasks(run);
  const ReferenceRequest request = makeReferenceRequest(*run.frame, run.frame->texture("gbuffer.wsPosition"),
                                                        run.frame->texture("gbuffer.wsNormal"), m,
                                                        /*stratified=*/false);
  const ReferenceTracer tracer(run.scene);
  const glm::vec3 centre = run.scene.light.center, forward = run.frame->light.forward;
  const Bounds bounds = run.scene.bounds();  // raster4d's nearest depth (plane.w)
  const float diagonal = glm::length(bounds.max - bounds.min);
  Agreement agreement;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const size_t i = size_t(y) * width + x;
      const float* p = &request.wsPosition[4 * i];
      const float* n = &request.wsNormal[4 * i];
      if (p[3] <= 0) continue;
      const glm::vec3 position(p[0], p[1], p[2]), normal(n[0], n[1], n[2]);
      const float offset = referenceOriginOffset(request, position);
      if (glm::dot(position + offset * normal - centre, forward) <= kRelativeEpsilon * diagonal) {
        ++agreement.behindLight;  // raster4d: unlit; not a question of bits
        continue;
      }
      const std::vector<std::uint8_t> blocked = tracer.blockedSamples(request, position, normal, x, y);
      ++agreement.pixels;
      for (int k = 0; k < m * m; ++k) {
        const bool raster4d = maskBit(masks, i, m, k / m, k % m), embree = blocked[size_t(k)] != 0;
        agreement.pairs += 1;
        agreement.onlyRaster4d += raster4d && !embree;
        agreement.onlyEmbree += embree && !raster4d;
        agreement.both += embree && raster4d;
        if (raster4d != embree && agreement.onlyRaster4d + agreement.onlyEmbree <= 5) {
          const float u = (float(k % m) + 0.5f) / float(m), v = (float(k / m) + 0.5f) / float(m);
          const glm::vec3 sample = request.wsLightCenter +
                                   (2 * u - 1) * request.halfWidth * request.wsLightRight +
                                   (2 * v - 1) * request.halfHeight * request.wsLightUp;
          std::printf("  pixel (%d, %d) sample (row %d, column %d): occluded for %s; the closest "
                      "triangle's barycentric margin %.3g\n",
                      x, height - 1 - y, k / m, k % m, raster4d ? "raster4d" : "Embree",
                      closestHitMargin(run.scene, glm::dvec3(position + offset * normal),
                                       glm::dvec3(sample)));
        }
      }
    }
  std::printf("%s m=%d: %d pixels, %.0f (pixel, sample) pairs, %.0f occluded for both; occluded "
              "for raster4d only %.0f, for Embree only %.0f (equal on %.6f); %d behind the light "
              "plane\n",
              scene.c_str(), m, agreement.pixels, agreement.pairs, agreement.both,
              agreement.onlyRaster4d, agreement.onlyEmbree, agreement.rate(), agreement.behindLight);
  return agreement;
}

TEST(Raster4d, SameBitsAsEmbreeOnCube) {
  const Agreement a = compareWithEmbree("cube", 32);
  EXPECT_GT(a.pixels, 1000);
  EXPECT_GE(a.rate(), 0.9999);
}

TEST(Raster4d, SameBitsAsEmbreeOnSpheres) {
  const Agreement a = compareWithEmbree("spheres", 32);
  EXPECT_GT(a.pixels, 1000);
  EXPECT_GE(a.rate(), 0.9999);
}

TEST(Raster4d, SameBitsAsEmbreeOnEngine) {
  const Agreement a = compareWithEmbree("engine", 32);
  EXPECT_GT(a.pixels, 1000);
  EXPECT_GE(a.rate(), 0.9999);
}

// The Stanford dragon (91,216 triangles, thesis Fig 4.1) at a small eye: its fine mesh
// has the most shared edges and vertices for a ray to graze.
TEST(Raster4d, SameBitsAsEmbreeOnDragon) {
  const Agreement a = compareWithEmbree("dragon", 32, 64, 48);
  EXPECT_GT(a.pixels, 1000);
  EXPECT_GT(a.both, 0.03 * a.pairs);  // the view holds a real shadow, not only lit pairs
  EXPECT_GE(a.rate(), 0.9999);
}

// The smallest grid, and the widest (64 columns: two words per row, k = 32 and 64 split
// columns); on the plate, whose shadow edges cross every column.
TEST(Raster4d, SameBitsAsEmbreeAt8And64Samples) {
  EXPECT_GE(compareWithEmbree("plate", 8).rate(), 0.9999);
  EXPECT_GE(compareWithEmbree("plate", 64, 64, 48).rate(), 0.9999);
  EXPECT_GE(compareWithEmbree("cube", 64, 64, 48).rate(), 0.9999);
}

// The paper's optimizations change the work, never the answer: every toggle, and lists
// split into bands of FB rows, give the same masks bit for bit.
TEST(Raster4d, OptimizationsAndBandsDoNotChangeABit) {
  for (int m : {16, 33}) {
    PipelineRun base(makeBuiltinScene("spheres"), raster4dSets(m), 64, 48);
    const std::vector<std::uint32_t> expected = readMasks(base);
    const double considered = base.frame->counters.at("raster4d.pairsConsidered");
    const double kept = base.frame->counters.at("raster4d.pairsKept");
    EXPECT_LT(kept, considered);  // the early rejection rejects something here
    EXPECT_LE(base.frame->counters.at("raster4d.pairsOccluding"), kept);
    EXPECT_EQ(base.frame->counters.at("raster4d.samplesStored"),
              base.frame->counters.at("raster4d.receivers"));  // Algorithm 2: one pixel each
    for (const std::vector<std::string>& toggle : std::vector<std::vector<std::string>>{
             {"raster4d.row_masks=false"},
             {"raster4d.row_culling=false"},
             {"raster4d.early_rejection=false"},
             {"raster4d.sample_assignment=proj4"},
             {"raster4d.max_entries=2000"},
             {"raster4d.fb_resolution=16"}}) {
      PipelineRun run(makeBuiltinScene("spheres"), raster4dSets(m, toggle), 64, 48);
      EXPECT_EQ(readMasks(run), expected) << toggle[0] << " m=" << m;
      const auto& c = run.frame->counters;
      if (toggle[0] == "raster4d.early_rejection=false") {
        EXPECT_EQ(c.at("raster4d.pairsKept"), c.at("raster4d.pairsConsidered"));
      } else if (toggle[0] == "raster4d.sample_assignment=proj4") {
        EXPECT_GT(c.at("raster4d.samplesStored"), c.at("raster4d.receivers"));
      } else if (toggle[0] == "raster4d.max_entries=2000") {
        EXPECT_GT(c.at("raster4d.bands"), 1);
      }
    }
  }
}

// The per-step times follow the pipeline's timing method (decision 021): with timer queries
// (forced here on llvmpipe) GL_TIMESTAMP results written by the GPU into a buffer and read
// after the frame; the masks are the same whichever way the steps were timed, and bands of
// FB rows (more than one slot of the plan) time every slot's steps.
TEST(Raster4d, StepTimesFromTimerQueriesAreReadAfterTheFrame) {
  PipelineRun finish(makeBuiltinScene("spheres"), raster4dSets(16, {"raster4d.max_entries=1024"}), 64, 48);
  PipelineRun queries(makeBuiltinScene("spheres"), raster4dSets(16, {"raster4d.max_entries=1024"}), 64, 48);
  queries.pipeline->setTiming(Pipeline::Timing::Queries);
  queries.run();
  EXPECT_EQ(readMasks(queries), readMasks(finish));
  const auto& c = queries.frame->counters;
  EXPECT_GT(c.at("raster4d.bands"), 1);
  EXPECT_EQ(c.at("raster4d.bands"), finish.frame->counters.at("raster4d.bands"));
  for (const char* step : {"raster4d.step2Ms", "raster4d.step3Ms", "raster4d.step4Ms",
                           "raster4d.step5Ms", "raster4d.resolveMs"})
    EXPECT_TRUE(std::isfinite(c.at(step)) && c.at(step) >= 0) << step;
}

// Finite and in [0, 1] everywhere, on every built-in and stress scene.
TEST(Raster4d, VisibilityFiniteAndInRangeOnEveryScene) {
  std::vector<std::pair<std::string, Scene>> scenes;
  for (const std::string& name : builtinSceneNames()) scenes.emplace_back(name, makeBuiltinScene(name));
  for (const std::string& name : stressSceneNames()) scenes.emplace_back(name, makeStressScene(name));
  for (auto& [name, scene] : scenes) {
    PipelineRun run(std::move(scene), raster4dSets(16), 96, 72);
    size_t bad = 0;
    for (float v : run.read("raster4d.visibility")) bad += !(std::isfinite(v) && v >= 0 && v <= 1);
    EXPECT_EQ(bad, 0u) << name;
  }
}

// The error stage against either ground truth: raster4d against Embree at the same samples
// is black but for ties (at most one light sample per pixel); the trace's error can be
// measured against raster4d without the CPU reference.
TEST(Raster4d, ErrorStageComparesWithEitherGroundTruth) {
  const TempDirectory cache("penumbra-raster4d-cache");
  setenv("PENUMBRA_CACHE", cache.path().c_str(), 1);
  PipelineRun black(makeBuiltinScene("spheres"),
                    {"raster4d.enabled=true", "raster4d.samples=16", "reference.enabled=true", "reference.cache=false",
                     "reference.sampling=uniform", "reference.samples=16",
                     "error.method=raster4d", "error.against=reference"},
                    kWidth, kHeight);
  EXPECT_GT(black.frame->counters.at("error.pixels"), 1000);
  EXPECT_LE(black.frame->counters.at("error.max"), 1.0 / 256 + 1e-6);
  PipelineRun trace(makeBuiltinScene("spheres"),
                    {"raster4d.enabled=true", "error.method=trace", "error.against=raster4d"},
                    kWidth, kHeight);
  EXPECT_GT(trace.frame->counters.at("error.rmse"), 0);
  EXPECT_LT(trace.frame->counters.at("error.rmse"), 0.2);
}

// Bad parameter values are refused by --set with the valid range.
TEST(Raster4d, ParameterRangesAreChecked) {
  headlessContext();
  Pipeline pipeline;
  EXPECT_NE(pipeline.set("raster4d.samples=65"), "");
  EXPECT_NE(pipeline.set("raster4d.samples=4"), "");
  EXPECT_NE(pipeline.set("raster4d.fb_resolution=0"), "");
  EXPECT_NE(pipeline.set("raster4d.sample_assignment=L1"), "");
  EXPECT_EQ(pipeline.set("raster4d.samples=64"), "");
}

// Off (the default), it leaves no output behind, so nothing compares against a stale truth.
TEST(Raster4d, DisabledWritesNothing) {
  PipelineRun run(makeBuiltinScene("cube"), raster4dSets(16), 64, 48);
  EXPECT_TRUE(run.frame->has("raster4d.visibility"));
  run.pipeline->set("raster4d.enabled=false");
  run.run();
  EXPECT_FALSE(run.frame->has("raster4d.visibility"));
  EXPECT_FALSE(run.frame->has("error.signed"));  // truth reference is off too
}

}  // namespace
