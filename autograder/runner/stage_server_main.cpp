// The stage server: the one program that links stage code (the student's, or a self-test
// submission's). The judge starts it, sandboxed (stage_process.h), sends it one request at a time on
// descriptor 3 (protocol.h) and reads each answer on descriptor 4. It decides nothing: it
// returns what the stage functions return, and the judge grades that.
#include "protocol.h"
#include "stage_calls.h"

#include "raylab/error.h"
#include "raylab/stages/01_camera_rays.h"
#include "raylab/stages/02_sphere.h"
#include "raylab/stages/03_triangle.h"
#include "raylab/stages/03b_watertight.h"
#include "raylab/stages/04_box.h"
#include "raylab/stages/05_bvh.h"
#include "raylab/stages/08_direct_light.h"

#include <exception>
#include <new>
#include <iostream>

namespace {

using namespace raylab;
using namespace raylab::grading;
using namespace raylab::grading::protocol;

// What the judge sent for intersect_bvh earlier: it sends a tree or a mesh only when it changed.
struct Cache {
  Bvh bvh;
  std::vector<Triangle> triangles;
};

// The judge's intersector when it is not the grader's triangle test: each test is a round trip.
std::optional<float> test_through_judge(void*, const Ray& ray, std::uint32_t primitive) {
  Writer callback;
  callback.put(kCallback);
  callback.put(ray);
  callback.put(primitive);
  write_frame(kReplyFd, callback.bytes());
  std::string answer;
  if (!read_frame(kRequestFd, answer)) std::exit(0);  // the judge went away
  Reader in(answer);
  if (in.get<std::uint8_t>() != kReturn) throw ProtocolError("expected the primitive test's answer");
  return in.get_optional<float>();
}

struct CountingContext {
  PrimitiveIntersector inner;
  std::uint64_t tests = 0;
};
std::optional<float> counting_test(void* context, const Ray& ray, std::uint32_t primitive) {
  auto* counting = static_cast<CountingContext*>(context);
  ++counting->tests;
  return counting->inner.test(counting->inner.context, ray, primitive);
}

void answer(Reader& in, Writer& out, Cache& cache) {
  const auto function = static_cast<Function>(in.get<std::uint8_t>());
  switch (function) {
    case Function::GenerateCameraRay: {
      const auto camera = in.get<Camera>();
      const auto x = in.get<int>(), y = in.get<int>();
      const auto position_in_pixel = in.get<glm::vec2>();
      out.put(generate_camera_ray(camera, x, y, position_in_pixel));
      return;
    }
    case Function::IntersectRaySphere: {
      const auto ray = in.get<Ray>();
      const auto center = in.get<glm::vec3>();
      const auto radius = in.get<float>();
      out.put_optional(intersect_ray_sphere(ray, center, radius));
      return;
    }
    case Function::IntersectRayTriangle:
    case Function::IntersectRayTriangleWatertight: {
      const auto ray = in.get<Ray>();
      const auto p0 = in.get<glm::vec3>(), p1 = in.get<glm::vec3>(), p2 = in.get<glm::vec3>();
      out.put_optional(function == Function::IntersectRayTriangle ? intersect_ray_triangle(ray, p0, p1, p2)
                                                                   : intersect_ray_triangle_watertight(ray, p0, p1, p2));
      return;
    }
    case Function::TrianglesHit: {
      const bool watertight = in.get<std::uint8_t>() != 0;
      const auto triangles = in.get_vector<Triangle>();
      const auto rays = in.get_vector<Ray>();
      const auto candidates = get_lists(in);
      put_lists(out, triangles_hit(watertight ? &intersect_ray_triangle_watertight : &intersect_ray_triangle, triangles,
                                   rays, candidates));
      return;
    }
    case Function::IntersectRayBox: {
      const auto ray = in.get<Ray>();
      const auto inverse = in.get<glm::vec3>();
      const auto box = in.get<Bounds3>();
      out.put_optional(intersect_ray_box(ray, inverse, box));
      return;
    }
    case Function::BuildBvh:
    case Function::BuildBvhSah: {
      const auto boxes = in.get_vector<Bounds3>();
      const auto max_leaf_size = in.get<int>();
      const Bvh bvh = function == Function::BuildBvh ? build_bvh(boxes, max_leaf_size) : build_bvh_sah(boxes, max_leaf_size);
      out.put_vector(bvh.nodes);
      out.put_vector(bvh.primitive_order);
      return;
    }
    case Function::IntersectBvh: {
      if (in.get<std::uint8_t>()) {
        cache.bvh.nodes = in.get_vector<BvhNode, BvhNodeAllocator<BvhNode>>();
        cache.bvh.primitive_order = in.get_vector<std::uint32_t>();
      }
      const auto mode = in.get<std::uint8_t>();  // 0: callbacks; 1: grader's test, same mesh; 2: new mesh follows
      if (mode == 2) cache.triangles = in.get_vector<Triangle>();
      const auto ray = in.get<Ray>();
      const bool any_hit = in.get<std::uint8_t>() != 0;
      CountingContext counting{mode == 0 ? PrimitiveIntersector{test_through_judge, nullptr}
                                         : PrimitiveIntersector{grader_triangle_test, &cache.triangles}};
      BvhTraversalStats stats;
      const std::optional<BvhHit> hit =
          intersect_bvh(cache.bvh, ray, PrimitiveIntersector{counting_test, &counting}, any_hit, stats);
      out.put_optional(hit);
      out.put<std::uint64_t>(stats.nodes_visited);
      out.put<std::uint64_t>(counting.tests);
      return;
    }
    case Function::WarpSamples: {
      const auto warp = in.get<Warp>();
      const auto uniform_randoms = in.get_vector<glm::vec2>();
      out.put_vector(warp_samples(warp, uniform_randoms));
      return;
    }
    case Function::WarpPdfs: {
      const auto warp = in.get<Warp>();
      const auto arguments = in.get_vector<glm::vec3>();
      out.put_vector(warp_pdfs(warp, arguments));
      return;
    }
    case Function::PointLightIntensity: {
      const auto power = in.get<glm::vec3>();
      out.put(point_light_intensity(power));
      return;
    }
    case Function::PointLightIrradiance: {
      const auto intensity = in.get<glm::vec3>();
      const auto position = in.get<glm::vec3>(), point = in.get<glm::vec3>(), normal = in.get<glm::vec3>();
      out.put(point_light_irradiance(intensity, position, point, normal));
      return;
    }
    case Function::LambertianF: {
      const auto albedo = in.get<glm::vec3>();
      out.put(lambertian_f(albedo));
      return;
    }
    case Function::AreaPdfToSolidAngle: {
      const auto pdf_area = in.get<float>(), distance = in.get<float>(), cos_at_light = in.get<float>();
      out.put(area_pdf_to_solid_angle(pdf_area, distance, cos_at_light));
      return;
    }
    case Function::DirectLightSamples: {
      DirectLightScene scene;
      scene.triangles = in.get_vector<DirectLightTriangle>();
      scene.spheres = in.get_vector<DirectLightSphere>();
      scene.point_lights = in.get_vector<DirectLightPoint>();
      const auto queries = in.get_vector<DirectLightQuery>();
      const auto seed = in.get<std::uint64_t>();
      out.put_vector(direct_light_samples(scene, queries, seed));
      return;
    }
    case Function::PathRender: {
      const std::string scene_path = in.get_string();
      const auto request = in.get<PathRenderRequest>();
      const PathRenderResult result = path_render(scene_path, request);
      out.put<int>(result.mean.width());
      out.put<int>(result.mean.height());
      out.put_vector(result.mean.pixels());
      out.put_vector(result.variance_of_mean.pixels());
      return;
    }
    case Function::RenderStageImage: {
      const Image image = render_stage_image(in.get_string());
      out.put<int>(image.width());
      out.put<int>(image.height());
      out.put_vector(image.pixels());
      return;
    }
  }
  throw ProtocolError("unknown request");
}

}  // namespace

