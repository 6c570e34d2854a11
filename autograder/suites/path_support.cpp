#include "path_support.h"

#include "raylab/testkit/statistics.h"

#include <algorithm>
#include <cmath>

namespace raylab::grading {

PathRenderRequest furnace_request(int index, std::uint64_t seed) {
  const Furnace& f = kFurnaces[index];
  PathRenderRequest request;
  request.width = request.height = 32;
  request.samples_per_pixel = 4;
  request.max_depth = f.max_depth;
  request.roulette_probability = static_cast<float>(f.roulette);
  request.albedo = static_cast<float>(f.albedo);
  request.seed = seed;
  return request;
}

double furnace_exact(const Furnace& furnace) {
  double sum = 0, term = 1;
  for (int k = 0; k <= furnace.max_depth + 1; ++k, term *= furnace.albedo) sum += term;
  return sum;
}

double path_test_level() {
  static const double level = testkit::sidak_level(testkit::kGraderFalseFailureRate, kPathStatisticalTests);
  return level;
}

RegionTest region_z_test(const PathRenderResult& yours, int your_samples, const Image& reference_mean,
                         const Image& reference_variance_of_mean, int reference_samples) {
  RegionTest result;
  result.z_limit = testkit::normal_quantile(1.0 - path_test_level() / 2.0);
  const double n = kRegion * kRegion;
  for (int ry = 0; ry < kRegionsPerSide; ++ry)
    for (int rx = 0; rx < kRegionsPerSide; ++rx)
      for (int c = 0; c < 3; ++c) {
        double mean = 0, expected = 0, variance_yours = 0, variance_reference_scaled = 0, variance_reference = 0;
        for (int y = ry * kRegion; y < (ry + 1) * kRegion; ++y)
          for (int x = rx * kRegion; x < (rx + 1) * kRegion; ++x) {
            mean += yours.mean.at(x, y)[c];
            variance_yours += yours.variance_of_mean.at(x, y)[c];
            expected += reference_mean.at(x, y)[c];
            const double reference_variance = reference_variance_of_mean.at(x, y)[c];
            variance_reference += reference_variance;
            variance_reference_scaled += reference_variance * reference_samples / your_samples;
          }
        mean /= n;
        expected /= n;
        const double variance = (std::max(variance_yours, variance_reference_scaled) + variance_reference) / (n * n);
        const double z = variance > 0 ? (mean - expected) / std::sqrt(variance) : (mean == expected ? 0.0 : 1e9);
        result.z_scores.push_back(z);
        if (!(std::fabs(z) <= result.z_limit)) {
          ++result.failures;
          if (!(std::fabs(z) <= std::fabs(result.worst_z))) {
            result.worst_z = z;
            result.worst_x = rx * kRegion;
            result.worst_y = ry * kRegion;
            result.worst_channel = c;
            result.worst_mean = mean;
            result.worst_expected = expected;
          }
        }
      }
  return result;
}

}  // namespace raylab::grading
