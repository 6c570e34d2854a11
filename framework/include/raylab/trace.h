// One pixel traced step by step (`raylab trace`): each call of your stage functions along the
// pixel's camera ray, its inputs and result beside the result the contract gives for the same
// inputs, from the kit's own exact versions (raylab/testkit/exact_tracing.h, which the student
// release has). The first call that disagrees is the place to look.
//   What is traced today: the camera ray (stage 01), and along the contract's camera ray every
// sphere and triangle test (stages 02 and 03) that your code or the contract hits, and the
// closest hit. Bounces, trees and the Monte Carlo stages are not traced yet.
#pragma once

#include "raylab/geometry.h"
#include "raylab/scene.h"

#include <glm/glm.hpp>

#include <ostream>
#include <string>
#include <vector>

namespace raylab {

struct TraceStep {
  std::string stage;     // "01_camera_rays"
  std::string function;  // "generate_camera_ray"
  std::string call;      // the call with its arguments, as C++ writes it
  std::string yours;     // what your function returned ("not written yet" for a stub)
  std::string expected;  // what the contract gives
  bool agrees = true;
};

struct PixelTrace {
  int x = 0, y = 0;
  glm::vec2 position_in_pixel{0.5f};
  std::vector<TraceStep> steps;
  // Not listed: missed by yours and the contract alike, or a stub's calls after its first.
  int untouched_spheres = 0, untouched_triangles = 0;
  // The index of the first step that disagrees, or -1.
  int first_disagreement() const;
};

// Traces pixel (x, y) of the scene's camera, through `position_in_pixel`, with the stage functions
// this program links, against `contract` (every function set). Throws std::invalid_argument for a
// pixel outside the image.
PixelTrace trace_pixel(const Scene& scene, int x, int y, glm::vec2 position_in_pixel, const TracingFunctions& contract);

// The trace as the terminal shows it: every step, the first disagreement marked with its stage and
// function, and what to do next.
void print_trace(std::ostream& out, const std::string& scene_path, const PixelTrace& trace);

}  // namespace raylab
