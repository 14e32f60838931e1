// The exact reference (stage `reference`, app/reference_*.h) and the error stage, against
// independent oracles: the analytic visibility of parallel rectangles on `plate`, brute
// force metrics, and the cache's key and files.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <thread>
#include <tuple>

#include "reference/error_metrics.h"
#include "reference/reference_cache.h"
#include "reference/reference_request.h"
#include "reference/reference_trace.h"
#include "scene/scene_builtin.h"
#include "support/gl_test.h"
#include "support/temp_directory.h"

namespace {

// A private, empty cache directory for one test (the cache is per user otherwise), removed
// when the test ends.
struct ScopedCache {
  TempDirectory scratch;
  const std::filesystem::path directory = scratch.path() / "cache";
  explicit ScopedCache(const std::string& name) : scratch("penumbra-test-cache-" + name) {
    setenv("PENUMBRA_CACHE", directory.c_str(), 1);
  }
};

// Overlap of [a0, a1] and [b0, b1].
double overlap(double a0, double a1, double b0, double b1) {
  return std::max(0.0, std::min(a1, b1) - std::max(a0, b0));
}

// `plate`: light [-0.5, 0.5]^2 at y = 3, plate [-0.5, 0.5]^2 at y = 1, both parallel to the
// ground. Seen from a ground point p, the plate projects onto the light plane as the square
// scaled by (3 - p.y) / (1 - p.y) about p. Per axis, in light units u in [0, 1] (u = x + 0.5
// or z + 0.5; the light's own orientation does not matter, every formula below is symmetric
// under u -> 1 - u), the projection covers [lo, hi]; the light is covered by the product.
struct PlateProjection {
  double lo[2], hi[2];  // x, z
};

PlateProjection project(const glm::dvec3& p) {
  const double scale = (3.0 - p.y) / (1.0 - p.y);
  PlateProjection r;
  for (int axis = 0; axis < 2; ++axis) {
    const double origin = axis == 0 ? p.x : p.z;
    r.lo[axis] = std::clamp(origin + scale * (-0.5 - origin) + 0.5, 0.0, 1.0);
    r.hi[axis] = std::clamp(origin + scale * (0.5 - origin) + 0.5, 0.0, 1.0);
  }
  return r;
}

// 1. The exact visibility: 1 - area(light n projection) / area(light).
double exactVisibility(const PlateProjection& r) {
  return 1.0 - (r.hi[0] - r.lo[0]) * (r.hi[1] - r.lo[1]);
}

// 2. Cell centres ((i + 0.5) / m): the count inside [lo, hi] per axis, exactly; `ambiguous`
//    when a centre lies within float round-off of an edge.
double uniformGridVisibility(const PlateProjection& r, int m, bool& ambiguous) {
  double inside[2] = {0, 0};
  for (int axis = 0; axis < 2; ++axis)
    for (int i = 0; i < m; ++i) {
      const double c = (i + 0.5) / m;
      if (std::fabs(c - r.lo[axis]) < 1e-4 || std::fabs(c - r.hi[axis]) < 1e-4) ambiguous = true;
      inside[axis] += c >= r.lo[axis] && c <= r.hi[axis];
    }
  return 1.0 - inside[0] * inside[1] / (double(m) * m);
}

// 3. Stratified sampling with one uniform sample per cell: each cell is a Bernoulli of its
//    covered fraction (product of the per-axis fractions), so the estimate's standard
//    deviation is sqrt(sum f (1 - f)) / m^2 and its mean is the exact visibility.
double stratifiedSigma(const PlateProjection& r, int m) {
  double variance = 0;
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < m; ++j) {
      const double f = overlap(r.lo[0], r.hi[0], double(i) / m, double(i + 1) / m) * m *
                       overlap(r.lo[1], r.hi[1], double(j) / m, double(j + 1) / m) * m;
      variance += f * (1 - f);
    }
  return std::sqrt(variance) / (double(m) * m);
}

struct PlatePixel {
  glm::dvec3 p;
  double reference;
};

