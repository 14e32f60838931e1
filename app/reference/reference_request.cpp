#include "reference/reference_request.h"

ReferenceRequest makeReferenceRequest(const Frame& frame, const GlTexture& wsPosition,
                                      const GlTexture& wsNormal, int samplesPerSide,
                                      bool stratified) {
  ReferenceRequest request;
  request.width = frame.eyeWidth;
  request.height = frame.eyeHeight;
  request.wsPosition = wsPosition.readFloats();
  request.wsNormal = wsNormal.readFloats();
  request.samplesPerSide = samplesPerSide;
  request.stratified = stratified;
  request.wsLightCenter = frame.scene.light.center;
  request.wsLightRight = frame.light.right;  // orthonormal, as the trace's light samples
  request.wsLightUp = frame.light.up;
  request.halfWidth = 0.5f * frame.scene.light.width;
  request.halfHeight = 0.5f * frame.scene.light.height;
  // Only the occluders are in the Embree scene (reference_trace.h, "Origin").
  request.relativeEpsilon = kRelativeEpsilon;
  request.minimumEpsilon = referenceMinimumOffset(frame.scene);
  return request;
}
