// The picture of a stage's image test (stages.json: "image"), rendered by the stage code in the
// stage server (stage_image_calls.cpp); support.h compares it with the reference.
#pragma once

#include "protocol.h"

#include "raylab/image.h"
#include "raylab/trace.h"

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

// Pixel (x, y) of that picture traced through the same functions (raylab/trace.h: the stage
// code's calls beside the contract's answers), for the report of a picture that fails. The judge
// keeps at most kMostTracedSteps steps, each text cut at kMostTracedTextBytes: the stage server
// runs the student's code, and what it sends is shown, never believed.
constexpr std::size_t kMostTracedSteps = 200, kMostTracedTextBytes = 300;
// `chinese`: the steps' words in Chinese (TraceSettings::chinese). The call is diagnostic
// (StageSession::DiagnosticCalls, kTraceSeconds at most): a trace that crashes or loops throws
// StageLost but costs the test nothing, as the trace runs the stage code on inputs the picture
// did not.
constexpr double kTraceSeconds = 10;
PixelTrace trace_stage_image_pixel(const std::string& stage_id, int x, int y, bool chinese);
// The command that prints the same trace on the student's machine.
std::string stage_image_trace_command(const std::string& stage_id, int x, int y, bool chinese);

// A trace's steps as a stage server sends them (the first kMostTracedSteps, and how many there
// were), and as the judge reads them back into `trace` (at most kMostTracedSteps, each text cut
// at kMostTracedTextBytes; steps left out set trace.steps_cut, and such a trace is never said to
// agree).
void write_trace_steps(protocol::Writer& out, const PixelTrace& trace);
void read_trace_steps(protocol::Reader& in, PixelTrace& trace);

}  // namespace raylab::grading
