// Random test values drawn from the kit's one generator (raylab/random.h): the autograder's
// cases, the regenerate tool and the test meshes use these, so that every program that
// makes test inputs makes them the same way, on every compiler and platform.
#pragma once

#include "raylab/random.h"

#include <glm/glm.hpp>

#include <cmath>
#include <cstdint>
#include <string_view>

namespace raylab::testkit {

// A generator's stream from a name (FNV-1a, the same everywhere, unlike std::hash): the
// cases of stage "02_sphere" come from Pcg32(seed, stream_of("02_sphere")), so that each
// stage's cases are independent of the others' and of how many stages there are.
constexpr std::uint64_t stream_of(std::string_view name) {
  std::uint64_t hash = 0xcbf29ce484222325ULL;
  for (const char c : name) {
    hash ^= static_cast<unsigned char>(c);
    hash *= 0x100000001b3ULL;
  }
  return hash;
}

// A whole number in [low, high], both included (low <= high).
inline int random_integer(Pcg32& random, int low, int high) {
  return low + static_cast<int>(random.next_bounded(static_cast<std::uint32_t>(high - low) + 1u));
}

// Each coordinate uniform over [low, high).
inline glm::vec3 random_vec3(Pcg32& random, float low, float high) {
  const float x = random.uniform(low, high), y = random.uniform(low, high), z = random.uniform(low, high);
  return {x, y, z};
}

// Uniform over [low, high) in double precision: 53 random bits from two draws.
inline double random_double(Pcg32& random, double low, double high) {
  const std::uint64_t high_bits = random.next_uint32() >> 5u, low_bits = random.next_uint32() >> 6u;  // 27 + 26
  const double unit = static_cast<double>((high_bits << 26u) | low_bits) * (1.0 / 9007199254740992.0);
  return low + (high - low) * unit;
}

// Spread evenly over the logarithm: as many values in [1e-6, 1e-5) as in [1e-2, 1e-1)
// (0 < low < high). For magnitudes that span decades (tiny spheres, huge distances).
inline float random_log_uniform(Pcg32& random, float low, float high) {
  return static_cast<float>(std::exp(random_double(random, std::log(double(low)), std::log(double(high)))));
}

// A direction uniform on the unit sphere (z uniform in [-1, 1], an angle uniform around z).
inline glm::vec3 random_unit_vector(Pcg32& random) {
  const double z = random_double(random, -1.0, 1.0), phi = random_double(random, 0.0, 6.283185307179586);
  const double r = std::sqrt(std::fmax(0.0, 1.0 - z * z));
  return {static_cast<float>(r * std::cos(phi)), static_cast<float>(r * std::sin(phi)), static_cast<float>(z)};
}

// true with probability `probability`.
inline bool random_chance(Pcg32& random, float probability) { return random.next_float() < probability; }

}  // namespace raylab::testkit
