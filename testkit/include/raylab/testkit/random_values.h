// Random test values drawn from the kit's one generator (raylab/random.h): the autograder's
// cases, the regenerate tool and the test meshes use these, so that every program that
// makes test inputs makes them the same way, on every compiler and platform.
#pragma once

#include "raylab/random.h"

#include <glm/glm.hpp>

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

// true with probability `probability`.
inline bool random_chance(Pcg32& random, float probability) { return random.next_float() < probability; }

}  // namespace raylab::testkit
