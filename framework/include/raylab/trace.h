// One pixel sample traced step by step (`raylab trace`): each call of your stage functions along
// the sample's path, its inputs and result beside the result the contract gives for the same
// inputs and the same random numbers, from the kit's own exact versions
// (raylab/testkit/exact_tracing.h, which the student release has). The first call that disagrees
// is the place to look.
//   What is traced:
//   - the camera ray (stage 01), and along the contract's camera ray every sphere and triangle
//     test (stages 02 and 03) that your code or the contract hits, and the closest hit;
//   - the closest hit through your trees (stages 04-05), where the renderer uses them, and the
//     trees' nodes from the root down to the leaf that holds the contract's closest hit: your box
//     test on each of their boxes (the ray enters each, as each holds that primitive); every leaf
//     your traversal opened (one whose primitives it tested), each of which the ray must enter,
//     and whether each test's t_max was lowered to the closest hit found before it; whether your
//     traversal tested that primitive, with the count of primitive tests it made;
//   - with --integrator direct, path or mis (trace_monte_carlo.cpp): the path your code took, surface
//     by surface: the closest hit of each bounce ray, at each diffuse surface lambertian_f, the
//     light's point density (stage 07) and area_pdf_to_solid_angle, estimate_direct_light called
//     once more on its own (stage 08), the shadow rays, each bounce's direction, density (stage
//     07) and Russian roulette, and the sample's value (path_radiance, stage 09; or, with
//     direct, the framework's around your estimate_direct_light; with mis, path_radiance_mis,
//     stage 09b, and your power_heuristic on the two densities of each weighted light sample and
//     emission) against the value the contract's rules give for the same surfaces, light samples
//     and bounces.
//   - with --integrator whitted (trace_whitted.cpp): the reflection, refraction and shadow rays
//     Whitted shading traces after the camera ray, your geometry's answer along each beside the
//     contract's, and where they differ, the sphere and triangle tests along that ray that differ.
//   Not traced: the inner nodes a traversal visits (seen only through the leaves it opens), and
//   the trees along the rays after the camera ray (only their answers).
#pragma once

#include "raylab/geometry.h"
#include "raylab/integrator.h"
#include "raylab/scene.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace raylab {

struct TraceStep {
  TraceStep(std::string stage_, std::string function_, std::string call_, std::string yours_, std::string expected_,
            std::string note_ = "", bool agrees_ = true)
      : stage(std::move(stage_)),
        function(std::move(function_)),
        call(std::move(call_)),
        yours(std::move(yours_)),
        expected(std::move(expected_)),
        note(std::move(note_)),
        agrees(agrees_) {}
  std::string stage;     // "01_camera_rays"
  std::string function;  // "generate_camera_ray"
  std::string call;      // the call with its arguments, as C++ writes it
  std::string yours;     // what your function returned ("not written yet" for a stub)
  std::string expected;  // what the contract gives
  std::string note;      // what the difference means, or what else happened at this step
  bool agrees = true;
  // The file the stage's function is written in ("assignments/01_camera_rays/camera_rays.cpp"),
  // or "" for a step of no known stage.
  std::string file() const;
};

// Which sample of the pixel, and the render settings it is taken with (raylab render's).
struct TraceSettings {
  IntegratorKind integrator = IntegratorKind::Whitted;
  int samples_per_pixel = 1;
  int sample = 0;  // 0 .. samples_per_pixel - 1
  std::uint64_t seed = 0;
  int max_depth = 5;
  RussianRoulette roulette;
  // The functions traced as yours: each left nullptr is the stage's own that this program links
  // (a grader's stage server gives its own for the stages it does not grade, as its pictures use).
  TracingFunctions yours;
  // The words of the trace's steps in Simplified Chinese, every part's alike (values and code as
  // they are).
  bool chinese = false;
};

// A ray of the path your code took, from where it starts to what it hit (or as far as the
// scene's size past it), for drawing over the picture (`raylab view`).
struct TraceSegment {
  enum class Kind { Camera, Bounce, Shadow };
  glm::vec3 from{0.0f}, to{0.0f};
  Kind kind = Kind::Camera;
};

struct PixelTrace {
  int x = 0, y = 0;
  TraceSettings settings;
  glm::vec2 position_in_pixel{0.5f};
  std::vector<TraceStep> steps;
  // Not listed: missed by yours and the contract alike, or a stub's calls after its first.
  int untouched_spheres = 0, untouched_triangles = 0;
  // Steps were left out after the first ones (a grader's report keeps a bounded number).
  bool steps_cut = false;
  // The rays traced for this sample: the camera ray to your closest hit; with whitted, the
  // reflection, refraction and shadow rays after it (the framework's, from your hits); with
  // direct, path and mis, the path's rays and shadow rays as your code made them.
  std::vector<TraceSegment> segments;
  // The index of the first step that disagrees, or -1.
  int first_disagreement() const;
};

// Traces sample settings.sample of pixel (x, y) of the scene's camera with the stage functions
// this program links, against `contract` (every function set). Throws std::invalid_argument for a
// pixel outside the image or a sample outside [0, samples_per_pixel).
PixelTrace trace_pixel(const Scene& scene, int x, int y, const TraceSettings& settings,
                       const TracingFunctions& contract);

// Whitted's rays after the camera ray (trace_whitted.cpp): from the surface your geometry hits
// along `camera_ray`, the reflection, refraction and shadow rays the framework's Whitted shading
// traces, each answered by your geometry beside the contract's exact tests, appended to `trace`
// (at most the first 24).
void trace_whitted(const Scene& scene, const Ray& camera_ray, const TracingFunctions& contract, PixelTrace& trace);

// The Monte Carlo part (trace_monte_carlo.cpp): the steps of the sample's path, from the
// `sampler` positioned after the camera ray's numbers, appended to `trace`.
void trace_monte_carlo(const Scene& scene, const Ray& camera_ray, Sampler& sampler, const TracingFunctions& contract,
                       PixelTrace& trace);

// The trace as the terminal shows it: every step, the first disagreement marked with its stage and
// function, and what to do next.
void print_trace(std::ostream& out, const std::string& scene_path, const PixelTrace& trace);

// The trace as JSON (`raylab trace --json`, which `raylab view` reads): {"ok": true, "x", "y",
// "sample", "steps": [{"stage", "function", "file", "call", "yours", "expected", "note",
// "agrees"}], "first_disagreement" (-1: none), "summary", "segments": [{"from": [x, y], "to":
// [x, y], "kind": "camera" | "bounce" | "shadow"}]}, the segments in the picture's raster
// coordinates (project_segment_to_raster; a segment wholly behind the camera left out).
void write_trace_json(std::ostream& out, const Camera& camera, const PixelTrace& trace);

}  // namespace raylab
