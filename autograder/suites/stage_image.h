// The picture of a stage's image test (stages.json: "image"), rendered by the stage code in the
// stage server (stage_image_calls.cpp); support.h compares it with the reference.
#pragma once

#include "raylab/image.h"

#include <string>

namespace raylab::grading {

// The size of each stage's picture: small so grading stays fast.
constexpr int kImageWidth = 320, kImageHeight = 240;

// The picture, the same for the student and the reference, kImageWidth x kImageHeight. What it
// shows (stages.json: "image" "shows"):
//   ray_directions  camera-ray directions as colours (only stage 1's function runs)
//   spheres         the scene's spheres, its meshes left out
//   everything      the whole scene, through whatever stages the renderer uses
Image render_stage_image(const std::string& stage_id);

}  // namespace raylab::grading
