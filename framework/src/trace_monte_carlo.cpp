// raylab trace, the Monte Carlo part (raylab/trace.h): the path one pixel
// sample took through your code, rebuilt from the framework calls your code
// made (raylab/trace_recorder.h), and at each of its surfaces your stage
// functions beside what the contract gives for the same inputs and the same
// random numbers.
//   Your estimate_direct_light and path_radiance are opaque, so what the
//   contract gives for them is
// computed from the calls they made: the light chosen (LightSet::choose), its
// point (sample_li), the shadow ray, the bounce (bsdf_sample_f). A correct
// function whose random numbers come in another order makes other calls, and
// the contract follows them: only the rules are held to, never one order of the
// random numbers.
#include "raylab/trace.h"

#include "trace_text.h"

#include "raylab/bsdf.h"
#include "raylab/lights.h"
#include "raylab/math.h"
#include "raylab/sampler.h"
#include "raylab/shading.h"
#include "raylab/stages/07_sampling.h"
#include "raylab/stages/08_direct_light.h"
#include "raylab/stages/09_path.h"
#include "raylab/trace_recorder.h"

#include <algorithm>
#include <cmath>
#include <exception>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace raylab {

using namespace trace_text;

namespace {

constexpr double kPiInDouble = 3.14159265358979323846;
using Kind = RecordedCall::Kind;

// Composite values (a light's estimate, a path's radiance) summed in another
// order by a correct function agree to this fraction.
constexpr double kValueTolerance = 1e-3;

bool same_direction(const glm::vec3& a, const glm::vec3& b) {
  const float la = glm::length(a), lb = glm::length(b);
  if (!(la > 0.0f) || !(lb > 0.0f)) return false;
  return glm::dot(a, b) / (la * lb) > 1.0f - 1e-5f;
}

std::string material_text(const Scene& scene, const SurfaceHit& hit) {
  const Material& material = scene.materials[hit.material];
  return material.name.empty() ? "material " + std::to_string(hit.material) : "material '" + material.name + "'";
}

std::string hit_text(const Scene& scene, const std::optional<SurfaceHit>& hit) {
  if (!hit) return "nothing: the background";
  return "hit at t = " + text(hit->t_hit) + ", point " + text(hit->point) + ", " + material_text(scene, *hit);
}

const char* bsdf_name(const Bsdf& bsdf) {
  switch (bsdf.kind) {
    case BsdfKind::Lambertian:
      return "diffuse";
    case BsdfKind::Mirror:
      return "mirror";
    case BsdfKind::Dielectric:
      return "glass";
    case BsdfKind::Microfacet:
      return "rough metal";
  }
  return "?";
}

// One surface of the path your code took: the ray it traced there and what your
// geometry found, and the calls made there (after that intersect, before the
// next surface's).
struct PathVertex {
  Ray ray;
  std::optional<SurfaceHit> hit;
  std::size_t first = 0, end = 0;        // the calls [first, end)
  const RecordedCall* bounce = nullptr;  // the first bsdf_sample_f among them
};

// The path: from the camera ray's intersect, each next surface is the first
// intersect along the direction bsdf_sample_f gave at the last one.
std::vector<PathVertex> path_of(const std::vector<RecordedCall>& calls, const Ray& camera_ray) {
  std::vector<PathVertex> path;
  glm::vec3 direction = camera_ray.direction;
  std::size_t from = 0;
  const auto next_intersect = [&](std::size_t i) {
    while (i < calls.size() && !(calls[i].kind == Kind::Intersect && same_direction(calls[i].ray.direction, direction)))
      ++i;
    return i;
  };
  std::size_t at = next_intersect(from);
  while (at < calls.size()) {
    PathVertex vertex;
    vertex.ray = calls[at].ray;
    vertex.hit = calls[at].hit;
    vertex.first = at + 1;
    vertex.end = calls.size();
    for (std::size_t k = vertex.first; k < calls.size(); ++k)
      if (calls[k].kind == Kind::BsdfSample) {
        vertex.bounce = &calls[k];
        break;
      }
    const bool goes_on = vertex.hit && vertex.bounce && vertex.bounce->bsdf_sample;
    if (goes_on) {
      direction = vertex.bounce->bsdf_sample->wi;
      from = static_cast<std::size_t>(vertex.bounce - calls.data()) + 1;
      at = next_intersect(from);
      vertex.end = at;
    } else {
      at = calls.size();
    }
    path.push_back(vertex);
  }
  return path;
}

// The light sampled among the calls [first, end): the choice, the point, your
// shadow ray's answer.
struct LightCalls {
  const RecordedCall* choice = nullptr;
  const RecordedCall* sample = nullptr;
  std::optional<bool> your_blocked;  // nullopt: your code traced no shadow ray towards the point
};

LightCalls light_calls(const std::vector<RecordedCall>& calls, std::size_t first, std::size_t end) {
  LightCalls found;
  for (std::size_t i = first; i < end; ++i) {
    const RecordedCall& call = calls[i];
    if (call.kind == Kind::LightChoice && !found.choice && !found.sample) found.choice = &call;
    if (call.kind == Kind::LightSample && !found.sample) found.sample = &call;
    if (!found.sample || !found.sample->light_sample || found.your_blocked) continue;
    const LightSample& sample = *found.sample->light_sample;
    if (call.kind == Kind::Occluded && same_direction(call.ray.direction, sample.point - call.ray.origin))
      found.your_blocked = call.blocked;
    if (call.kind == Kind::Intersect && same_direction(call.ray.direction, sample.point - call.ray.origin)) {
      // A shadow ray traced as a closest hit: blocked by a hit short of the
      // light's point.
      const float to_point = glm::length(sample.point - call.ray.origin);
      found.your_blocked = call.hit && call.hit->t_hit * glm::length(call.ray.direction) < to_point * (1.0f - 1e-3f);
    }
  }
  return found;
}

// The contract's f for a pair of directions: stage 08's albedo / pi on wo's
// side for a diffuse surface; the framework's (stage 10's) for a rough metal; 0
// for mirrors and glass.
glm::dvec3 contract_f(const Bsdf& bsdf, const glm::vec3& normal, const glm::vec3& wo, const glm::vec3& wi) {
  if (bsdf.is_specular()) return glm::dvec3(0.0);
  if (!(glm::dot(normal, wo) * glm::dot(normal, wi) > 0.0f)) return glm::dvec3(0.0);
  if (bsdf.kind == BsdfKind::Lambertian) return glm::dvec3(bsdf.albedo) / kPiInDouble;
  return glm::dvec3(bsdf_f(bsdf, normal, wo, wi));
}

// A sampled light point's density per steradian as the contract gives it (stage
// 08's area_pdf_to_solid_angle of uniform area sampling), and its inputs.
struct LightDensity {
  double pdf_area = 0.0, distance = 0.0, cos_at_light = 0.0, per_steradian = 1.0;
};
LightDensity contract_light_density(const Light& light, const LightSample& sample) {
  LightDensity density;
  if (light.kind == LightKind::Point) return density;  // a delta light: no density
  density.pdf_area = 1.0 / double(light.area);
  density.distance = sample.distance;
  const glm::dvec3 normal = light.kind == LightKind::Triangle
                                ? glm::dvec3(light.normal)
                                : glm::normalize(glm::dvec3(sample.point) - glm::dvec3(light.sphere.center));
  // The sphere's normal points out; from inside (an enclosure) the light leaves
  // the other side.
  density.cos_at_light = std::fabs(glm::dot(normal, glm::dvec3(sample.direction)));
  density.per_steradian = density.pdf_area * density.distance * density.distance / density.cos_at_light;
  return density;
}

// What the contract's estimate_direct_light gives at `hit` for the light sample
// your code drew.
struct ContractDirect {
  std::optional<glm::dvec3> value;  // nullopt: not known from your calls (`why`)
  std::string why, what;            // what: the light sample, in words
};

ContractDirect contract_direct(const RenderContext& contract, const SurfaceHit& hit, const Bsdf& bsdf,
                               const glm::vec3& wo, const LightCalls& found) {
  ContractDirect direct;
  if (contract.lights.empty()) {
    direct.value = glm::dvec3(0.0);
    direct.what = "the scene has no lights";
    return direct;
  }
  if (!found.sample) {
    direct.why = "your code sampled no light point with sample_li";
    return direct;
  }
  double chosen_with = 1.0;
  if (found.choice) {
    chosen_with = found.choice->choice_probability;
  } else if (contract.lights.size() > 1) {
    direct.why = "your code chose its light without context.lights.choose";
    return direct;
  }
  if (!found.sample->light_sample) {
    direct.value = glm::dvec3(0.0);
    direct.what = "sample_li gave no sample (the light seen from behind or edge-on)";
    return direct;
  }
  const LightSample& sample = *found.sample->light_sample;
  const LightDensity density = contract_light_density(found.sample->light, sample);
  const glm::vec3& normal = hit.geometric_normal;
  const glm::dvec3 f = contract_f(bsdf, normal, wo, sample.direction);
  Ray shadow;  // from just off the surface to just short of the light's point
  shadow.origin = offset_ray_origin(hit, sample.direction);
  shadow.direction = sample.point - shadow.origin;
  shadow.t_max = 1.0f - 1e-4f;
  const bool blocked = f != glm::dvec3(0.0) && contract.geometry.occluded(shadow);
  const double cosine = std::fabs(glm::dot(glm::dvec3(normal), glm::dvec3(sample.direction)));
  direct.value =
      blocked ? glm::dvec3(0.0) : f * glm::dvec3(sample.radiance) * (cosine / (density.per_steradian * chosen_with));
  direct.what = "light " + std::to_string(found.choice ? found.choice->light_index : 0) + " (chosen with probability " +
                text(chosen_with) + "), its point " + text(sample.point) + ", pdf " + text(density.per_steradian) +
                " per sr; the shadow ray " +
                (f == glm::dvec3(0.0) ? "not needed (f = 0)"
                 : blocked            ? "blocked"
                                      : "clear");
  if (found.your_blocked && f != glm::dvec3(0.0) && *found.your_blocked != blocked)
    direct.what += std::string("; your shadow ray found it ") + (*found.your_blocked ? "blocked" : "clear");
  return direct;
}

// Your stage function's value, or why there is none.
template <typename Value>
struct Outcome {
  std::optional<Value> value;
  std::string failure;  // "... not written yet", or what it threw
  // A stub reached from the call (perhaps of another stage:
  // estimate_direct_light samples lights with stage 07's warps): the step is
  // marked at it.
  std::string stub_stage, stub_function;
};
template <typename Call>
auto outcome_of(const Call& call) -> Outcome<decltype(call())> {
  Outcome<decltype(call())> result;
  try {
    result.value = call();
  } catch (const NotImplemented& e) {
    result.failure = e.function() + " not written yet";
    result.stub_stage = e.stage_id();
    result.stub_function = e.function();
  } catch (const std::exception& e) {
    result.failure = std::string("threw: ") + e.what();
  }
  return result;
}

// A step whose call reached a stub: marked at the stub, not at the function
// that called it.
template <typename Value>
TraceStep marked_at_stub(TraceStep step, const Outcome<Value>& outcome) {
  if (!outcome.stub_function.empty() && outcome.stub_function != step.function) {
    step.note = "your " + step.function + " called " + outcome.stub_function + ", not written yet";
    step.stage = outcome.stub_stage;
    step.function = outcome.stub_function;
  }
  return step;
}

// What the contract's rules make of a path (stage 09's path_radiance), given
// each surface's terms; each rule can be broken on purpose, to name the mistake
// that gives your value.
struct PathRules {
  bool divide_by_p = true;
  bool cosine = true;
  bool f_over_pi = true;
  bool camera_emission = true;
  bool emission_after_specular = true;
  bool emission_after_diffuse = false;
  bool background = true;
  bool last_surface = true;  // the surface at depth == max_depth counts
  // Correct variants: Russian roulette with a probability of your own instead
  // of context.continue_probability's (the same mean): a fixed one, or
  // pbrt-v4's, the throughput's largest channel kept within [0.05, 1].
  float own_fixed_p = 0.0f;  // 0: none
  bool own_p_by_throughput = false;
};

struct SurfaceTerms {
  bool hit = false;
  glm::dvec3 emission{0.0};
  bool specular = false;
  std::optional<glm::dvec3> direct;  // the contract's estimate for your light sample (0 at mirrors)
  bool went_on = false;              // your path has a next surface
  // The bounce from here: f, |cos| and pdf as the contract has them.
  glm::dvec3 albedo{0.0}, f{0.0};
  double cosine = 0.0, pdf = 0.0;
  bool diffuse_bounce = false, specular_bounce = false;
};

std::optional<glm::dvec3> path_value(const std::vector<SurfaceTerms>& surfaces, const RenderContext& context,
                                     const PathRules& rules) {
  glm::dvec3 radiance(0.0), throughput(1.0);
  bool after_specular = true;
  for (std::size_t depth = 0; depth < surfaces.size(); ++depth) {
    const SurfaceTerms& surface = surfaces[depth];
    if (!surface.hit) return rules.background ? radiance + throughput * glm::dvec3(context.scene.background) : radiance;
    if (!rules.last_surface && static_cast<int>(depth) >= context.max_depth) return radiance;
    const bool counts = depth == 0       ? rules.camera_emission
                        : after_specular ? rules.emission_after_specular
                                         : rules.emission_after_diffuse;
    if (counts) radiance += throughput * surface.emission;
    if (!surface.specular) {
      if (!surface.direct) return std::nullopt;
      radiance += throughput * *surface.direct;
    }
    if (static_cast<int>(depth) >= context.max_depth || !surface.went_on) return radiance;
    float p = context.continue_probability(static_cast<int>(depth), glm::vec3(throughput));
    if (rules.own_fixed_p > 0.0f) p = rules.own_fixed_p;
    if (rules.own_p_by_throughput)
      p = float(std::min(1.0, std::max(0.05, std::max(throughput.x, std::max(throughput.y, throughput.z)))));
    if (p < 1.0f && rules.divide_by_p) throughput /= double(p);
    const glm::dvec3 f = surface.diffuse_bounce && !rules.f_over_pi ? surface.albedo : surface.f;
    throughput *= f * ((rules.cosine ? surface.cosine : 1.0) / surface.pdf);
    after_specular = surface.specular_bounce;
  }
  return radiance;
}

struct PathMistake {
  const char* words;
  std::function<void(PathRules&)> make;
};
const std::vector<PathMistake>& path_mistakes() {
  static const std::vector<PathMistake> mistakes = {
      {"Russian roulette not divided by p (a path that goes on must be divided "
       "by p)",
       [](PathRules& r) { r.divide_by_p = false; }},
      {"the cosine missing from the bounce weight f |cos| / pdf", [](PathRules& r) { r.cosine = false; }},
      {"a diffuse bounce weighed with f = the albedo (1 / pi missing)", [](PathRules& r) { r.f_over_pi = false; }},
      {"emission counted after a diffuse bounce too (estimate_direct_light "
       "counted it already)",
       [](PathRules& r) { r.emission_after_diffuse = true; }},
      {"no emission counted after a mirror or glass bounce", [](PathRules& r) { r.emission_after_specular = false; }},
      {"the emission of a light the camera sees left out", [](PathRules& r) { r.camera_emission = false; }},
      {"black where the path leaves the scene, not the background", [](PathRules& r) { r.background = false; }},
      {"the surface at depth == max_depth left out", [](PathRules& r) { r.last_surface = false; }},
  };
  return mistakes;
}

// Your value as a correct path's with a Russian roulette probability of its own
// (PathRules), in words, or "".
std::string fitted_own_roulette(const std::vector<SurfaceTerms>& surfaces, const RenderContext& context,
                                const glm::vec3& yours) {
  const auto fits = [&](const PathRules& rules) {
    const std::optional<glm::dvec3> value = path_value(surfaces, context, rules);
    return value && near(glm::dvec3(yours), *value, kValueTolerance);
  };
  PathRules by_throughput;
  by_throughput.own_p_by_throughput = true;
  if (fits(by_throughput))
    return "your path plays Russian roulette with a probability of its own, "
           "the throughput's largest channel "
           "(as pbrt-v4 does), not context.continue_probability's: the same "
           "mean, and right along this path";
  // A fixed probability of the common ones (GAMES101 assignment 7 uses 0.8).
  // Not any number: with one bounce, some fixed probability gives every value
  // that a wrong factor on the bounce gives.
  for (const float p : {0.5f, 0.6f, 0.7f, 0.75f, 0.8f, 0.85f, 0.9f, 0.95f, 0.99f}) {
    PathRules fixed;
    fixed.own_fixed_p = p;
    if (fits(fixed))
      return "your path plays Russian roulette with a fixed probability of its "
             "own, " +
             text(p) +
             ", not context.continue_probability's: the same mean, and right "
             "along this path";
  }
  return "";
}

// The mistakes (one, or two together) whose rules give `yours` where the
// contract's do not.
std::string fitted_mistakes(const std::vector<SurfaceTerms>& surfaces, const RenderContext& context,
                            const glm::vec3& yours, const glm::dvec3& contract) {
  const auto& mistakes = path_mistakes();
  const auto fits = [&](const PathRules& rules) {
    const std::optional<glm::dvec3> value = path_value(surfaces, context, rules);
    return value && !near(*value, contract, kValueTolerance) && near(glm::dvec3(yours), *value, kValueTolerance);
  };
  for (const PathMistake& mistake : mistakes) {
    PathRules rules;
    mistake.make(rules);
    if (fits(rules)) return std::string("your value is the contract's with ") + mistake.words;
  }
  for (std::size_t a = 0; a < mistakes.size(); ++a)
    for (std::size_t b = a + 1; b < mistakes.size(); ++b) {
      PathRules rules;
      mistakes[a].make(rules);
      mistakes[b].make(rules);
      if (fits(rules))
        return std::string(
                   "your value is the contract's with two mistakes "
                   "together: ") +
               mistakes[a].words + "; and " + mistakes[b].words;
    }
  return "";
}

}  // namespace