// The ground pixels of `plate` and their reference visibility.
std::vector<PlatePixel> platePixels(const std::string& sampling, int m) {
  const ScopedCache cache("plate");
  PipelineRun run(makeBuiltinScene("plate"),
                  {"reference.enabled=true", "reference.cache=false",
                   "reference.sampling=" + sampling, "reference.samples=" + std::to_string(m)},
                  160, 120);
  const auto positions = run.read("gbuffer.wsPosition");
  const auto reference = run.read("reference.visibility");
  std::vector<PlatePixel> pixels;
  for (size_t i = 0; i < reference.size(); ++i) {
    const glm::dvec3 p{positions[4 * i], positions[4 * i + 1], positions[4 * i + 2]};
    if (positions[4 * i + 3] == 0 || std::fabs(p.y) > 1e-3) continue;  // ground pixels only
    pixels.push_back({p, reference[i]});
  }
  return pixels;
}

}  // namespace

// Uniform grid: the reference is the exact count of cell centres the projection leaves
// uncovered, pixel by pixel (and within 2/m of the exact area).
// The pixels an error counts (the error stage and a lesson crop's numbers share the rule):
// classes 0 (background) and 4 (outside the map) never; with the receivers flag, only
// flagged pixels.
TEST(ErrorMetrics, CountedPixelsFollowTheMaskAndTheReceiversFlag) {
  const std::vector<float> mask = {0, 1, 2, 3, 4, 2};
  EXPECT_EQ(countedPixels(mask), (std::vector<std::uint8_t>{0, 1, 1, 1, 0, 1}));
  const std::vector<float> flag = {1, 1, 0, 1, 1, 0};
  EXPECT_EQ(countedPixels(mask, &flag), (std::vector<std::uint8_t>{0, 1, 0, 1, 0, 0}));
  const std::vector<float> shortFlag = {1};
  EXPECT_THROW(countedPixels(mask, &shortFlag), std::invalid_argument);
}

TEST(Reference, PlateUniformGridEqualsTheCellCentreCount) {
  const int m = 16;
  int penumbra = 0, umbra = 0, compared = 0;
  for (const PlatePixel& pixel : platePixels("uniform", m)) {
    const PlateProjection r = project(pixel.p);
    const double exact = exactVisibility(r);
    penumbra += exact > 0 && exact < 1;
    umbra += exact == 0;
    EXPECT_LE(std::fabs(pixel.reference - exact), 2.0 / m + 1e-4);
    bool ambiguous = false;
    const double counted = uniformGridVisibility(r, m, ambiguous);
    if (ambiguous) continue;
    ++compared;
    ASSERT_NEAR(pixel.reference, counted, 1e-6) << "ground point " << pixel.p.x << ", " << pixel.p.z;
  }
  EXPECT_GT(compared, 5000);
  EXPECT_GT(penumbra, 1000);  // the comparison covers penumbra and umbra, not just light
  EXPECT_GT(umbra, 200);
}

// Stratified: unbiased, with the per-pixel spread of stratified sampling. The standardized
// errors (reference - exact) / sigma have mean ~0 and RMS ~1 if the estimator is right; a
// wrong light, plate or sample placement moves them by many sigmas.
TEST(Reference, PlateStratifiedIsUnbiasedWithinTheSamplingError) {
  const int m = 16;
  double sumZ = 0, sumZ2 = 0;
  int n = 0, exactPixels = 0;
  for (const PlatePixel& pixel : platePixels("stratified", m)) {
    const PlateProjection r = project(pixel.p);
    const double error = pixel.reference - exactVisibility(r), sigma = stratifiedSigma(r, m);
    EXPECT_LE(std::fabs(error), 4.0 / m);  // <= 4m cut cells, each off by <= 1/m^2
    if (sigma < 1e-3) {  // no cell cut (up to round-off): the estimate is exact
      EXPECT_NEAR(error, 0.0, 2e-3) << "ground point " << pixel.p.x << ", " << pixel.p.z;
      ++exactPixels;
      continue;
    }
    const double z = error / sigma;
    sumZ += z;
    sumZ2 += z * z;
    ++n;
  }
  ASSERT_GT(n, 500);
  ASSERT_GT(exactPixels, 1000);
  const double meanZ = sumZ / n, rmsZ = std::sqrt(sumZ2 / n);
  std::printf("stratified m=%d: %d penumbra pixels, mean z %.3f, rms z %.3f\n", m, n, meanZ, rmsZ);
  EXPECT_LT(std::fabs(meanZ), 0.15);  // neighbouring pixels are correlated: generous
  EXPECT_GT(rmsZ, 0.5);
  EXPECT_LT(rmsZ, 1.5);
}

