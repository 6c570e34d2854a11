// What the scene and OBJ loaders promise for ANY input (scene_loader.h), checked by the fuzz
// targets (fuzz_scene.cpp, fuzz_obj.cpp) on every input they are given: either the loader
// returns a usable result (every index in range, every number finite, every material named
// exists) or it throws InputError whose message starts with the file's name. Anything else
// (another exception, a result breaking the contract) aborts with a message, which libFuzzer
// and the corpus replay report as a crash. Crashes, hangs and sanitizer reports are theirs to
// catch.
#pragma once

#include "raylab/error.h"
#include "raylab/scene.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>

namespace raylab::fuzz {

[[noreturn]] inline void contract_broken(const std::string& what) {
  std::fprintf(stderr, "loader contract broken: %s\n", what.c_str());
  std::abort();
}

inline bool finite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

inline void check_mesh(const TriangleMesh& mesh, std::size_t material_count) {
  if (mesh.indices.empty() || mesh.indices.size() % 3 != 0)
    contract_broken("mesh " + mesh.name + " has " + std::to_string(mesh.indices.size()) + " indices");
  for (std::uint32_t index : mesh.indices)
    if (index >= mesh.positions.size()) contract_broken("mesh " + mesh.name + ": index out of range");
  for (const glm::vec3& p : mesh.positions)
    if (!finite(p)) contract_broken("mesh " + mesh.name + ": a position is not finite");
  if (!mesh.texcoords.empty() && mesh.texcoords.size() != mesh.positions.size())
    contract_broken("mesh " + mesh.name + ": texcoords and positions differ in number");
  for (const glm::vec2& st : mesh.texcoords)
    if (!std::isfinite(st.x) || !std::isfinite(st.y)) contract_broken("mesh " + mesh.name + ": a texcoord is not finite");
  if (material_count != 0 && mesh.material >= material_count) contract_broken("mesh " + mesh.name + ": no such material");
}

inline void check_scene(const Scene& scene) {
  try {
    validate_camera(scene.camera);
  } catch (const std::invalid_argument& e) {
    contract_broken(std::string("the camera is invalid: ") + e.what());
  }
  if (!finite(scene.background)) contract_broken("the background is not finite");
  const std::size_t materials = scene.materials.size();
  for (const Sphere& sphere : scene.spheres)
    if (!finite(sphere.center) || !std::isfinite(sphere.radius) || !(sphere.radius > 0) || sphere.material >= materials)
      contract_broken("a sphere is invalid");
  for (const TriangleMesh& mesh : scene.meshes) {
    if (mesh.material >= materials) contract_broken("mesh " + mesh.name + ": no such material");
    check_mesh(mesh, materials);
  }
  for (const PointLight& light : scene.lights)
    if (!finite(light.position) || !finite(light.intensity)) contract_broken("a light is not finite");
}

// Runs `load` (a loader call that returns a result checked by `check`); an InputError must
// name `source` first.
template <typename Load, typename Check>
void expect_result_or_input_error(const std::string& source, Load load, Check check) {
  try {
    check(load());
  } catch (const InputError& e) {
    const std::string message = e.what();
    if (message.rfind(source, 0) != 0) contract_broken("the error does not start with " + source + ": " + message);
  } catch (const std::exception& e) {
    contract_broken(std::string("an exception other than InputError: ") + e.what());
  }
}

}  // namespace raylab::fuzz
