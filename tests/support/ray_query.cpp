#include "ray_query.h"

#include "gl_test.h"
#include "shared_inputs/minmax/minmax_build.h"
#include "gl/nbuffer_build.h"
#include "gl/shader_program.h"

RayQueryRunner::RayQueryRunner(int width, int height, const std::vector<float>& nearLayer,
                               const std::vector<float>& farLayer, float zNear, float zFar)
    : width_(width), height_(height), zNear_(zNear), zFar_(zFar) {
  headlessContext();
  near_ = GlTexture(GL_DEPTH_COMPONENT32F, width, height);
  far_ = GlTexture(GL_R32F, width, height);  // as the pipeline's far layer: the trace reads it as an image
  glTextureSubImage2D(near_.id(), 0, 0, 0, width, height, GL_DEPTH_COMPONENT, GL_FLOAT,
                      nearLayer.data());
  glTextureSubImage2D(far_.id(), 0, 0, 0, width, height, GL_RED, GL_FLOAT, farLayer.data());
  levels_ = GlTexture(GL_RGBA32F, width, height, nbufferLevelCount(width, height));
  buildNBuffer(near_, far_, levels_);
  minmax_ = buildMinMaxLevels(near_, far_);
}

std::vector<RayQueryOutcome> RayQueryRunner::run(const std::vector<gpu::RayQuery>& queries,
                                                 int search, int layers, float linearStep,
                                                 int binarySteps, int maxIterations) {
  static ShaderProgram program{{{GL_COMPUTE_SHADER, "tests/ray_query.comp"}}};
  gpu::LightUniforms light{};
  light.lightDepthRange = {zNear_, zFar_, 1, 1};
  light.mapSize = {width_, height_, 0, 0};
  light.bias = {0, 0, 0.1f, 0};
  gpu::TraceParams trace{};
  trace.config = {1, 0, search, layers};
  trace.limits = {maxIterations, binarySteps, hierarchy_, 0};
  trace.stepping = {linearStep, 0, 0, 0};
  trace.record = {-1, -1, 0,
                  hierarchy_ == HIERARCHY_MINMAX ? minmaxTopLevel(width_, height_)
                                                 : levels_.layers() - 1};
  GlBuffer lightBuffer, traceBuffer, records, totals, queryBuffer, resultBuffer;
  lightBuffer.upload(&light, sizeof light);
  traceBuffer.upload(&trace, sizeof trace);
  std::vector<std::uint32_t> zeros(64, 0);
  records.upload(zeros.data(), zeros.size() * 4);
  totals.upload(zeros.data(), zeros.size() * 4);
  queryBuffer.upload(queries.data(), queries.size() * sizeof(gpu::RayQuery));
  std::vector<gpu::RayQueryResult> results(queries.size());
  resultBuffer.upload(results.data(), results.size() * sizeof(gpu::RayQueryResult));
  glBindBufferBase(GL_UNIFORM_BUFFER, binding::kLightUniforms, lightBuffer.id());
  glBindBufferBase(GL_UNIFORM_BUFFER, binding::kTraceParams, traceBuffer.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::kTraceRecords, records.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::kTraceTotals, totals.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 2, queryBuffer.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 3, resultBuffer.id());
  glBindTextureUnit(TRACE_NEAR_UNIT, near_.id());
  bindTextureForReading(TRACE_FAR_UNIT, far_);
  bindTextureForReading(TRACE_LEVELS_UNIT, levels_);
  bindTextureForReading(TRACE_MINMAX_UNIT, minmax_);
  program.use();
  glUniform1i(0, int(queries.size()));
  glUniform1i(1, earlyOuts_);
  glDispatchCompute(GLuint((queries.size() + 63) / 64), 1, 1);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  glGetNamedBufferSubData(resultBuffer.id(), 0, GLsizeiptr(results.size() * sizeof(gpu::RayQueryResult)),
                          results.data());
  std::vector<RayQueryOutcome> outcomes;
  outcomes.reserve(results.size());
  for (const auto& result : results)
    outcomes.push_back({(result.outcome.x & 1u) != 0, result.outcome.y, result.outcome.z,
                        result.outcome.w, result.outcome.x >> 1});
  return outcomes;
}