TEST(Reference, SameInputSameBitsWhateverTheThreadCount) {
  const ScopedCache cache("determinism");
  std::vector<std::vector<float>> images;
  for (const char* threads : {"1", "2", "3"}) {
    PipelineRun run(makeBuiltinScene("spheres"),
                    {"reference.enabled=true", "reference.cache=false", "reference.samples=8",
                     std::string("reference.threads=") + threads}, 96, 80);
    images.push_back(run.read("reference.visibility"));
  }
  ASSERT_EQ(images[0].size(), size_t(96 * 80));
  EXPECT_EQ(std::memcmp(images[0].data(), images[1].data(), images[0].size() * 4), 0);
  EXPECT_EQ(std::memcmp(images[0].data(), images[2].data(), images[0].size() * 4), 0);
  const auto [low, high] = std::minmax_element(images[0].begin(), images[0].end());
  EXPECT_EQ(*low, 0.0f);  // umbra under the sphere on the ground...
  EXPECT_EQ(*high, 1.0f);
}

TEST(Reference, CacheHitReturnsTheSameImageAndAnyChangedInputMisses) {
  const ScopedCache cache("hits");
  const auto& directory = cache.directory;
  const std::vector<std::string> sets = {"reference.enabled=true", "reference.samples=12"};
  auto timedRun = [](PipelineRun& run, double& seconds) {
    const auto start = std::chrono::steady_clock::now();
    run.run();
    seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };
  PipelineRun first(makeBuiltinScene("cube"), sets, 128, 96);  // computes and stores
  EXPECT_EQ(first.frame->counters.at("reference.cacheHit"), 0);
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(directory / "reference"),
                          std::filesystem::directory_iterator()), 2);  // .exr + .json
  double computeSeconds = 0, memorySeconds = 0, diskSeconds = 0;
  {
    PipelineRun again(makeBuiltinScene("cube"), sets, 128, 96);
    EXPECT_EQ(again.frame->counters.at("reference.cacheHit"), 2);  // from disk
    EXPECT_EQ(again.read("reference.visibility"), first.read("reference.visibility"));
    timedRun(again, memorySeconds);
    EXPECT_EQ(again.frame->counters.at("reference.cacheHit"), 1);  // from memory
  }
  {
    PipelineRun fromDisk(makeBuiltinScene("cube"), {"reference.enabled=false"}, 128, 96);
    for (const auto& set : sets) fromDisk.pipeline->set(set);
    timedRun(fromDisk, diskSeconds);
    EXPECT_EQ(fromDisk.frame->counters.at("reference.cacheHit"), 2);
  }
  {
    PipelineRun recompute(makeBuiltinScene("cube"), {"reference.enabled=false"}, 128, 96);
    for (const auto& set : sets) recompute.pipeline->set(set);
    recompute.pipeline->set("reference.cache=false");
    timedRun(recompute, computeSeconds);
    EXPECT_EQ(recompute.frame->counters.at("reference.cacheHit"), 0);
  }
  // Reported, not asserted (no timed assertions): the whole frame with each kind of hit.
  std::printf("frame with reference: computed %.3f s, disk hit %.3f s, memory hit %.3f s\n",
              computeSeconds, diskSeconds, memorySeconds);

  Scene moved = makeBuiltinScene("cube");
  moved.light.center.x += 0.01f;
  for (const auto& [scene, extra, w] :
       std::vector<std::tuple<Scene, std::string, int>>{{moved, "", 128},
                                                        {makeBuiltinScene("cube"), "reference.samples=13", 128},
                                                        {makeBuiltinScene("cube"), "reference.sampling=uniform", 128},
                                                        {makeBuiltinScene("cube"), "", 130}}) {
    std::vector<std::string> changed = sets;
    if (!extra.empty()) changed.push_back(extra);
    PipelineRun run(scene, changed, w, 96);
    EXPECT_EQ(run.frame->counters.at("reference.cacheHit"), 0) << extra << " width " << w;
  }
}

