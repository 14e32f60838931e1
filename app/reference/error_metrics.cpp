#include "reference/error_metrics.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace gpu {
#include "shared/classes.h"
}  // namespace gpu

ErrorMetrics computeErrorMetrics(const std::vector<float>& method,
                                 const std::vector<float>& reference,
                                 const std::vector<std::uint8_t>& counted, int width, int height,
                                 std::vector<float>* signedError) {
  const size_t n = size_t(width) * height;
  if (method.size() != n || reference.size() != n || counted.size() != n)
    throw std::invalid_argument("computeErrorMetrics: image sizes differ");
  ErrorMetrics metrics;
  // Pixels that do not count get 0 in both images, so OIIO's compare sees no difference
  // there: its max is the masked max, and its RMSE over all n pixels rescales to the RMSE
  // over the counted ones (the squared sum is the same).
  std::vector<float> a(n, 0.0f), b(n, 0.0f), absolute;
  if (signedError) signedError->assign(n, 0.0f);
  double sumSigned = 0, sumAbsInShadow = 0;
  for (size_t i = 0; i < n; ++i) {
    if (!counted[i]) continue;
    a[i] = method[i];
    b[i] = reference[i];
    const float difference = method[i] - reference[i];
    if (signedError) (*signedError)[i] = difference;
    absolute.push_back(std::fabs(difference));
    sumSigned += difference;
    if (reference[i] < 1.0f) {
      ++metrics.pixelsInShadow;
      sumAbsInShadow += std::fabs(difference);
    }
  }
  metrics.pixels = absolute.size();
  if (metrics.pixels == 0) return metrics;

  const OIIO::ImageSpec spec(width, height, 1, OIIO::TypeDesc::FLOAT);
  const OIIO::ImageBuf imageA(spec, a.data()), imageB(spec, b.data());
  const OIIO::ImageBufAlgo::CompareResults compared =
      OIIO::ImageBufAlgo::compare(imageA, imageB, /*failthresh=*/1.0f, /*warnthresh=*/1.0f);
  metrics.rmse = compared.rms_error * std::sqrt(double(n) / double(metrics.pixels));
  metrics.max = compared.maxerror;
  metrics.meanSigned = sumSigned / double(metrics.pixels);
  metrics.meanAbsInShadow =
      metrics.pixelsInShadow ? sumAbsInShadow / double(metrics.pixelsInShadow) : 0.0;
  const size_t rank = size_t(std::ceil(0.99 * double(absolute.size()))) - 1;  // nearest rank
  std::nth_element(absolute.begin(), absolute.begin() + long(rank), absolute.end());
  metrics.p99 = absolute[rank];
  return metrics;
}

std::vector<std::uint8_t> countedPixels(const std::vector<float>& mask,
                                        const std::vector<float>* receiverFlag) {
  if (receiverFlag && receiverFlag->size() != mask.size())
    throw std::invalid_argument("countedPixels: the receiver flag and the mask differ in size");
  std::vector<std::uint8_t> counted(mask.size());
  for (size_t i = 0; i < mask.size(); ++i) {
    const int pixelClass = int(std::lround(mask[i]));
    counted[i] = pixelClass != CLASS_BACKGROUND && pixelClass != CLASS_OUTSIDE &&
                 (!receiverFlag || (*receiverFlag)[i] > 0.5f);
  }
  return counted;
}
