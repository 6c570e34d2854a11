#include "raylab/trace.h"

#include "trace_text.h"

#include "raylab/math.h"
#include "raylab/sampler.h"
#include "raylab/stage_table.h"
#include "raylab/stages/01_camera_rays.h"
#include "raylab/stages/02_sphere.h"

#include <optional>
#include <stdexcept>

namespace raylab {

using namespace trace_text;

int PixelTrace::first_disagreement() const {
  for (std::size_t i = 0; i < steps.size(); ++i)
    if (!steps[i].agrees) return static_cast<int>(i);
  return -1;
}

PixelTrace trace_pixel(const Scene& scene, int x, int y, const TraceSettings& settings,
                       const TracingFunctions& contract) {
  const Camera& camera = scene.camera;
  if (x < 0 || y < 0 || x >= camera.width || y >= camera.height)
    throw std::invalid_argument("pixel (" + std::to_string(x) + ", " + std::to_string(y) + ") is outside the " +
                                std::to_string(camera.width) + "x" + std::to_string(camera.height) + " image");
  if (settings.sample < 0 || settings.sample >= settings.samples_per_pixel)
    throw std::invalid_argument("sample " + std::to_string(settings.sample) + " is outside the pixel's " +
                                std::to_string(settings.samples_per_pixel) + " (from 0 to " +
                                std::to_string(settings.samples_per_pixel - 1) + ": --spp sets how many)");
  PixelTrace trace;
  trace.x = x;
  trace.y = y;
  trace.settings = settings;
  // The sample's random numbers, as the renderer draws them (render.cpp): the point in the pixel
  // first, then the integrator's.
  Sampler sampler(settings.samples_per_pixel, settings.seed);
  sampler.start_pixel_sample(x, y, settings.sample);
  const glm::vec2 position_in_pixel = sampler.get_pixel_2d();
  trace.position_in_pixel = position_in_pixel;

  // Stage 01: the camera ray.
  const Ray ray = contract.camera_ray(camera, x, y, position_in_pixel);
  {
    bool stub = false;
    const std::optional<Ray> got = yours([&] { return generate_camera_ray(camera, x, y, position_in_pixel); }, stub);
    TraceStep step{"01_camera_rays", "generate_camera_ray",
                   "generate_camera_ray(camera, " + std::to_string(x) + ", " + std::to_string(y) + ", " +
                       text(position_in_pixel) + ")",
                   stub ? "not written yet" : text(*got), text(ray)};
    step.agrees = !stub && near(got->origin, ray.origin) && near(got->direction, ray.direction);
    trace.steps.push_back(step);
  }

  // Stages 02 and 03 along the contract's ray: every primitive that either answer hits.
  struct Closest {
    float t = kInfinity;
    std::string what;
  } closest_yours, closest_contract;
  const auto record = [](Closest& closest, const std::optional<float>& t, const std::string& what) {
    if (t && *t < closest.t) closest = {*t, what};
  };
  // A stub is shown once, at its first call; the calls after it are not listed.
  bool sphere_stub_shown = false, triangle_stub_shown = false;
  for (std::size_t i = 0; i < scene.spheres.size(); ++i) {
    const Sphere& sphere = scene.spheres[i];
    bool stub = false;
    const std::optional<std::optional<float>> got =
        yours([&] { return intersect_ray_sphere(ray, sphere.center, sphere.radius); }, stub);
    const std::optional<float> expected = contract.sphere(ray, sphere.center, sphere.radius);
    const std::string what = "sphere " + std::to_string(i);
    if (got) record(closest_yours, *got, what);
    record(closest_contract, expected, what);
    if ((!stub && !*got && !expected) || (stub && sphere_stub_shown)) {
      ++trace.untouched_spheres;
      continue;
    }
    sphere_stub_shown = sphere_stub_shown || stub;
    TraceStep step{"02_sphere", "intersect_ray_sphere",
                   "intersect_ray_sphere(ray, center " + text(sphere.center) + ", radius " + text(sphere.radius) + ")   [" +
                       what + "]",
                   stub ? "not written yet" : text(*got), text(expected)};
    step.agrees = !stub && near(*got, expected);
    trace.steps.push_back(step);
  }
  for (std::size_t m = 0; m < scene.meshes.size(); ++m) {
    const TriangleMesh& mesh = scene.meshes[m];
    for (std::size_t k = 0; k < mesh.triangle_count(); ++k) {
      const glm::vec3& p0 = mesh.positions[mesh.indices[3 * k]];
      const glm::vec3& p1 = mesh.positions[mesh.indices[3 * k + 1]];
      const glm::vec3& p2 = mesh.positions[mesh.indices[3 * k + 2]];
      bool stub = false;
      const std::optional<std::optional<TriangleHit>> got =
          yours([&] { return intersect_ray_triangle(ray, p0, p1, p2); }, stub);
      const std::optional<TriangleHit> expected = contract.triangle(ray, p0, p1, p2);
      const std::string what = "triangle " + std::to_string(k) + " of mesh " +
                               (mesh.name.empty() ? std::to_string(m) : "\"" + mesh.name + "\"");
      if (got && *got) record(closest_yours, (*got)->t_hit, what);
      if (expected) record(closest_contract, expected->t_hit, what);
      if ((!stub && !*got && !expected) || (stub && triangle_stub_shown)) {
        ++trace.untouched_triangles;
        continue;
      }
      triangle_stub_shown = triangle_stub_shown || stub;
      TraceStep step{"03_triangle", "intersect_ray_triangle",
                     "intersect_ray_triangle(ray, " + text(p0) + ", " + text(p1) + ", " + text(p2) + ")   [" + what + "]",
                     stub ? "not written yet" : text(*got), text(expected)};
      step.agrees = !stub && near(*got, expected);
      trace.steps.push_back(step);
    }
  }

  // The closest hit, as the renderer picks it from the answers above.
  const auto closest_text = [](const Closest& closest) {
    return closest.what.empty() ? std::string("nothing: the background") : closest.what + " at t = " + text(closest.t);
  };
  TraceStep closest{"", "", "the closest hit along the camera ray", closest_text(closest_yours),
                    closest_text(closest_contract)};
  closest.agrees = closest_yours.what == closest_contract.what && near(closest_yours.t, closest_contract.t);
  trace.steps.push_back(closest);
  if (settings.integrator == IntegratorKind::DirectLight || settings.integrator == IntegratorKind::Path)
    trace_monte_carlo(scene, ray, sampler, contract, trace);
  return trace;
}

void print_trace(std::ostream& out, const std::string& scene_path, const PixelTrace& trace) {
  const TraceSettings& settings = trace.settings;
  const bool monte_carlo =
      settings.integrator == IntegratorKind::DirectLight || settings.integrator == IntegratorKind::Path;
  out << "raylab trace " << scene_path << ": pixel (" << trace.x << ", " << trace.y << "), sample " << settings.sample
      << " of " << settings.samples_per_pixel << " (seed " << settings.seed << "), through "
      << text(trace.position_in_pixel) << " in the pixel, integrator " << integrator_name(settings.integrator) << "\n"
      << "Each call of your stage functions along this sample's " << (monte_carlo ? "path" : "camera ray")
      << ", beside what the contract gives for the\n"
      << "same inputs and the same random numbers (the kit's own exact versions). The sphere and triangle tests use\n"
      << "the contract's camera ray.\n\n";
  if (settings.integrator == IntegratorKind::PathMis)
    out << "(The mis integrator's path is not traced yet: only its camera ray.)\n\n";
  const int first = trace.first_disagreement();
  for (std::size_t i = 0; i < trace.steps.size(); ++i) {
    const TraceStep& step = trace.steps[i];
    out << "  " << i + 1 << ". " << (step.stage.empty() ? "" : "stage " + step.stage + "  ") << step.call << "\n"
        << "       yours     " << step.yours << "\n"
        << "       contract  " << step.expected << "\n";
    if (!step.note.empty()) out << "       note      " << step.note << "\n";
    if (static_cast<int>(i) == first) {
      out << "       ^ the first disagreement";
      if (!step.function.empty()) {
        const StageDescription* stage = find_stage_description(step.stage);
        out << ": your " << step.function;
        if (stage && !stage->files.empty()) out << " (assignments/" << stage->files.front() << ")";
      }
      out << "\n";
    } else if (!step.agrees) {
      out << "       ^ differs too\n";
    }
  }
  const auto count = [](int n, const char* noun) { return std::to_string(n) + " " + noun + (n == 1 ? "" : "s"); };
  if (trace.untouched_spheres + trace.untouched_triangles > 0)
    out << "\n  Not listed: " << count(trace.untouched_spheres, "sphere") << " and "
        << count(trace.untouched_triangles, "triangle") << " that neither your tests nor the contract's hit (or a\n"
        << "  stub's calls after its first).\n";
  out << "\n"
      << (first < 0
              ? std::string("Every call agrees with the contract along this ") + (monte_carlo ? "path" : "ray") + ".\n"
              : "Start at the first disagreement: the steps after it may differ only because of it.\n");
}

}  // namespace raylab