TEST(Reference, KeyDependsOnEveryInput) {
  headlessContext();
  const Scene scene = makeBuiltinScene("cube");
  ReferenceRequest base;
  base.width = 4;
  base.height = 2;
  base.wsPosition.assign(32, 0.5f);
  base.wsNormal.assign(32, 0.25f);
  const std::string key = referenceCacheKey(scene, base);
  EXPECT_EQ(key, referenceCacheKey(scene, base));
  EXPECT_EQ(key.size(), 32u);
  auto differs = [&](auto change) {
    Scene s = scene;
    ReferenceRequest r = base;
    change(s, r);
    return referenceCacheKey(s, r) != key;
  };
  EXPECT_TRUE(differs([](Scene&, ReferenceRequest& r) { r.samplesPerSide = 17; }));
  EXPECT_TRUE(differs([](Scene&, ReferenceRequest& r) { r.stratified = false; }));
  EXPECT_TRUE(differs([](Scene&, ReferenceRequest& r) { r.wsPosition[31] = 0.0f; }));
  EXPECT_TRUE(differs([](Scene&, ReferenceRequest& r) { r.wsNormal[0] = 1.0f; }));
  EXPECT_TRUE(differs([](Scene&, ReferenceRequest& r) { r.halfWidth *= 2; }));
  EXPECT_TRUE(differs([](Scene& s, ReferenceRequest&) { s.light.center.y += 1e-3f; }));
  EXPECT_TRUE(differs([](Scene& s, ReferenceRequest&) { s.camera.fovYDegrees += 1; }));
  EXPECT_TRUE(differs([](Scene& s, ReferenceRequest&) { s.objects[1].mesh.positions[0].x += 1e-4f; }));
  EXPECT_TRUE(differs([](Scene& s, ReferenceRequest&) { s.objects[0].receiverOnly = false; }));
}

TEST(Reference, CancelStopsAndReportsIt) {
  headlessContext();
  ReferenceTracer tracer(makeBuiltinScene("cube"));
  EXPECT_EQ(tracer.occluderTriangles(), 12u);  // the box; the receiver-only ground is out
  ReferenceRequest request;
  request.width = request.height = 64;
  request.wsPosition.assign(64 * 64 * 4, 0.0f);
  request.wsNormal.assign(64 * 64 * 4, 0.0f);
  for (size_t i = 0; i < 64 * 64; ++i) {
    request.wsPosition[4 * i + 3] = 1;
    request.wsNormal[4 * i + 1] = 1;
  }
  ReferenceProgress progress;
  progress.cancel = true;
  std::vector<float> visibility;
  EXPECT_FALSE(tracer.trace(request, visibility, &progress, 2));
  EXPECT_LT(progress.tilesDone.load(), 16);  // 4 x 4 tiles of 16 x 16
  progress.cancel = false;
  EXPECT_TRUE(tracer.trace(request, visibility, &progress, 2));
  EXPECT_EQ(progress.tilesDone.load(), 16);
}