int main(int argc, char** argv) {
  try {
    adopt_channels(argc, argv);
  } catch (const std::exception& e) {
    std::cerr << "stage server: " << e.what() << "\n";
    return 2;
  }
  std::string request;
  Cache cache;
  for (;;) {
    try {
      if (!read_frame(kRequestFd, request)) return 0;  // the judge is done with this process
    } catch (const std::exception& e) {
      std::cerr << "stage server: " << e.what() << "\n";
      return 0;
    }
    Writer out;
    out.put(kReturn);
    try {
      Reader in(request);
      if (in.get<std::uint8_t>() != kCall) throw ProtocolError("expected a call");
      answer(in, out, cache);
    } catch (const NotImplemented& e) {
      out = Writer{};
      out.put(kThrow);
      out.put(ExceptionKind::NotImplemented);
      out.put_string(e.what());
      out.put_string(e.stage_id());
      out.put_string(e.function());
    } catch (const std::bad_alloc&) {
      out = Writer{};
      out.put(kThrow);
      out.put(ExceptionKind::Other);
      out.put_string("ran out of memory (std::bad_alloc): the stage's memory limit was reached "
                     "(a container that grows without end? memory allocated in every call and never freed?)");
      out.put_string("");
      out.put_string("");
    } catch (const std::invalid_argument& e) {
      out = Writer{};
      out.put(kThrow);
      out.put(ExceptionKind::InvalidArgument);
      out.put_string(e.what());
      out.put_string("");
      out.put_string("");
    } catch (const std::exception& e) {
      out = Writer{};
      out.put(kThrow);
      out.put(ExceptionKind::Other);
      out.put_string(e.what());
      out.put_string("");
      out.put_string("");
    } catch (...) {
      out = Writer{};
      out.put(kThrow);
      out.put(ExceptionKind::Other);
      out.put_string("an exception that is not a std::exception");
      out.put_string("");
      out.put_string("");
    }
    write_frame(kReplyFd, out.bytes());
  }
}