void trace_monte_carlo(const Scene& scene, const Ray& camera_ray, Sampler& sampler, const TracingFunctions& contract,
                       PixelTrace& trace) {
  const TraceSettings& settings = trace.settings;
  const bool path_tracer = settings.integrator == IntegratorKind::Path;
  // Yours: the geometry your stages 02-05 trace (as raylab render's); the
  // contract's: every primitive tested with the kit's exact tests. Every ray is
  // traced (no skip of rays outside the scene's bounds), so that each one is
  // seen.
  const SceneGeometry your_geometry(scene);
  const SceneGeometry contract_geometry(scene, Acceleration::BruteForce, TriangleTest::MollerTrumbore, contract);
  const RenderContext yours(scene, your_geometry, settings.max_depth, Skips::none(), settings.roulette);
  const RenderContext contracts(scene, contract_geometry, settings.max_depth, Skips::none(), settings.roulette);
  std::vector<TraceStep>& steps = trace.steps;

  // Your code's sample, with every framework call it makes recorded.
  TraceRecorder recorder;
  Outcome<glm::vec3> radiance;
  {
    RecordingCalls recording(recorder);
    ShadingStats stats;
    radiance = outcome_of([&] {
      return path_tracer ? path_radiance(yours, camera_ray, sampler)
                         : direct_light_li(yours, camera_ray, sampler, stats);
    });
  }
  const std::vector<RecordedCall>& calls = recorder.calls;
  const std::vector<PathVertex> path = path_of(calls, camera_ray);

  std::vector<SurfaceTerms> surfaces;
  glm::dvec3 throughput(1.0);  // the contract's, for the roulette's p
  bool own_bounce_sampling = false;
  std::optional<int> ended_early;  // the surface where your path stopped and the
                                   // contract's goes on
  for (std::size_t depth = 0; depth < path.size(); ++depth) {
    const PathVertex& vertex = path[depth];
    const std::string at = "surface " + std::to_string(depth);
    SurfaceTerms surface;
    // The closest hit of a bounce ray (the camera ray's is above).
    if (depth > 0) {
      const std::optional<SurfaceHit> expected = contract_geometry.intersect(vertex.ray);
      TraceStep step{"", "", at + ": the closest hit along the bounce ray (" + text(vertex.ray) + ")",
                     hit_text(scene, vertex.hit), hit_text(scene, expected)};
      step.agrees =
          vertex.hit.has_value() == expected.has_value() &&
          (!expected || (near(vertex.hit->t_hit, expected->t_hit) && vertex.hit->material == expected->material));
      if (!step.agrees)
        step.note =
            "your geometry (stages 02-05: spheres, triangles, boxes, "
            "trees) finds another closest hit";
      steps.push_back(step);
    }
    if (!vertex.hit) {
      surfaces.push_back(surface);
      break;
    }
    const SurfaceHit& hit = *vertex.hit;
    const Material& material = scene.materials[hit.material];
    const Bsdf bsdf = bsdf_of(material, diffuse_color_at(material, hit));
    const glm::vec3 wo = -glm::normalize(vertex.ray.direction);
    surface.hit = true;
    surface.emission = glm::dvec3(emitted_radiance(material, hit, vertex.ray.direction));
    surface.specular = bsdf.is_specular();

    if (bsdf.kind == BsdfKind::Lambertian) {
      const Outcome<glm::vec3> f = outcome_of([&] { return lambertian_f(bsdf.albedo); });
      const glm::dvec3 expected = glm::dvec3(bsdf.albedo) / kPiInDouble;
      TraceStep step{
          "08_direct_light", "lambertian_f",
          at + " (" + material_text(scene, hit) + ", diffuse): lambertian_f(albedo " + text(bsdf.albedo) + ")",
          f.value ? text(*f.value) : f.failure, text(expected) + "  (albedo / pi)"};
      step.agrees = f.value && near(glm::dvec3(*f.value), expected);
      steps.push_back(step);
    }

    if (!surface.specular) {
      // Your estimate_direct_light on its own, on a sampler of its own, with
      // its calls recorded: the contract's value for the light sample it drew.
      TraceRecorder probe_recorder;
      Outcome<glm::vec3> estimate;
      {
        RecordingCalls recording(probe_recorder);
        Sampler probe(settings.samples_per_pixel, settings.seed + 1);
        probe.start_pixel_sample(trace.x, trace.y, settings.sample);
        estimate = outcome_of([&] { return estimate_direct_light(yours, hit, bsdf, wo, probe); });
      }
      const LightCalls probe_calls = light_calls(probe_recorder.calls, 0, probe_recorder.calls.size());
      if (probe_calls.sample && probe_calls.sample->light_sample &&
          probe_calls.sample->light.kind != LightKind::Point) {
        const LightDensity density =
            contract_light_density(probe_calls.sample->light, *probe_calls.sample->light_sample);
        const Outcome<float> pdf = outcome_of([&] {
          return area_pdf_to_solid_angle(float(density.pdf_area), float(density.distance), float(density.cos_at_light));
        });
        TraceStep step{"08_direct_light", "area_pdf_to_solid_angle",
                       at + ": area_pdf_to_solid_angle(pdf_area " + text(density.pdf_area) + ", distance " +
                           text(density.distance) + ", cos_at_light " + text(density.cos_at_light) + ")",
                       pdf.value ? text(*pdf.value) : pdf.failure,
                       text(density.per_steradian) + "  (pdf_area * distance^2 / cos_at_light)"};
        step.agrees = pdf.value && near(*pdf.value, density.per_steradian);
        steps.push_back(step);
      }
      const ContractDirect expected = contract_direct(contracts, hit, bsdf, wo, probe_calls);
      TraceStep step{"08_direct_light",
                     "estimate_direct_light",
                     at + ": estimate_direct_light(context, hit, bsdf, wo, sampler)",
                     estimate.value ? text(*estimate.value) : estimate.failure,
                     expected.value ? text(*expected.value) : "not checked: " + expected.why,
                     expected.what};
      step.agrees =
          estimate.value && (!expected.value || near(glm::dvec3(*estimate.value), *expected.value, kValueTolerance));
      steps.push_back(marked_at_stub(step, estimate));

      // The same for the light sample of your path itself (its value is not
      // seen, only its calls).
      const LightCalls path_calls = light_calls(calls, vertex.first, vertex.end);
      surface.direct = contract_direct(contracts, hit, bsdf, wo, path_calls).value;
    } else {
      surface.direct = glm::dvec3(0.0);
    }

    // The bounce.
    surface.went_on = depth + 1 < path.size();
    if (vertex.bounce) {
      const RecordedCall& bounce = *vertex.bounce;
      std::string roulette;
      const float p = contracts.continue_probability(static_cast<int>(depth), glm::vec3(throughput));
      if (path_tracer && static_cast<int>(depth) < settings.max_depth && (p < 1.0f || !surface.went_on)) {
        roulette =
            "Russian roulette: p = context.continue_probability(" + std::to_string(depth) + ", throughput " +
            text(glm::vec3(throughput)) + ") = " + text(p) +
            (surface.went_on ? (p < 1.0f ? "; your path went on (the contract divides by p)" : "; your path went on")
                             : "; your path ended here");
      }
      const std::string call =
          at + ": bsdf_sample_f(" + bsdf_name(bsdf) + ", u_lobe " + text(bounce.u_lobe) + ", u " + text(bounce.u) + ")";
      if (!bounce.bsdf_sample) {
        steps.push_back(
            TraceStep{"", "", call, "no sample: the path ends", "no sample: the path ends", roulette, true});
      } else {
        const BsdfSample& sample = *bounce.bsdf_sample;
        const glm::vec3 facing =
            glm::dot(hit.geometric_normal, wo) > 0.0f ? hit.geometric_normal : -hit.geometric_normal;
        const double cosine = std::fabs(glm::dot(glm::dvec3(hit.geometric_normal), glm::dvec3(sample.wi)));
        surface.cosine = cosine;
        surface.specular_bounce = sample.is_specular;
        const std::string got =
            "wi " + text(sample.wi) + ", f " + text(sample.f) + ", pdf " + text(sample.pdf) + ", |cos| " + text(cosine);
        if (bsdf.kind == BsdfKind::Lambertian) {
          // Stage 07's warp and density: any cosine-weighted warp is right (the
          // grader tests the distribution); its direction must be unit and
          // above the surface, and its pdf cos / pi.
          const double length = glm::length(glm::dvec3(sample.wi));
          const double cos_facing = glm::dot(glm::dvec3(facing), glm::dvec3(sample.wi)) / length;
          const bool direction_ok = std::fabs(length - 1.0) < 1e-3 && cos_facing > 0.0;
          TraceStep step{"07_sampling",
                         direction_ok ? "cosine_hemisphere_pdf" : "sample_cosine_hemisphere",
                         call +
                             ": your sample_cosine_hemisphere(u) and "
                             "cosine_hemisphere_pdf",
                         got,
                         direction_ok ? "pdf " + text(cos_facing / kPiInDouble) + "  (cos / pi for this direction)"
                                      : "a unit direction above the surface (|wi| = 1, "
                                        "z > 0 locally)",
                         roulette};
          step.agrees = direction_ok && near(sample.pdf, cos_facing / kPiInDouble);
          steps.push_back(step);
          surface.diffuse_bounce = true;
          surface.albedo = glm::dvec3(bsdf.albedo);
          surface.f = glm::dvec3(bsdf.albedo) / kPiInDouble;
          surface.pdf = cosine / kPiInDouble;
        } else {
          steps.push_back(
              TraceStep{"", "", call, got, "the framework's (" + std::string(bsdf_name(bsdf)) + ")", roulette, true});
          surface.f = glm::dvec3(sample.f);
          surface.pdf = sample.pdf;
        }
        if (p < 1.0f) throughput /= double(p);
        throughput *= surface.f * (surface.cosine / surface.pdf);
      }
    } else if (path_tracer && static_cast<int>(depth) < settings.max_depth && !bsdf.is_black()) {
      const float p = contracts.continue_probability(static_cast<int>(depth), glm::vec3(throughput));
      if (p < 1.0f)
        steps.push_back(TraceStep{"", "",
                                  at + ": Russian roulette, p = context.continue_probability(" + std::to_string(depth) +
                                      ", throughput " + text(glm::vec3(throughput)) + ")",
                                  "the path ended here", "p = " + text(p) + ": the path goes on with probability p", "",
                                  true});
      // No bsdf_sample_f: your code sampled the bounce itself (a ray traced
      // here that is no shadow ray), or the path ended here, which without
      // roulette (p = 1) the contract does not.
      const LightCalls light = light_calls(calls, vertex.first, vertex.end);
      for (std::size_t i = vertex.first; i < vertex.end; ++i)
        if (calls[i].kind == Kind::Intersect &&
            !(light.sample && light.sample->light_sample &&
              same_direction(calls[i].ray.direction, light.sample->light_sample->point - calls[i].ray.origin)))
          own_bounce_sampling = true;
      if (!own_bounce_sampling &&
          contracts.continue_probability(static_cast<int>(depth), glm::vec3(throughput)) >= 1.0f)
        ended_early = static_cast<int>(depth);
    }
    surfaces.push_back(surface);
  }

  if (!path_tracer) return;
  // path_radiance's value against the contract's rules on the same path.
  TraceStep step{"09_path", "path_radiance", "path_radiance(context, camera_ray, sampler): this sample's value",
                 radiance.value ? text(*radiance.value) : radiance.failure, ""};
  if (!radiance.value) {
    step.expected = "a radiance, three finite numbers";
    step.agrees = false;
    steps.push_back(marked_at_stub(step, radiance));
    return;
  }
  const std::optional<glm::dvec3> expected =
      own_bounce_sampling ? std::nullopt : path_value(surfaces, contracts, PathRules{});
  if (own_bounce_sampling) {
    step.expected =
        "not checked: your path samples its bounces without "
        "bsdf_sample_f, which the trace follows";
  } else if (!expected) {
    step.expected = "not checked: a light sample of your path could not be followed";
  } else {
    step.expected = text(*expected) +
                    "  (the contract's rules on your path's "
                    "surfaces, light samples and bounces)";
    step.agrees = near(glm::dvec3(*radiance.value), *expected, kValueTolerance);
    const int last_depth = static_cast<int>(path.size()) - 1;
    if (last_depth > settings.max_depth) {
      step.agrees = false;
      step.note = "your path went on after the surface at depth max_depth = " + std::to_string(settings.max_depth);
    } else if (!step.agrees) {
      // A mistake that gives your value comes first; a roulette of your own
      // that gives it too is named beside it (one sample cannot tell them
      // apart), and alone it is no disagreement.
      const std::string mistake = fitted_mistakes(surfaces, contracts, *radiance.value, *expected);
      const std::string own_roulette = fitted_own_roulette(surfaces, contracts, *radiance.value);
      if (!mistake.empty()) {
        step.note = mistake;
        if (!own_roulette.empty()) step.note += " (or else " + own_roulette + ")";
      } else if (!own_roulette.empty()) {
        step.agrees = true;
        step.expected = text(*expected) + "  (with context.continue_probability's p)";
        step.note = own_roulette;
      }
    }
    if (ended_early && step.agrees)
      step.note += (step.note.empty() ? "" : "; ") + std::string("your path ended at surface ") +
                   std::to_string(*ended_early) +
                   ", where context.continue_probability's p = 1 goes on: "
                   "right only with a roulette of your own";
  }
  if (recorder.overflowed)
    step.note += (step.note.empty() ? "" : "; ") + std::string("only the first calls were followed");
  steps.push_back(step);
}

}  // namespace raylab
