// The renderer's side of `raylab view` (framework/view/): a process of the student's program
// (`raylab view-worker`, started by the view's server, which never runs stage code itself) that
// renders the picture in passes and sends each pass to the server as a frame on a file
// descriptor of its own, so that what the stage code prints on stdout and stderr cannot mix with
// the pictures. When the stage code crashes or loops, only this process is lost; the server says
// so and its page stays up.
//
// The frames, each a line of text and then its bytes:
//   "tree N\n" and N bytes: the trees' boxes by level as rectangles on the picture, JSON
//       {"levels": [[[x0, y0, x1, y1], ...], ...]} (tree_levels_json below); sent first.
//   "pass FIRST COUNT SECONDS RAYS\n" and width x height x 3 floats (row by row from the top,
//       in the machine's byte order): the mean of samples FIRST .. FIRST + COUNT - 1 of every
//       pixel, out of the render's samples_per_pixel (RenderSettings::first_sample), the pass's
//       seconds and the rays it traced.
//   "rate\n" and width x height x 3 floats: with adaptive sampling or samples by noise (rendered
//       in one pass), each pixel's samples as a fraction of samples_per_pixel.
#pragma once

#include "raylab/geometry.h"
#include "raylab/render.h"
#include "raylab/scene.h"

#include <string>

namespace raylab {

// {"levels": [[[x0, y0, x1, y1], ...], ...]}: the boxes of each depth of the geometry's trees
// (SceneGeometry::tree_boxes_by_level) as the rectangles they cover on the camera's picture, in
// raster coordinates (project_segment_to_raster of their twelve edges; a box wholly behind the
// camera is left out); the levels up to 2^20 boxes and 256 levels in all.
std::string tree_levels_json(const SceneGeometry& geometry, const Camera& camera);

// Renders samples settings.first_sample .. settings.samples_per_pixel - 1 in passes on one
// geometry (render_geometry: the trees built once), each taking about a quarter of a second or
// more (1, 2, 4, ... samples, at most 64), and writes the
// frames to `frames_fd`; the tree first when `send_tree`. With adaptive sampling or samples by
// noise, one pass of all samples and its "rate" frame. Exceptions from the stage code reach the
// caller; a server that went away ends the work quietly. Returns kExitOk.
int run_view_worker(const Scene& scene, const RenderSettings& settings, int frames_fd, bool send_tree);

}  // namespace raylab
