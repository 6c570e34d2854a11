// The scene model: what a scene file describes, in memory. Loaded by scene_loader.h.
#pragma once

#include "raylab/camera.h"
#include "raylab/math.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace raylab {

// The three material kinds of GAMES101 assignment 5, and three for Monte Carlo rendering.
// How each one reflects: shading (Whitted) and bsdf.h (bsdf_of).
enum class MaterialKind {
  DiffuseGlossy,          // Lambert diffuse + Phong highlight, lit by the point lights
  Reflective,             // a mirror, weighted by Fresnel reflectance
  ReflectiveRefractive,   // glass: Fresnel-weighted reflection + refraction
  Diffuse,                // Lambertian of albedo diffuse_color (kd 1, ks 0 under Whitted)
  Mirror,                 // a perfect mirror of colour `reflectance`
  Microfacet,             // a rough metal: GGX of roughness alpha, Schlick's Fresnel from
                          // `reflectance` at normal incidence (stage 10; a mirror under Whitted)
};

// A texture over the (s, t) coordinates of a mesh: checkers with `scale` periods per unit
// of texture coordinate in each direction (scale 5 over 0..1 gives 10 x 10 squares), as in
// GAMES101: colour_b where exactly one of frac(s*scale), frac(t*scale) is above 0.5.
struct Checkerboard {
  float scale = 5.0f;
  glm::vec3 color_a{0.815f, 0.235f, 0.031f};
  glm::vec3 color_b{0.937f, 0.937f, 0.231f};
};

struct Material {
  std::string name;
  MaterialKind kind = MaterialKind::DiffuseGlossy;
  glm::vec3 diffuse_color{0.2f};
  std::optional<Checkerboard> checkerboard;  // replaces diffuse_color where texcoords exist
  float kd = 0.8f;                           // diffuse weight
  float ks = 0.2f;                           // specular weight
  float specular_exponent = 25.0f;
  float index_of_refraction = 1.3f;
  glm::vec3 reflectance{1.0f};  // Mirror; Microfacet: the reflectance at normal incidence
  float alpha = 0.2f;           // Microfacet: GGX's roughness parameter, in [kMinMicrofacetAlpha, 1]
  // Radiance emitted (W / (m^2 sr) per channel) from the surface's front, the side its
  // geometric normal points to: every object of an emitting material is an area light
  // (lights.h).
  glm::vec3 emission{0.0f};
};

// The smallest roughness a microfacet material may have: below it D(h) = 1 / (pi alpha^2) at the
// normal outgrows float precision in the path tracer's weights (use a mirror instead).
constexpr float kMinMicrofacetAlpha = 1e-3f;

struct Sphere {
  glm::vec3 center{0.0f};
  float radius = 1.0f;
  std::uint32_t material = 0;
  // The side the geometric normal points to, which is the side that emits: outwards (the
  // default), or inwards for a closed room seen from inside (scenes/furnace.json).
  bool faces_inward = false;
};

// An indexed triangle mesh. texcoords, when present, has one entry per position.
struct TriangleMesh {
  std::string name;
  std::vector<glm::vec3> positions;
  std::vector<glm::vec2> texcoords;
  std::vector<std::uint32_t> indices;  // 3 per triangle, into positions
  std::uint32_t material = 0;

  std::size_t triangle_count() const { return indices.size() / 3; }
};

// A point light. The scene file gives its intensity I (W/sr) or its power, the flux it
// sends out in all directions (W): I = flux / (4 pi).
struct PointLight {
  glm::vec3 position{0.0f};
  glm::vec3 intensity{1.0f};
};

struct Scene {
  std::string source;  // the file it came from, for messages
  Camera camera;
  glm::vec3 background{0.0f};
  int max_depth = 5;   // the default for --max-depth
  std::string integrator = "whitted";  // the default for --integrator: whitted, direct, path or mis
  std::vector<Material> materials;
  std::vector<Sphere> spheres;
  std::vector<TriangleMesh> meshes;
  std::vector<PointLight> lights;
};

}  // namespace raylab
