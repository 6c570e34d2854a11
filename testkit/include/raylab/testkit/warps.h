// Stage 07's warps as a statistical test sees them: the parameters (u, v) each warp's samples
// are counted in, where the intended density is smooth inside every cell of a grid, and that
// density. The autograder's suite and the kit's own check of the stage's false-failure rate
// (tests/test_bsdf_lights.cpp) both judge with these, so the two cannot drift apart.
//   directions:     u = phi in [0, 2 pi), v = z = cos(theta) in [-1, 1]; d omega = du dv
//   disk points:    u = phi in [0, 2 pi), v = r in [0, 1];               dA = v du dv
//   triangle:       u = t = b2 / (b1 + b2) in [0, 1], v = s = b1 + b2 in [0, 1] (barycentric
//                   space, the unit triangle (0,0), (1,0), (0,1));      dA = v du dv
#pragma once

#include <glm/glm.hpp>

#include <cstdint>

namespace raylab::testkit {

enum class Warp : std::uint8_t { UniformHemisphere, CosineHemisphere, UniformSphere, UniformDisk, UniformTriangle };
constexpr Warp kWarps[] = {Warp::UniformHemisphere, Warp::CosineHemisphere, Warp::UniformSphere, Warp::UniformDisk,
                           Warp::UniformTriangle};

const char* warp_sample_function(Warp warp);  // "sample_cosine_hemisphere"
const char* warp_pdf_function(Warp warp);     // "cosine_hemisphere_pdf"
inline bool is_direction_warp(Warp warp) { return warp != Warp::UniformDisk && warp != Warp::UniformTriangle; }
inline bool is_hemisphere(Warp warp) { return warp == Warp::UniformHemisphere || warp == Warp::CosineHemisphere; }

// The histogram grid over the warp's parameters: columns across u, rows across v.
struct WarpGrid {
  int columns, rows;
  double u_min, u_max, v_min, v_max;
};
WarpGrid warp_grid(Warp warp);

// A sample's parameters. Samples are given as the stage calls return them: a direction; a disk
// point as (x, y, 0); barycentrics as (b1, b2, 0). A value that rounding puts just above 1 is
// counted just below it.
glm::dvec2 warp_parameters(Warp warp, const glm::vec3& sample);

// What the warp's pdf function takes at parameters (u, v): the direction, or the disk point as
// (x, y, 0). (The triangle's pdf takes corners: the unit triangle's value is used.)
glm::vec3 warp_pdf_argument(Warp warp, double u, double v);

// Solid angle or area per du dv.
double warp_jacobian(Warp warp, double u, double v);

// The density the warp should have at (u, v), per steradian or per unit area (the triangle's
// per unit area of the unit triangle: 2); and per du dv (times the Jacobian).
double intended_pdf(Warp warp, double u, double v);
inline double intended_density(Warp warp, double u, double v) {
  return intended_pdf(warp, u, v) * warp_jacobian(warp, u, v);
}

}  // namespace raylab::testkit
