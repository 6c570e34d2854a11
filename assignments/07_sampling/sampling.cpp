// Stage 07_sampling: warps from uniform random numbers, each with its density.
//                                                                   Handout: docs/07_sampling.md
//
// A Monte Carlo renderer picks directions and points at random. A "warp" turns two uniform
// random numbers into a point or direction with a chosen distribution, and its "pdf" says how
// likely each result is. The renderer divides by the pdf, so the two must agree exactly.
//
// WHAT EVERY FUNCTION RECEIVES
//   uniform_random   two independent numbers, each uniform in [0, 1) (0 can happen, 1 never):
//                    uniform_random.x and uniform_random.y. A warp depends on them alone: do
//                    not call rand() (the autograder asks for the same numbers twice).
//
// CONVENTIONS
//   Directions: unit-length glm::vec3 in a LOCAL frame whose z axis is the surface normal, so
//   direction.z = cos(theta), theta measured from the normal; "below the surface" is z < 0.
//   phi is the angle around z, from the x axis. The framework turns local directions into
//   world space (raylab::Frame); you never see the surface.
//   Densities (pdfs) of directions are per unit solid angle (per steradian): over the whole
//   sphere of directions each pdf integrates to 1. Densities of points are per unit area.
//   A pdf is 0 where its warp never goes.
//
// READ docs/07_sampling.md: section 1 (densities, solid angle and why pdfs matter), section 2
//   (the inversion method), sections 3-7 (each warp, with its derivation and worked numbers),
//   section 8 (common mistakes, which the autograder's hints name, and how to check).
//
// HOW TO CHECK
//   build/bin/autograder --stage 07_sampling
//   (grading-output/07_sampling-<warp>.png shows a histogram of your samples beside the density
//   they should have.)
#include "raylab/error.h"
#include "raylab/stages/07_sampling.h"

namespace raylab {

// Uniform hemisphere. RETURN a unit direction with z >= 0; every direction of the hemisphere
// equally likely (equal solid angles get equal numbers of samples).
glm::vec3 sample_uniform_hemisphere(glm::vec2 uniform_random) {
  (void)uniform_random;
  // Delete the line below when you write the function (handout section 3).
  throw NotImplemented("sample_uniform_hemisphere");
}

// The density of sample_uniform_hemisphere's directions at `direction` (unit, local frame),
// per steradian: the same for every direction with z >= 0, 0 for z < 0.
float uniform_hemisphere_pdf(const glm::vec3& direction) {
  (void)direction;
  throw NotImplemented("uniform_hemisphere_pdf");
}

// Cosine-weighted hemisphere. RETURN a unit direction with z >= 0, with density proportional
// to cos(theta): directions near the normal are more likely, grazing ones rare.
glm::vec3 sample_cosine_hemisphere(glm::vec2 uniform_random) {
  (void)uniform_random;
  // Delete the line below when you write the function (handout section 4).
  throw NotImplemented("sample_cosine_hemisphere");
}

// The density of sample_cosine_hemisphere's directions at `direction` (unit, local frame),
// per steradian; 0 for z < 0.
float cosine_hemisphere_pdf(const glm::vec3& direction) {
  (void)direction;
  throw NotImplemented("cosine_hemisphere_pdf");
}

// Uniform sphere. RETURN a unit direction, every direction of the whole sphere equally likely.
glm::vec3 sample_uniform_sphere(glm::vec2 uniform_random) {
  (void)uniform_random;
  // Delete the line below when you write the function (handout section 5).
  throw NotImplemented("sample_uniform_sphere");
}

// The density of sample_uniform_sphere's directions at `direction` (unit), per steradian.
float uniform_sphere_pdf(const glm::vec3& direction) {
  (void)direction;
  throw NotImplemented("uniform_sphere_pdf");
}

// Uniform disk. RETURN a point (x, y) of the disk of radius 1 around (0, 0), uniform by area
// (equal areas get equal numbers of samples). Any correct mapping is accepted.
glm::vec2 sample_uniform_disk(glm::vec2 uniform_random) {
  (void)uniform_random;
  // Delete the line below when you write the function (handout section 6).
  throw NotImplemented("sample_uniform_disk");
}

// The density of sample_uniform_disk's points at `point`, per unit area: the same everywhere
// inside the disk (x^2 + y^2 <= 1), 0 outside.
float uniform_disk_pdf(glm::vec2 point) {
  (void)point;
  throw NotImplemented("uniform_disk_pdf");
}

// Uniform triangle. RETURN barycentrics {barycentric_b1, barycentric_b2} of a point uniform by
// area on ANY triangle (p0, p1, p2): point = (1 - b1 - b2) p0 + b1 p1 + b2 p2, with b1 >= 0,
// b2 >= 0 and b1 + b2 <= 1. (Barycentrics are the same fractions of area on every triangle,
// so you never need the corners.) Area lights pick their points with this.
Barycentrics sample_uniform_triangle(glm::vec2 uniform_random) {
  (void)uniform_random;
  // Delete the line below when you write the function (handout section 7).
  throw NotImplemented("sample_uniform_triangle");
}

// The density, per unit area, of sample_uniform_triangle's points on the triangle (p0, p1, p2)
// (world-space corners of a triangle with area > 0): the same at every point of it.
float uniform_triangle_pdf(const glm::vec3& p0, const glm::vec3& p1, const glm::vec3& p2) {
  (void)p0;
  (void)p1;
  (void)p2;
  throw NotImplemented("uniform_triangle_pdf");
}

}  // namespace raylab