TEST(Reference, BackgroundModeWritesTheSameImageWhenDone) {
  const ScopedCache cache("background");
  const std::vector<std::string> sets = {"reference.enabled=true", "reference.cache=false",
                                         "reference.samples=8"};
  PipelineRun sync(makeBuiltinScene("cube"), sets, 96, 64);
  std::vector<std::string> background = sets;
  background.push_back("reference.background=true");
  const int finishedBefore = referenceStageProgress().finished;
  PipelineRun async(makeBuiltinScene("cube"), background, 96, 64);
  EXPECT_FALSE(async.frame->has("reference.visibility"));  // pending
  EXPECT_FALSE(async.frame->has("error.signed"));
  for (int i = 0; i < 600 && referenceStageProgress().finished == finishedBefore; ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  async.run();
  ASSERT_TRUE(async.frame->has("reference.visibility"));
  EXPECT_EQ(async.read("reference.visibility"), sync.read("reference.visibility"));
}

// Independent oracle: plain loops over the pixels, against OIIO-backed computeErrorMetrics.
TEST(ErrorMetrics, MatchBruteForceOverCountedPixels) {
  const int w = 37, h = 23;
  std::vector<float> method(w * h), reference(w * h);
  std::vector<std::uint8_t> counted(w * h);
  for (int i = 0; i < w * h; ++i) {
    reference[i] = i % 5 == 0 ? 1.0f : float((i * 7) % 11) / 10.0f;
    method[i] = std::clamp(reference[i] + float((i * 13) % 9 - 4) / 17.0f, 0.0f, 1.0f);
    counted[i] = (i % 7) != 3;
  }
  method[5] = 0.0f;  // not counted below: a huge error there must not show
  counted[5] = 0;
  std::vector<float> signedError;
  const ErrorMetrics m = computeErrorMetrics(method, reference, counted, w, h, &signedError);
  double sumSq = 0, maxAbs = 0, inShadow = 0, signedSum = 0;
  int n = 0, nShadow = 0;
  std::vector<double> absolute;
  for (int i = 0; i < w * h; ++i) {
    if (!counted[i]) {
      EXPECT_EQ(signedError[i], 0.0f);
      continue;
    }
    const double e = double(method[i]) - reference[i];
    EXPECT_FLOAT_EQ(signedError[i], float(e));
    sumSq += e * e;
    signedSum += e;
    maxAbs = std::max(maxAbs, std::fabs(e));
    absolute.push_back(std::fabs(e));
    ++n;
    if (reference[i] < 1) { inShadow += std::fabs(e); ++nShadow; }
  }
  std::sort(absolute.begin(), absolute.end());
  EXPECT_EQ(m.pixels, size_t(n));
  EXPECT_EQ(m.pixelsInShadow, size_t(nShadow));
  EXPECT_NEAR(m.rmse, std::sqrt(sumSq / n), 1e-6);
  EXPECT_NEAR(m.max, maxAbs, 1e-6);
  EXPECT_NEAR(m.meanAbsInShadow, inShadow / nShadow, 1e-6);
  EXPECT_NEAR(m.meanSigned, signedSum / n, 1e-6);
  EXPECT_NEAR(m.p99, absolute[size_t(std::ceil(0.99 * n)) - 1], 1e-6);
}

TEST(ErrorStage, SignedImageIsMethodMinusReferenceOnReceiversInsideTheMap) {
  const ScopedCache cache("error");
  PipelineRun run(makeBuiltinScene("plate"),
                  {"reference.enabled=true", "reference.cache=false", "reference.samples=8",
                   "error.method=hard_shadow"}, 128, 96);
  const auto method = run.read("hard_shadow.visibility");
  const auto reference = run.read("reference.visibility");
  const auto mask = run.read("classify.mask");
  const auto signedError = run.read("error.signed");
  const auto absolute = run.read("error.absolute");
  int counted = 0;
  double maxAbs = 0;
  for (size_t i = 0; i < mask.size(); ++i) {
    const bool counts = mask[i] != 0 && mask[i] != 4;  // background, outside the map
    const float expected = counts ? method[i] - reference[i] : 0.0f;
    ASSERT_EQ(signedError[i], expected) << i;
    ASSERT_EQ(absolute[i], std::fabs(expected)) << i;
    counted += counts;
    if (counts) maxAbs = std::max(maxAbs, double(std::fabs(expected)));
  }
  const auto& counters = run.frame->counters;
  EXPECT_EQ(counters.at("error.pixels"), counted);
  EXPECT_NEAR(counters.at("error.max"), maxAbs, 1e-6);
  EXPECT_GT(counters.at("error.meanAbsInShadow"), 0.05);  // a hard shadow misses the penumbra
  for (const char* name : {"error.rmse", "error.p99", "error.meanSigned"})
    EXPECT_TRUE(std::isfinite(counters.at(name))) << name;
  // The GPU's statistics (shaders/ground_truth/error/error*.comp) against plain loops over the images: counts,
  // max and the percentile exactly (a sort, nearest rank), the sums to summation order.
  std::vector<float> absolutes;
  double sumSq = 0, sumSigned = 0, sumShadow = 0;
  int inShadow = 0;
  for (size_t i = 0; i < mask.size(); ++i) {
    if (mask[i] == 0 || mask[i] == 4) continue;
    const float e = method[i] - reference[i];
    absolutes.push_back(std::fabs(e));
    sumSq += double(e) * double(e);
    sumSigned += e;
    if (reference[i] < 1.0f) sumShadow += std::fabs(e), ++inShadow;
  }
  ASSERT_GT(absolutes.size(), 1000u);
  std::sort(absolutes.begin(), absolutes.end());
  const size_t rank = size_t(std::ceil(0.99 * double(absolutes.size()))) - 1;
  EXPECT_EQ(counters.at("error.max"), double(absolutes.back()));
  EXPECT_EQ(counters.at("error.p99"), double(absolutes[rank]));
  EXPECT_EQ(counters.at("error.pixelsInShadow"), inShadow);
  EXPECT_NEAR(counters.at("error.rmse"), std::sqrt(sumSq / double(absolutes.size())), 1e-12);
  EXPECT_NEAR(counters.at("error.meanSigned"), sumSigned / double(absolutes.size()), 1e-12);
  EXPECT_NEAR(counters.at("error.meanAbsInShadow"), sumShadow / inShadow, 1e-12);
  // Turning the reference off removes both (no stale comparison).
  run.pipeline->set("reference.enabled=false");
  run.run();
  EXPECT_FALSE(run.frame->has("reference.visibility"));
  EXPECT_FALSE(run.frame->has("error.signed"));
  EXPECT_EQ(run.frame->counters.count("error.rmse"), 0u);
}

// error.pixels = receivers (Atty et al. 2006 §4.2.1 measure on the receiver) against a
// recount from read-back buffers. On `cube` the ground (y = 0) is the one receiver-only
// object and the box (y in [0.65, 1.15]) shades its own faces, which soft shadow maps do not
// (§3). The G-buffer's world positions say which pixel shows which, independently of the
// `receivers` stage's flags.
TEST(ErrorStage, ReceiversOnlyCountsTheGroundAloneAsARecountDoes) {
  const ScopedCache cache("error-receivers");
  PipelineRun run(makeBuiltinScene("cube"),
                  {"reference.enabled=true", "reference.cache=false", "reference.samples=4",
                   "error.method=ssm", "error.pixels=all"}, 128, 96);
  const auto method = run.read("ssm.visibility");
  const auto reference = run.read("reference.visibility");
  const auto mask = run.read("classify.mask");
  const auto wsPosition = run.read("gbuffer.wsPosition");
  const auto flag = run.read("receivers.flag");
  const auto all = run.frame->counters;

  // 1. The flags are the ground's pixels, as the world positions say.
  size_t ground = 0, box = 0, countedAll = 0, countedBox = 0, n = 0, nShadow = 0, boxShadow = 0;
  double sumShadow = 0, sumBoxShadow = 0;
  for (size_t i = 0; i < mask.size(); ++i) {
    const float y = wsPosition[4 * i + 1], coverage = wsPosition[4 * i + 3];
    const bool isGround = coverage > 0 && std::fabs(y) < 1e-3f;
    const bool isBox = coverage > 0 && y > 0.5f;
    ASSERT_EQ(flag[i], isGround ? 1.0f : 0.0f) << "pixel " << i << " y " << y;
    ground += isGround, box += isBox;
    const bool counts = mask[i] != 0 && mask[i] != 4;  // background, outside the map
    countedAll += counts;
    countedBox += counts && isBox;
    const double e = std::fabs(double(method[i]) - reference[i]);
    if (counts && isBox && reference[i] < 1) ++boxShadow, sumBoxShadow += e;
    if (!counts || !isGround) continue;
    ++n;
    if (reference[i] < 1) ++nShadow, sumShadow += e;
  }
  ASSERT_GT(ground, 1000u);
  ASSERT_GT(boxShadow, 100u);  // the box's own shaded faces: what `all` counts and SSM misses
  EXPECT_EQ(all.at("error.pixels"), double(countedAll));

  // 2. Receivers only: the recount over the ground's counted pixels.
  run.pipeline->set("error.pixels=receivers");
  run.run();
  const auto& receivers = run.frame->counters;
  EXPECT_EQ(receivers.at("error.pixels"), double(n));
  EXPECT_EQ(receivers.at("error.pixels"), all.at("error.pixels") - double(countedBox));
  EXPECT_EQ(receivers.at("error.pixelsInShadow"), double(nShadow));
  EXPECT_EQ(all.at("error.pixelsInShadow"), double(nShadow + boxShadow));
  EXPECT_NEAR(receivers.at("error.meanAbsInShadow"), sumShadow / double(nShadow), 1e-6);
  // The box's faces are where SSM errs most: no self-shadowing.
  EXPECT_GT(sumBoxShadow / double(boxShadow), sumShadow / double(nShadow));
  const auto absolute = run.read("error.absolute");
  for (size_t i = 0; i < absolute.size(); ++i)
    if (flag[i] == 0.0f) {
      ASSERT_EQ(absolute[i], 0.0f) << "an occluder pixel counted: " << i;
    }
}
