// The Monte Carlo estimate (thesis §3.1) against dense visibility through the same layers
// (the exact traversal of tests/support/layer_oracle.h over a 32 x 32 grid of light
// samples): unbiased at 1 ray per pixel, converging as rays grow.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <map>

#include "scene/scene_builtin.h"
#include "support/gl_test.h"
#include "support/layer_oracle.h"
#include "shared/classes.h"

namespace {

constexpr int kEye = 48;
// The oracle's ray model has one bias per receiver along the ray and no normal test, so
// the stage runs with the same: constant bias, no Eq 3.2, no back-face early out.
const std::vector<std::string> kSameModel = {
    "light.resolution=256", "light.adaptive_bias=false", "light.bias=0.01",
    "light.normal_offset=0", "trace.early_out_backface=false", "light.layers=two"};
constexpr float kBias = 0.01f;

struct Dense {
  std::vector<float> visibility;  // per eye pixel (GL order); -1 where not a traced receiver
};

const Dense& denseOf(const std::string& scene) {
  static std::map<std::string, Dense> cache;
  if (cache.count(scene)) return cache.at(scene);
  const Dense dense = [&] {
    PipelineRun run(makeBuiltinScene(scene), kSameModel, kEye, kEye);
    const GlTexture& nearLayer = run.frame->texture("light_layers.near");
    const LayerMaps maps{nearLayer.width(), nearLayer.height(), run.read("light_layers.near"),
                         run.read("light_layers.far")};
    const auto positions = run.read("gbuffer.wsPosition");
    const auto mask = run.read("classify.mask");
    Dense result{std::vector<float>(kEye * kEye, -1.0f)};
    for (int i = 0; i < kEye * kEye; ++i) {
      if (positions[i * 4 + 3] == 0 || mask[i] == CLASS_OUTSIDE) continue;
      const glm::vec3 p{positions[i * 4], positions[i * 4 + 1], positions[i * 4 + 2]};
      result.visibility[i] = denseVisibility(maps, run.frame->light, run.scene.light, p, kBias, 32, 2);
    }
    return result;
  }();
  return cache[scene] = dense;
}

std::vector<float> traced(const std::string& scene, const std::vector<std::string>& extra,
                          std::uint32_t key) {
  auto sets = kSameModel;
  sets.insert(sets.end(), extra.begin(), extra.end());
  PipelineRun run(makeBuiltinScene(scene), sets, kEye, kEye);
  run.frame->frameKey = key;
  run.run();
  return run.read("trace.visibility");
}

double rmse(const std::vector<float>& estimate, const Dense& dense) {
  double sum = 0;
  int count = 0;
  for (size_t i = 0; i < estimate.size(); ++i) {
    if (dense.visibility[i] < 0) continue;
    sum += std::pow(double(estimate[i]) - dense.visibility[i], 2);
    ++count;
  }
  return std::sqrt(sum / count);
}

}  // namespace

// Each ray is a Bernoulli trial with mean = the fraction of the light visible, so the mean
// over 64 frame keys lies within 3 standard errors of the dense value on >= 99% of pixels.
// The dense value itself has a grid resolution of 1/1024, which floors p(1-p). `plate` is
// a zero-thickness occluder (near == far): the case ray shortening once got wrong.
class TraceMonteCarloScenes : public ::testing::TestWithParam<const char*> {};

TEST_P(TraceMonteCarloScenes, OneRayIsUnbiased) {
  const std::string param = GetParam();  // "scene" or "scene:search"
  const std::string scene = param.substr(0, param.find(':'));
  const std::string search =
      param.find(':') == std::string::npos ? "hierarchical" : param.substr(param.find(':') + 1);
  const Dense& dense = denseOf(scene);
  std::vector<double> mean(kEye * kEye, 0.0);
  const int keys = 64;
  for (int key = 0; key < keys; ++key) {
    const auto v = traced(scene, {"trace.rays=1", "trace.sampling=random", "trace.search=" + search},
                          std::uint32_t(key) * 7919u + 1u);
    for (size_t i = 0; i < v.size(); ++i) mean[i] += v[i] / keys;
  }
  int pixels = 0, within = 0, penumbra = 0;
  for (size_t i = 0; i < mean.size(); ++i) {
    const double p = dense.visibility[i];
    if (p < 0) continue;
    ++pixels;
    penumbra += p > 0 && p < 1;
    const double variance = std::max(p * (1 - p), (1.0 / 1024) * (1 - 1.0 / 1024));
    const double standardError = std::sqrt(variance / keys);
    if (std::fabs(mean[i] - p) <= 3 * standardError) ++within;
    else std::printf("  pixel %zu: mean of 64 keys %.4f, dense %.4f (3 SE = %.4f)\n", i, mean[i], p,
                     3 * standardError);
  }
  std::printf("%s: %d of %d receiver pixels within 3 SE (%d in penumbra)\n", param.c_str(),
              within, pixels, penumbra);
  EXPECT_GT(penumbra, 100);
  EXPECT_GE(within, 0.99 * pixels);
}

INSTANTIATE_TEST_SUITE_P(Scenes, TraceMonteCarloScenes, ::testing::Values("cube", "plate", "spheres",
                                                                     "plate:linear_binary"));

// Error against the dense visibility falls like 1/sqrt(rays) for random sampling, and at
// least as fast for the jittered grid (stratification, §3.1, Fig 3.3).
TEST(TraceMonteCarlo, ErrorFallsWithRays) {
  const Dense& dense = denseOf("cube");
  std::printf("rays   RMSE jittered   RMSE random\n");
  std::map<std::string, std::vector<double>> errors;
  for (int n : {1, 2, 3, 4, 8}) {
    for (const char* sampling : {"jittered", "random"})
      errors[sampling].push_back(rmse(traced("cube", {"trace.rays=" + std::to_string(n),
                                             std::string("trace.sampling=") + sampling}, 12345u),
                                      dense));
    std::printf("%4d   %13.5f   %11.5f\n", n * n, errors["jittered"].back(), errors["random"].back());
  }
  for (const auto& [sampling, e] : errors)
    for (size_t i = 1; i < e.size(); ++i) EXPECT_LT(e[i], e[i - 1]) << sampling;
  // 1 -> 64 rays: 1/sqrt(64) = 1/8 for independent samples; allow a factor 2 either way.
  const double randomRatio = errors["random"].back() / errors["random"].front();
  EXPECT_GT(randomRatio, 1.0 / 16);
  EXPECT_LT(randomRatio, 1.0 / 4);
  EXPECT_LT(errors["jittered"].back(), errors["jittered"].front() / 4);
  EXPECT_LE(errors["jittered"].back(), errors["random"].back() * 1.1);
}
