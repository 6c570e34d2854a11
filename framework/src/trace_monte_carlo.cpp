// raylab trace, the Monte Carlo part (raylab/trace.h): the path one pixel sample took through your
// code, rebuilt from the framework calls your code made (raylab/trace_recorder.h), and at each of
// its surfaces your stage functions beside what the contract gives for the same inputs and the
// same random numbers.
//   Your estimate_direct_light and path_radiance are opaque, so what the contract gives for them
// is computed from the calls they made: the light chosen (LightSet::choose), its point
// (sample_li), the shadow ray, the bounce (bsdf_sample_f). A correct function whose random numbers
// come in another order makes other calls, and the contract follows them: only the rules are held
// to, never one order of the random numbers.
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
#include "raylab/stages/09b_mis.h"
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

// Composite values (a light's estimate, a path's radiance) summed in another order by a correct
// function agree to this fraction.
constexpr double kValueTolerance = 1e-3;

bool same_direction(const glm::vec3& a, const glm::vec3& b) {
  const float la = glm::length(a), lb = glm::length(b);
  if (!(la > 0.0f) || !(lb > 0.0f)) return false;
  return glm::dot(a, b) / (la * lb) > 1.0f - 1e-5f;
}

std::string bsdf_name(const Words& words, const Bsdf& bsdf) {
  switch (bsdf.kind) {
    case BsdfKind::Lambertian:
      return words("diffuse", "漫反射");
    case BsdfKind::Mirror:
      return words("mirror", "镜面");
    case BsdfKind::Dielectric:
      return words("glass", "玻璃");
    case BsdfKind::Microfacet:
      return words("rough metal", "粗糙金属");
  }
  return "?";
}

// One surface of the path your code took: the ray it traced there and what your geometry found, and
// the calls made there (after that intersect, up to the next ray that is no shadow ray).
struct PathVertex {
  Ray ray;
  std::optional<SurfaceHit> hit;
  std::size_t first = 0, end = 0;        // the calls [first, end)
  const RecordedCall* bounce = nullptr;  // the first bsdf_sample_f among them
  // The ray traced next (calls[end]) does not follow the bounce: your code sampled its own.
  bool own_next_ray = false;
};

// A ray towards a light point sampled before it, among the calls [first, at): a shadow ray.
bool is_shadow_ray(const std::vector<RecordedCall>& calls, std::size_t first, std::size_t at) {
  for (std::size_t i = first; i < at; ++i)
    if (calls[i].kind == Kind::LightSample && calls[i].light_sample &&
        same_direction(calls[at].ray.direction, calls[i].light_sample->point - calls[at].ray.origin))
      return true;
  return false;
}

// The path: from the camera ray's intersect, each surface's calls run up to the next intersect that
// is no shadow ray, and that intersect is the next surface when it follows the direction
// bsdf_sample_f gave there.
std::vector<PathVertex> path_of(const std::vector<RecordedCall>& calls, const Ray& camera_ray) {
  std::vector<PathVertex> path;
  std::size_t at = 0;
  while (at < calls.size() && !(calls[at].kind == Kind::Intersect && same_direction(calls[at].ray.direction, camera_ray.direction)))
    ++at;
  while (at < calls.size()) {
    PathVertex vertex;
    vertex.ray = calls[at].ray;
    vertex.hit = calls[at].hit;
    vertex.first = at + 1;
    std::size_t next = vertex.first;
    for (; next < calls.size(); ++next) {
      if (calls[next].kind == Kind::BsdfSample && !vertex.bounce) vertex.bounce = &calls[next];
      if (calls[next].kind == Kind::Intersect && !is_shadow_ray(calls, vertex.first, next)) break;
    }
    vertex.end = next;
    const bool follows_the_bounce = next < calls.size() && vertex.hit && vertex.bounce && vertex.bounce->bsdf_sample &&
                                    same_direction(calls[next].ray.direction, vertex.bounce->bsdf_sample->wi);
    vertex.own_next_ray = next < calls.size() && !follows_the_bounce;
    path.push_back(vertex);
    if (!follows_the_bounce) break;
    at = next;
  }
  return path;
}

// The light sampled among the calls [first, end): the choice, the point, your shadow ray's answer.
struct LightCalls {
  const RecordedCall* choice = nullptr;
  const RecordedCall* sample = nullptr;
  std::optional<bool> your_blocked;  // nullopt: your code traced no shadow ray towards the point
  const RecordedCall* shadow = nullptr;  // that shadow ray
};

LightCalls light_calls(const std::vector<RecordedCall>& calls, std::size_t first, std::size_t end) {
  LightCalls found;
  for (std::size_t i = first; i < end; ++i) {
    const RecordedCall& call = calls[i];
    if (call.kind == Kind::LightChoice && !found.choice && !found.sample) found.choice = &call;
    if (call.kind == Kind::LightSample && !found.sample) found.sample = &call;
    if (!found.sample || !found.sample->light_sample || found.your_blocked) continue;
    const LightSample& sample = *found.sample->light_sample;
    if (call.kind == Kind::Occluded && same_direction(call.ray.direction, sample.point - call.ray.origin)) {
      found.your_blocked = call.blocked;
      found.shadow = &call;
    }
    if (call.kind == Kind::Intersect && same_direction(call.ray.direction, sample.point - call.ray.origin)) {
      found.shadow = &call;
      // A shadow ray traced as a closest hit: blocked by a hit short of the light's point.
      const float to_point = glm::length(sample.point - call.ray.origin);
      found.your_blocked = call.hit && call.hit->t_hit * glm::length(call.ray.direction) < to_point * (1.0f - 1e-3f);
    }
  }
  return found;
}

// The contract's f for a pair of directions: stage 08's albedo / pi on wo's side for a diffuse
// surface; the framework's (stage 10's) for a rough metal; 0 for mirrors and glass.
glm::dvec3 contract_f(const Bsdf& bsdf, const glm::vec3& normal, const glm::vec3& wo, const glm::vec3& wi) {
  if (bsdf.is_specular()) return glm::dvec3(0.0);
  if (!(glm::dot(normal, wo) * glm::dot(normal, wi) > 0.0f)) return glm::dvec3(0.0);
  if (bsdf.kind == BsdfKind::Lambertian) return glm::dvec3(bsdf.albedo) / kPiInDouble;
  return glm::dvec3(bsdf_f(bsdf, normal, wo, wi));
}

// The contract's density of the BSDF strategy for a direction (what MIS weighs against): stage 07's
// cos / pi on wo's side for a diffuse surface; the framework's (stage 10's) for a rough metal; 0
// for mirrors and glass.
double contract_bsdf_pdf(const Bsdf& bsdf, const glm::vec3& normal, const glm::vec3& wo, const glm::vec3& wi) {
  if (bsdf.is_specular()) return 0.0;
  const double cos_o = glm::dot(glm::dvec3(normal), glm::dvec3(wo)), cos_i = glm::dot(glm::dvec3(normal), glm::dvec3(wi));
  if (!(cos_o * cos_i > 0.0)) return 0.0;
  if (bsdf.kind == BsdfKind::Lambertian) return std::fabs(cos_i) / (glm::length(glm::dvec3(wi)) * kPiInDouble);
  return bsdf_pdf(bsdf, normal, wo, wi);
}

// The weight of a sample of strategy f (density pdf_f) against strategy g, one sample each: the
// power heuristic (exponent 2), or the balance heuristic (exponent 1, a mistake's rule); 1 for a
// delta (an infinite pdf_f), 0 where f cannot make the sample.
double mis_weight(double pdf_f, double pdf_g, int exponent = 2) {
  if (std::isinf(pdf_f)) return 1.0;
  if (!(pdf_f > 0.0)) return 0.0;
  const double f = exponent == 2 ? pdf_f * pdf_f : pdf_f, g = exponent == 2 ? pdf_g * pdf_g : pdf_g;
  return f / (f + g);
}

// A sampled light point's density per steradian as the contract gives it (stage 08's
// area_pdf_to_solid_angle of uniform area sampling), and its inputs.
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
  // The sphere's normal points out; from inside (an enclosure) the light leaves the other side.
  density.cos_at_light = std::fabs(glm::dot(normal, glm::dvec3(sample.direction)));
  density.per_steradian = density.pdf_area * density.distance * density.distance / density.cos_at_light;
  return density;
}

bool same_light(const Light& a, const Light& b) {
  if (a.kind != b.kind) return false;
  switch (a.kind) {
    case LightKind::Point: return a.position == b.position;
    case LightKind::Triangle: return a.p0 == b.p0 && a.p1 == b.p1 && a.p2 == b.p2;
    case LightKind::Sphere: return a.sphere.center == b.sphere.center && a.sphere.radius == b.sphere.radius;
  }
  return false;
}

// What the contract's estimate_direct_light gives at `hit` for the light sample your code drew. The
// shadow ray's answer is your geometry's where your code traced one (a different answer is your
// geometry's disagreement, `shadow`, not the estimator's).
struct ContractDirect {
  std::optional<glm::dvec3> value;  // nullopt: not known from your calls (`why`)
  std::string why, what;            // what: the light sample, in words
  std::string wrong_light;          // your code sampled another light than the one it chose
  std::optional<bool> your_blocked, contract_blocked;  // both set: the shadow ray, when your code traced one
  // The light strategy's density of the sample's direction (per steradian, the choice included),
  // and the direction: what MIS weighs the sample with (stage 09b). 0 with no sample.
  double light_pdf = 0.0;
  bool delta = false;  // a point light's sample: weight 1 under MIS
  glm::vec3 direction{0.0f};
};

ContractDirect contract_direct(const Words& words, const RenderContext& contract, const SurfaceHit& hit,
                               const Bsdf& bsdf, const glm::vec3& wo, const LightCalls& found) {
  ContractDirect direct;
  if (contract.lights.empty()) {
    direct.value = glm::dvec3(0.0);
    direct.what = words("the scene has no lights", "场景中没有光源");
    return direct;
  }
  if (!found.sample) {
    direct.why = words("your code sampled no light point with sample_li", "你的代码没有用 sample_li 采样光源上的点");
    return direct;
  }
  double chosen_with = 1.0;
  if (found.choice) {
    chosen_with = found.choice->choice_probability;
    if (found.choice->light_index < contract.lights.size() &&
        !same_light(contract.lights[found.choice->light_index], found.sample->light))
      direct.wrong_light = words("your code chose light ", "你的代码选择了光源 ") +
                           std::to_string(found.choice->light_index) +
                           words(" (context.lights.choose) but sampled a point on another light",
                                 "（context.lights.choose），却在另一个光源上采样了点");
  } else if (contract.lights.size() > 1) {
    direct.why = words("your code chose its light without context.lights.choose",
                       "你的代码没有用 context.lights.choose 选择光源");
    return direct;
  }
  if (!found.sample->light_sample) {
    direct.value = glm::dvec3(0.0);
    direct.what = words("sample_li gave no sample (the light seen from behind or edge-on)",
                        "sample_li 没有给出样本（从这里只看得到光源的背面或侧边）");
    return direct;
  }
  const LightSample& sample = *found.sample->light_sample;
  const LightDensity density = contract_light_density(found.sample->light, sample);
  direct.light_pdf = density.per_steradian * chosen_with;
  direct.delta = found.sample->light.kind == LightKind::Point;
  direct.direction = sample.direction;
  const glm::vec3& normal = hit.geometric_normal;
  const glm::dvec3 f = contract_f(bsdf, normal, wo, sample.direction);
  bool blocked = false;
  if (f != glm::dvec3(0.0)) {
    Ray shadow;  // from just off the surface to just short of the light's point
    shadow.origin = offset_ray_origin(hit, sample.direction);
    shadow.direction = sample.point - shadow.origin;
    shadow.t_max = 1.0f - 1e-4f;
    blocked = contract.geometry.occluded(shadow);
    if (found.your_blocked && *found.your_blocked != blocked) {
      direct.your_blocked = found.your_blocked;
      direct.contract_blocked = blocked;
      blocked = *found.your_blocked;
    }
  }
  const double cosine = std::fabs(glm::dot(glm::dvec3(normal), glm::dvec3(sample.direction)));
  direct.value = blocked ? glm::dvec3(0.0)
                         : f * glm::dvec3(sample.radiance) * (cosine / (density.per_steradian * chosen_with));
  direct.what = words("light ", "光源 ") + std::to_string(found.choice ? found.choice->light_index : 0) +
                words(" (chosen with probability ", "（以概率 ") + text(chosen_with) +
                words("), its point ", " 选中），它上面的点 ") + text(sample.point) + words(", pdf ", "，pdf ") +
                text(density.per_steradian) +
                (f == glm::dvec3(0.0) ? words(" per sr; the shadow ray not needed (f = 0)", " 每球面度；不需要阴影光线（f = 0）")
                 : blocked            ? words(" per sr; the shadow ray blocked", " 每球面度；阴影光线被遮挡")
                                      : words(" per sr; the shadow ray clear", " 每球面度；阴影光线没有被遮挡"));
  if (!direct.wrong_light.empty()) direct.what += words("; ", "；") + direct.wrong_light;
  return direct;
}

// Your shadow ray, where its answer is not the contract's: marked at `function` (the code that
// built it) when the ray itself breaks the contract's rules (it reaches the light's point, or
// starts on the surface), else at your geometry (stages 02-05).
std::optional<TraceStep> shadow_ray_step(const Words& words, const std::string& at, const LightCalls& found,
                                         const ContractDirect& direct, const SurfaceHit& hit, const std::string& stage,
                                         const std::string& function) {
  if (!direct.your_blocked || !found.shadow || !found.sample || !found.sample->light_sample) return std::nullopt;
  const Ray& ray = found.shadow->ray;
  TraceStep step{"", "",
                 at + words(": the shadow ray (", "：阴影光线（") + ray_text(words, ray) + words(", t_max ", "，t_max ") +
                     text(ray.t_max) + words(")", "）"),
                 blocked_text(words, *direct.your_blocked), blocked_text(words, *direct.contract_blocked), "", false};
  const glm::vec3 point = found.sample->light_sample->point;
  const float reach = ray.t_max * glm::length(ray.direction), to_point = glm::length(point - ray.origin);
  const bool reaches_the_light =
      found.shadow->kind == Kind::Occluded && *direct.your_blocked && reach >= to_point * (1.0f - 1e-6f);
  const bool starts_on_the_surface = ray.origin == hit.point;
  if (reaches_the_light || starts_on_the_surface) {  // the ray itself: the code that built it
    step.stage = stage;
    step.function = function;
  }
  step.note =
      reaches_the_light
          ? words("your shadow ray reaches the light's point and hits the light itself: stop it just short of the "
                  "point (direction = point - origin, t_max = 1 - 1e-4: docs/08_direct_light.md, section 5)",
                  "你的阴影光线到达了光源上的点，击中了光源本身：让它停在这个点之前一点点"
                  "（direction = point - origin，t_max = 1 - 1e-4：docs/zh/08_direct_light.md，第 5 节）")
      : starts_on_the_surface
          ? words("your shadow ray starts on the surface, where rounding puts it a little below, not at "
                  "offset_ray_origin(hit, direction)",
                  "你的阴影光线从表面上出发，舍入误差会让它落在表面下方一点点；要从 offset_ray_origin(hit, direction) "
                  "出发")
          : shadow_answer_note(words);
  return step;
}

// Your stage function's value, or why there is none.
template <typename Value>
struct Outcome {
  std::optional<Value> value;
  std::string failure;  // "... not written yet", or what it threw
  // A stub reached from the call (perhaps of another stage: estimate_direct_light samples lights
  // with stage 07's warps): the step is marked at it.
  std::string stub_stage, stub_function;
};
template <typename Call>
auto outcome_of(const Words& words, const Call& call) -> Outcome<decltype(call())> {
  Outcome<decltype(call())> result;
  try {
    result.value = call();
  } catch (const NotImplemented& e) {
    result.failure = e.function() + words(" not written yet", " 尚未编写");
    result.stub_stage = e.stage_id();
    result.stub_function = e.function();
  } catch (const std::exception& e) {
    result.failure = words("threw: ", "抛出了异常：") + e.what();
  }
  return result;
}

// A step whose call reached a stub: marked at the stub, not at the function that called it.
template <typename Value>
TraceStep marked_at_stub(const Words& words, TraceStep step, const Outcome<Value>& outcome) {
  if (!outcome.stub_function.empty() && outcome.stub_function != step.function) {
    step.note = words("your ", "你的 ") + step.function + words(" called ", " 调用了 ") + outcome.stub_function +
                words(", not written yet", "，它尚未编写");
    step.stage = outcome.stub_stage;
    step.function = outcome.stub_function;
  }
  return step;
}

// What the contract's rules make of a path (stage 09's path_radiance), given each surface's terms;
// each rule can be broken on purpose, to name the mistake that gives your value.
enum class OwnRoulette { None, Fixed, ByThroughputBefore, ByThroughputAfter };
struct PathRules {
  bool divide_by_p = true;
  bool cosine = true;
  bool f_over_pi = true;
  bool camera_emission = true;
  bool emission_after_specular = true;
  bool emission_after_diffuse = false;
  bool background = true;
  bool last_surface = true;            // the surface at depth == max_depth counts
  bool no_light_sample_is_zero = false;  // a diffuse surface whose light your code did not sample adds 0
  // Stage 09b's rules (path_radiance_mis): the light sample of a diffuse surface and the emission
  // found by the bounce from one both count, each weighted against the other strategy.
  bool mis = false;
  int mis_exponent = 2;              // 2: the power heuristic; 1: the balance heuristic
  bool mis_weigh_light = true;       // false: the light sample keeps weight 1
  bool mis_weigh_emission = true;    // false: the emission after a diffuse bounce counts fully
  bool mis_last_vertex_one = true;   // false: the light sample at depth == max_depth is weighted too
  // Correct variants: Russian roulette with a probability of your own instead of
  // context.continue_probability's (the same mean): a fixed one, or the throughput's largest
  // channel (before or after the bounce's weight, from depth `own_from_depth` on, at least
  // `own_floor`).
  OwnRoulette own = OwnRoulette::None;
  float own_fixed_p = 1.0f;
  int own_from_depth = 0;
  double own_floor = 0.0;
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
  // For MIS: the densities of the light sample's direction (the light strategy's, the choice
  // included, and the BSDF's; a point light's is a delta), and, for the emission found here after
  // a diffuse bounce, that bounce's density and the light strategy's of the same direction.
  double light_pdf = 0.0, light_bsdf_pdf = 0.0;
  bool light_delta = false;
  double emission_bsdf_pdf = 0.0, emission_light_pdf = 0.0;
};

std::optional<glm::dvec3> path_value(const std::vector<SurfaceTerms>& surfaces, const RenderContext& context,
                                     const PathRules& rules) {
  glm::dvec3 radiance(0.0), throughput(1.0);
  bool after_specular = true;
  const auto own_p = [&](int depth, const glm::dvec3& weight) {
    if (rules.own == OwnRoulette::Fixed) return double(rules.own_fixed_p);
    if (depth < rules.own_from_depth) return 1.0;
    const glm::dvec3 t = rules.own == OwnRoulette::ByThroughputAfter ? throughput * weight : throughput;
    return std::min(1.0, std::max(rules.own_floor, std::max(t.x, std::max(t.y, t.z))));
  };
  for (std::size_t depth = 0; depth < surfaces.size(); ++depth) {
    const SurfaceTerms& surface = surfaces[depth];
    if (!surface.hit) return rules.background ? radiance + throughput * glm::dvec3(context.scene.background) : radiance;
    if (!rules.last_surface && static_cast<int>(depth) >= context.max_depth) return radiance;
    const bool counts = depth == 0        ? rules.camera_emission
                        : after_specular ? rules.emission_after_specular
                                         : rules.emission_after_diffuse || rules.mis;
    const bool weigh_emission = rules.mis && rules.mis_weigh_emission && depth > 0 && !after_specular;
    if (counts)
      radiance += throughput * surface.emission *
                  (weigh_emission ? mis_weight(surface.emission_bsdf_pdf, surface.emission_light_pdf, rules.mis_exponent)
                                  : 1.0);
    if (!surface.specular) {
      const bool weigh_light = rules.mis && rules.mis_weigh_light && !surface.light_delta &&
                               (static_cast<int>(depth) < context.max_depth || !rules.mis_last_vertex_one);
      if (surface.direct)
        radiance += throughput * *surface.direct *
                    (weigh_light ? mis_weight(surface.light_pdf, surface.light_bsdf_pdf, rules.mis_exponent) : 1.0);
      else if (!rules.no_light_sample_is_zero)
        return std::nullopt;
    }
    if (static_cast<int>(depth) >= context.max_depth || !surface.went_on) return radiance;
    const glm::dvec3 f = surface.diffuse_bounce && !rules.f_over_pi ? surface.albedo : surface.f;
    const glm::dvec3 weight = f * ((rules.cosine ? surface.cosine : 1.0) / surface.pdf);
    const double p = rules.own == OwnRoulette::None
                         ? double(context.continue_probability(static_cast<int>(depth), glm::vec3(throughput)))
                         : own_p(static_cast<int>(depth), weight);
    throughput *= weight;
    if (p < 1.0 && rules.divide_by_p) throughput /= p;
    after_specular = surface.specular_bounce;
  }
  return radiance;
}

struct PathMistake {
  const char* english;
  const char* chinese;
  std::function<void(PathRules&)> make;
  enum class Of { Both, Path, Mis } of = Of::Both;  // the path tracers whose mistake it can be
};
const std::vector<PathMistake>& path_mistakes() {
  using Of = PathMistake::Of;
  static const std::vector<PathMistake> mistakes = {
      {"Russian roulette not divided by p (a path that goes on must be divided "
       "by p)",
       "俄罗斯轮盘赌没有除以 p（继续的路径必须除以 p）", [](PathRules& r) { r.divide_by_p = false; }},
      {"the cosine missing from the bounce weight f |cos| / pdf", "弹射权重 f |cos| / pdf 中缺少余弦",
       [](PathRules& r) { r.cosine = false; }},
      {"a diffuse bounce weighed with f = the albedo (1 / pi missing)", "漫反射弹射的权重用了 f = 反照率（缺少 1 / pi）",
       [](PathRules& r) { r.f_over_pi = false; }},
      {"emission counted after a diffuse bounce too (estimate_direct_light "
       "counted it already)",
       "漫反射弹射之后也计算了自发光（estimate_direct_light 已经计算过它）",
       [](PathRules& r) { r.emission_after_diffuse = true; }, Of::Path},
      {"no emission counted after a mirror or glass bounce", "镜面或玻璃弹射之后没有计算自发光",
       [](PathRules& r) { r.emission_after_specular = false; }},
      {"the emission of a light the camera sees left out", "漏掉了相机直接看到的光源的自发光",
       [](PathRules& r) { r.camera_emission = false; }},
      {"black where the path leaves the scene, not the background", "路径离开场景时用了黑色，而不是背景",
       [](PathRules& r) { r.background = false; }},
      {"the surface at depth == max_depth left out", "漏掉了 depth == max_depth 处的表面",
       [](PathRules& r) { r.last_surface = false; }},
      {"no MIS weights at all (stage 09's rules: the light sample keeps weight 1, the emission a diffuse bounce "
       "finds is not counted)",
       "完全没有 MIS 权重（阶段 09 的规则：光源样本的权重保持为 1，漫反射弹射找到的自发光不计入）",
       [](PathRules& r) { r.mis = false; }, Of::Mis},
      {"the light sample not weighted (it keeps weight 1)", "光源样本没有加权（权重保持为 1）",
       [](PathRules& r) { r.mis_weigh_light = false; }, Of::Mis},
      {"the emission a diffuse bounce finds counted in full, without its weight",
       "漫反射弹射找到的自发光被完整计入，没有乘它的权重", [](PathRules& r) { r.mis_weigh_emission = false; }, Of::Mis},
      {"the balance heuristic pdf_f / (pdf_f + pdf_g), not the power heuristic",
       "用了平衡启发式 pdf_f / (pdf_f + pdf_g)，而不是幂启发式", [](PathRules& r) { r.mis_exponent = 1; }, Of::Mis},
      {"the light sample at the last vertex (depth == max_depth) weighted, though no BSDF sample follows it",
       "最后一个顶点（depth == max_depth）的光源样本也加了权重，但它之后没有 BSDF 样本",
       [](PathRules& r) { r.mis_last_vertex_one = false; }, Of::Mis},
  };
  return mistakes;
}

// Your value as a correct path's with a Russian roulette probability of its own (PathRules), in
// words, or "".
std::string fitted_own_roulette(const Words& words, const std::vector<SurfaceTerms>& surfaces,
                                const RenderContext& context, const PathRules& base, const glm::vec3& yours) {
  const auto fits = [&](const PathRules& rules) {
    const std::optional<glm::dvec3> value = path_value(surfaces, context, rules);
    return value && near(glm::dvec3(yours), *value, kValueTolerance);
  };
  for (const OwnRoulette own : {OwnRoulette::ByThroughputBefore, OwnRoulette::ByThroughputAfter})
    for (const int from_depth : {0, 1, 2})
      for (const double floor : {0.0, 0.05}) {
        PathRules rules = base;
        rules.own = own;
        rules.own_from_depth = from_depth;
        rules.own_floor = floor;
        if (fits(rules))
          return words("your path plays Russian roulette with a probability of its own, the largest channel of "
                       "the throughput ",
                       "你的路径用自己的概率做俄罗斯轮盘赌，即乘上弹射权重") +
                 (own == OwnRoulette::ByThroughputAfter ? words("after", "之后") : words("before", "之前")) +
                 words(" the bounce's weight (from depth ", "的吞吐量的最大通道（从深度 ") + std::to_string(from_depth) +
                 words(" on), not context.continue_probability's: the same mean, and right along this path",
                       " 开始），而不是 context.continue_probability 给出的 p：均值相同，沿这条路径也是对的");
      }
  // A fixed probability of the common ones (GAMES101 assignment 7 uses 0.8). Not any number: with
  // one bounce, some fixed probability gives every value that a wrong factor on the bounce gives.
  for (const float p : {0.5f, 0.6f, 0.7f, 0.75f, 0.8f, 0.85f, 0.9f, 0.95f, 0.99f}) {
    PathRules rules = base;
    rules.own = OwnRoulette::Fixed;
    rules.own_fixed_p = p;
    if (fits(rules))
      return words("your path plays Russian roulette with a fixed probability of its own, ",
                   "你的路径用自己的固定概率 ") +
             text(p) +
             words(", not context.continue_probability's: the same mean, and right along this path",
                   " 做俄罗斯轮盘赌，而不是 context.continue_probability 给出的 p：均值相同，沿这条路径也是对的");
  }
  return "";
}

// The mistakes (one, or two together) whose rules give `yours` where the contract's do not.
std::string fitted_mistakes(const Words& words, const std::vector<SurfaceTerms>& surfaces,
                            const RenderContext& context, const PathRules& base, const glm::vec3& yours,
                            const glm::dvec3& contract) {
  std::vector<PathMistake> mistakes;
  for (const PathMistake& mistake : path_mistakes())
    if (mistake.of == PathMistake::Of::Both || (mistake.of == PathMistake::Of::Mis) == base.mis)
      mistakes.push_back(mistake);
  const auto fits = [&](const PathRules& rules) {
    const std::optional<glm::dvec3> value = path_value(surfaces, context, rules);
    return value && !near(*value, contract, kValueTolerance) && near(glm::dvec3(yours), *value, kValueTolerance);
  };
  for (const PathMistake& mistake : mistakes) {
    PathRules rules = base;
    mistake.make(rules);
    if (fits(rules))
      return words("your value is the contract's with ", "你的值正是契约的规则犯了这个错误时给出的值：") +
             words(mistake.english, mistake.chinese);
  }
  for (std::size_t a = 0; a < mistakes.size(); ++a)
    for (std::size_t b = a + 1; b < mistakes.size(); ++b) {
      PathRules rules = base;
      mistakes[a].make(rules);
      mistakes[b].make(rules);
      if (fits(rules))
        return words("your value is the contract's with two mistakes "
                     "together: ",
                     "你的值正是契约的规则同时犯了两个错误时给出的值：") +
               words(mistakes[a].english, mistakes[a].chinese) + words("; and ", "；以及") +
               words(mistakes[b].english, mistakes[b].chinese);
    }
  return "";
}

}  // namespace

void trace_monte_carlo(const Scene& scene, const Ray& camera_ray, Sampler& sampler, const TracingFunctions& contract,
                       PixelTrace& trace) {
  const TraceSettings& settings = trace.settings;
  // The path tracers: stage 09's path_radiance, or stage 09b's path_radiance_mis, whose rules add
  // MIS weights to the same path.
  const bool mis = settings.integrator == IntegratorKind::PathMis;
  const bool path_tracer = settings.integrator == IntegratorKind::Path || mis;
  const std::string path_stage = mis ? "09b_mis" : "09_path", path_function = mis ? "path_radiance_mis" : "path_radiance";
  // The steps' words in the trace's language.
  const Words words{settings.chinese};
  // Yours: the geometry your stages 02-05 trace (as raylab render's); the contract's: every
  // primitive tested with the kit's exact tests. Every ray is traced (no skip of rays outside the
  // scene's bounds), so that each one is seen.
  const SceneGeometry your_geometry(scene, Acceleration::Bvh, TriangleTest::MollerTrumbore, settings.yours);
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
    radiance = outcome_of(words, [&] {
      return mis           ? path_radiance_mis(yours, camera_ray, sampler)
             : path_tracer ? path_radiance(yours, camera_ray, sampler)
                           : direct_light_li(yours, camera_ray, sampler, stats);
    });
  }
  const std::vector<RecordedCall>& calls = recorder.calls;
  const std::vector<PathVertex> path = path_of(calls, camera_ray);
  // The rays to draw: the path's, and every other ray as a shadow ray (the camera ray's segment
  // kept when your code traced no path).
  if (!path.empty()) {
    trace.segments.clear();
    const float far = miss_length(scene);
    const auto end_of = [&](const Ray& ray, float t) {
      return ray.origin + ray.direction * std::min(t, std::isfinite(ray.t_max) ? std::min(ray.t_max, far) : far);
    };
    std::vector<bool> on_path(calls.size(), false);
    for (const PathVertex& vertex : path) on_path[vertex.first - 1] = true;
    for (std::size_t i = 0; i < calls.size(); ++i) {
      const RecordedCall& call = calls[i];
      if (call.kind == Kind::Occluded) {
        trace.segments.push_back({call.ray.origin, end_of(call.ray, far), TraceSegment::Kind::Shadow});
      } else if (call.kind == Kind::Intersect) {
        const float t = call.hit ? call.hit->t_hit : far;
        trace.segments.push_back({call.ray.origin, end_of(call.ray, t),
                                  !on_path[i]               ? TraceSegment::Kind::Shadow
                                  : i + 1 == path.front().first ? TraceSegment::Kind::Camera
                                                           : TraceSegment::Kind::Bounce});
      }
    }
  }

  // Stage 09b: your power_heuristic on the contract's two densities of a direction, beside the
  // contract's weight.
  const auto weight_step = [&](const std::string& at, const std::string& what, double pdf_f, double pdf_g) {
    const float f = static_cast<float>(pdf_f), g = static_cast<float>(pdf_g);
    const Outcome<float> got = outcome_of(words, [&] { return power_heuristic(1, f, 1, g); });
    const double expected = mis_weight(f, g);
    TraceStep step{"09b_mis", "power_heuristic",
                   at + words(": ", "：") + what + words(", ", "，") + "power_heuristic(1, " + text(f) + ", 1, " + text(g) + ")",
                   got.value ? text(*got.value) : got.failure,
                   text(expected) + "  (pdf_f^2 / (pdf_f^2 + pdf_g^2))"};
    step.agrees = got.value && near(double(*got.value), expected);
    steps.push_back(marked_at_stub(words, step, got));
  };

  std::vector<SurfaceTerms> surfaces;
  glm::dvec3 throughput(1.0);        // the contract's, for the roulette's p
  std::string not_followed;          // why your path's value cannot be checked
  std::vector<int> unsampled_light;  // the diffuse surfaces where your path sampled no light
  std::string light_not_followed;    // why a light sample of your path could not be followed
  std::string stopped_short;         // your path ended where the contract's goes on
  // The surfaces up to one past max_depth (a path that goes on further is marked at its value).
  const std::size_t traced_surfaces = std::min(path.size(), static_cast<std::size_t>(std::max(settings.max_depth, 0)) + 2);
  for (std::size_t depth = 0; depth < traced_surfaces; ++depth) {
    const PathVertex& vertex = path[depth];
    const int d = static_cast<int>(depth);
    const std::string at = words("surface ", "表面 ") + std::to_string(depth);
    SurfaceTerms surface;
    // The closest hit of a bounce ray (the camera ray's is above).
    if (depth > 0) {
      const std::optional<SurfaceHit> expected = contract_geometry.intersect(vertex.ray);
      TraceStep step{"", "",
                     at + words(": the closest hit along the bounce ray (", "：沿弹射光线的最近交点（") +
                         ray_text(words, vertex.ray) + words(")", "）"),
                     hit_text(words, scene, vertex.hit), hit_text(words, scene, expected)};
      step.agrees = same_closest_hit(vertex.hit, expected);
      if (!step.agrees) step.note = another_hit_note(words);
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
    // MIS: the emission a diffuse bounce found, weighted against the light strategy's density of
    // the same direction from the surface before.
    if (mis && depth > 0 && !surfaces.back().specular_bounce && surfaces.back().pdf > 0.0) {
      surface.emission_bsdf_pdf = surfaces.back().pdf;
      surface.emission_light_pdf =
          contracts.lights.pdf_li(path[depth - 1].hit->point, glm::normalize(vertex.ray.direction));
      if (surface.emission != glm::dvec3(0.0))
        weight_step(at, words("the weight of the emission your bounce found (BSDF strategy against the light's)",
                              "你的弹射找到的自发光的权重（BSDF 策略对光源策略）"),
                    surface.emission_bsdf_pdf, surface.emission_light_pdf);
    }

    if (bsdf.kind == BsdfKind::Lambertian) {
      const Outcome<glm::vec3> f = outcome_of(words, [&] { return lambertian_f(bsdf.albedo); });
      const glm::dvec3 expected = glm::dvec3(bsdf.albedo) / kPiInDouble;
      TraceStep step{"08_direct_light", "lambertian_f",
                     at + words(" (", "（") + material_text(words, scene, hit) + words(", diffuse): ", "，漫反射）：") +
                         "lambertian_f(albedo " + text(bsdf.albedo) + ")",
                     f.value ? text(*f.value) : f.failure,
                     text(expected) + words("  (albedo / pi)", "  （albedo / pi）")};
      step.agrees = f.value && near(glm::dvec3(*f.value), expected);
      steps.push_back(marked_at_stub(words, step, f));
    }

    if (bsdf.is_black()) {
      surface.direct = glm::dvec3(0.0);  // reflects nothing: no light to sample
    } else if (!surface.specular) {
      // Your estimate_direct_light called once more on its own, on a sampler of its own, with its
      // calls recorded: the contract's estimate for the light, the point and the shadow ray that
      // call drew. (With --integrator direct, the sample's own estimate is checked below too.)
      TraceRecorder probe_recorder;
      Outcome<glm::vec3> estimate;
      {
        RecordingCalls recording(probe_recorder);
        Sampler probe(settings.samples_per_pixel, settings.seed + 1);
        probe.start_pixel_sample(trace.x, trace.y, settings.sample);
        estimate = outcome_of(words, [&] { return estimate_direct_light(yours, hit, bsdf, wo, probe); });
      }
      const LightCalls probe_calls = light_calls(probe_recorder.calls, 0, probe_recorder.calls.size());
      if (probe_calls.sample && probe_calls.sample->light_sample && probe_calls.sample->light.kind != LightKind::Point) {
        const Light& light = probe_calls.sample->light;
        const LightDensity density = contract_light_density(light, *probe_calls.sample->light_sample);
        // Stage 07's density of the light's points (sample_li's, through sample_triangle or
        // sample_sphere), then stage 08's conversion.
        if (light.kind == LightKind::Triangle) {
          const Outcome<float> pdf =
              outcome_of(words, [&] { return uniform_triangle_pdf(light.p0, light.p1, light.p2); });
          TraceStep step{"07_sampling", "uniform_triangle_pdf",
                         at + words(": the light's points, ", "：光源上的点的密度，") + "uniform_triangle_pdf(" +
                             text(light.p0) + ", " + text(light.p1) + ", " + text(light.p2) + ")",
                         pdf.value ? text(*pdf.value) : pdf.failure,
                         text(density.pdf_area) + words("  (1 / area)", "  （1 / 面积）")};
          step.agrees = pdf.value && near(*pdf.value, density.pdf_area);
          steps.push_back(marked_at_stub(words, step, pdf));
        } else {
          const glm::vec3 outward =
              glm::normalize(probe_calls.sample->light_sample->point - light.sphere.center);
          const Outcome<float> pdf = outcome_of(words, [&] { return uniform_sphere_pdf(outward); });
          TraceStep step{"07_sampling", "uniform_sphere_pdf",
                         at + words(": the light's points, ", "：光源上的点的密度，") + "uniform_sphere_pdf(" +
                             text(outward) + ")",
                         pdf.value ? text(*pdf.value) : pdf.failure,
                         text(1.0 / (4.0 * kPiInDouble)) + words("  (1 / (4 pi))", "  （1 / (4 pi)）")};
          step.agrees = pdf.value && near(*pdf.value, 1.0 / (4.0 * kPiInDouble));
          steps.push_back(marked_at_stub(words, step, pdf));
        }
        const Outcome<float> pdf = outcome_of(words, [&] {
          return area_pdf_to_solid_angle(float(density.pdf_area), float(density.distance), float(density.cos_at_light));
        });
        TraceStep step{"08_direct_light", "area_pdf_to_solid_angle",
                       at + words(": ", "：") + "area_pdf_to_solid_angle(pdf_area " + text(density.pdf_area) +
                           ", distance " + text(density.distance) + ", cos_at_light " +
                           text(density.cos_at_light) + ")",
                       pdf.value ? text(*pdf.value) : pdf.failure,
                       text(density.per_steradian) + words("  (pdf_area * distance^2 / cos_at_light)",
                                                           "  （pdf_area * distance^2 / cos_at_light）")};
        step.agrees = pdf.value && near(*pdf.value, density.per_steradian);
        steps.push_back(marked_at_stub(words, step, pdf));
      }
      const ContractDirect expected = contract_direct(words, contracts, hit, bsdf, wo, probe_calls);
      // A shadow ray whose answer differs is a step of its own; the estimate below takes your
      // answer, so that only the estimator's arithmetic is held to the contract there.
      if (auto shadow =
              shadow_ray_step(words, at, probe_calls, expected, hit, "08_direct_light", "estimate_direct_light"))
        steps.push_back(*shadow);
      TraceStep step{"08_direct_light", "estimate_direct_light",
                     at + words(": ", "：") + "estimate_direct_light(context, hit, bsdf, wo, sampler)" +
                         words(", called once more on its own", "，单独再调用一次"),
                     estimate.value ? text(*estimate.value) : estimate.failure,
                     expected.value ? text(*expected.value) : words("not checked: ", "没有检查：") + expected.why,
                     expected.what};
      step.agrees = estimate.value && expected.wrong_light.empty() &&
                    (!expected.value || near(glm::dvec3(*estimate.value), *expected.value, kValueTolerance));
      steps.push_back(marked_at_stub(words, step, estimate));

      // The light sample of your path itself: its value is not seen, only its calls.
      const LightCalls path_calls = light_calls(calls, vertex.first, vertex.end);
      const ContractDirect path_direct = contract_direct(words, contracts, hit, bsdf, wo, path_calls);
      surface.direct = path_direct.value;
      surface.light_pdf = path_direct.light_pdf;
      surface.light_delta = path_direct.delta;
      surface.light_bsdf_pdf = contract_bsdf_pdf(bsdf, hit.geometric_normal, wo, path_direct.direction);
      if (mis && !path_direct.delta && path_direct.light_pdf > 0.0 && d < settings.max_depth &&
          path_direct.value && *path_direct.value != glm::dvec3(0.0))
        weight_step(at, words("the weight of your path's light sample (light strategy against the BSDF's)",
                              "你的路径的光源样本的权重（光源策略对 BSDF 策略）"),
                    surface.light_pdf, surface.light_bsdf_pdf);
      if (auto shadow = shadow_ray_step(words, at + words(" (your path's own light sample)", "（你的路径自己的光源样本）"),
                                        path_calls, path_direct, hit, path_tracer ? path_stage : "08_direct_light",
                                        path_tracer ? path_function : "estimate_direct_light"))
        steps.push_back(*shadow);
      if (!path_calls.sample && !contracts.lights.empty())
        unsampled_light.push_back(d);
      else if (!path_direct.value && light_not_followed.empty())
        light_not_followed = words(path_direct.why + " at " + at, "在" + at + "，" + path_direct.why);
    } else {
      surface.direct = glm::dvec3(0.0);
    }

    // The bounce.
    surface.went_on = depth + 1 < path.size();
    const float p = contracts.continue_probability(d, glm::vec3(throughput));
    std::string roulette;
    if (path_tracer && d < settings.max_depth && (p < 1.0f || !surface.went_on))
      roulette = words("Russian roulette: ", "俄罗斯轮盘赌：") + "p = context.continue_probability(" +
                 std::to_string(depth) + ", throughput " + text(glm::vec3(throughput)) + ") = " + text(p) +
                 (surface.went_on ? (p < 1.0f ? words("; your path went on (the contract divides by p)",
                                                      "；你的路径继续了（契约会除以 p）")
                                              : words("; your path went on", "；你的路径继续了"))
                                  : words("; your path ended here", "；你的路径在这里结束"));
    if (vertex.bounce) {
      const RecordedCall& bounce = *vertex.bounce;
      const std::string call = at + words(": ", "：") + "bsdf_sample_f(" + bsdf_name(words, bsdf) + ", u_lobe " +
                               text(bounce.u_lobe) + ", u " + text(bounce.u) + ")";
      // Its arguments: this surface's BSDF, its normal (either side) and minus the ray's direction.
      std::string wrong_arguments;
      if (std::fabs(glm::dot(bounce.normal, hit.geometric_normal)) < 1.0f - 1e-4f)
        wrong_arguments = words("the normal ", "法线 ") + text(bounce.normal) +
                          words(", not the hit's geometric_normal ", "，而不是交点的 geometric_normal ") +
                          text(hit.geometric_normal);
      else if (!same_direction(bounce.wo, wo))
        wrong_arguments = "wo " + text(bounce.wo) + words(", not minus the ray's direction ", "，而不是光线方向的相反方向 ") +
                          text(wo);
      else if (bounce.bsdf.kind != bsdf.kind || bounce.bsdf.albedo != bsdf.albedo)
        wrong_arguments = words("another BSDF than bsdf_of(material, diffuse_color_at(material, hit))",
                                "另一个 BSDF，而不是 bsdf_of(material, diffuse_color_at(material, hit))");
      if (!wrong_arguments.empty()) {
        steps.push_back(TraceStep{path_stage, path_function, call, words("called with ", "调用时用了") + wrong_arguments,
                                  words("this surface's BSDF, normal and wo", "这个表面的 BSDF、法线和 wo"), "", false});
        not_followed = words("your bounce at " + at + " was sampled with other arguments", "你在" + at + " 的弹射是用别的参数采样的");
      } else if (!bounce.bsdf_sample) {
        const std::string no_sample = words("no sample: the path ends", "没有样本：路径结束");
        steps.push_back(TraceStep{"", "", call, no_sample, no_sample, roulette, true});
      } else {
        const BsdfSample& sample = *bounce.bsdf_sample;
        const glm::vec3 facing = glm::dot(hit.geometric_normal, wo) > 0.0f ? hit.geometric_normal : -hit.geometric_normal;
        const double cosine = std::fabs(glm::dot(glm::dvec3(hit.geometric_normal), glm::dvec3(sample.wi)));
        surface.cosine = cosine;
        surface.specular_bounce = sample.is_specular;
        const std::string got =
            "wi " + text(sample.wi) + ", f " + text(sample.f) + ", pdf " + text(sample.pdf) + ", |cos| " + text(cosine);
        if (bsdf.kind == BsdfKind::Lambertian) {
          // Stage 07's warp and density: any cosine-weighted warp is right (the grader tests the
          // distribution); its direction must be unit and above the surface, its pdf cos / pi.
          const double length = glm::length(glm::dvec3(sample.wi));
          const double cos_facing = glm::dot(glm::dvec3(facing), glm::dvec3(sample.wi)) / length;
          const bool direction_ok = std::fabs(length - 1.0) < 1e-3 && cos_facing > 0.0;
          TraceStep step{"07_sampling", direction_ok ? "cosine_hemisphere_pdf" : "sample_cosine_hemisphere",
                         call + words(": your ", "：你的 ") + "sample_cosine_hemisphere(u)" + words(" and ", " 和 ") +
                             "cosine_hemisphere_pdf",
                         got,
                         direction_ok ? "pdf " + text(cos_facing / kPiInDouble) +
                                            words("  (cos / pi for this direction)", "  （这个方向的 cos / pi）")
                                      : words("a unit direction above the surface (|wi| = 1, z > 0 locally)",
                                              "表面上方的单位方向（|wi| = 1，局部坐标中 z > 0）"),
                         roulette};
          step.agrees = direction_ok && near(sample.pdf, cos_facing / kPiInDouble);
          steps.push_back(step);
          surface.diffuse_bounce = true;
          surface.albedo = glm::dvec3(bsdf.albedo);
          surface.f = glm::dvec3(bsdf.albedo) / kPiInDouble;
          surface.pdf = cosine / kPiInDouble;
        } else {
          steps.push_back(TraceStep{"", "", call, got,
                                    words("the framework's (", "由框架计算（") + bsdf_name(words, bsdf) + words(")", "）"),
                                    roulette, true});
          surface.f = glm::dvec3(sample.f);
          surface.pdf = sample.pdf;
        }
        if (p < 1.0f) throughput /= double(p);
        throughput *= surface.f * (surface.cosine / surface.pdf);
        if (path_tracer && !surface.went_on && !vertex.own_next_ray && p >= 1.0f && d == settings.max_depth - 1 &&
            throughput != glm::dvec3(0.0))
          stopped_short =
              words("your path stopped after sampling the bounce at " + at + ", the surface before depth " +
                        "max_depth = " + std::to_string(settings.max_depth) +
                        ", which counts too (a loop "
                        "depth < max_depth?)",
                    "你的路径在" + at + " 采样弹射之后就停止了，这是深度 max_depth = " + std::to_string(settings.max_depth) +
                        " 之前的表面，而深度 max_depth 处的表面也要算（循环写成了 depth < max_depth？）");
      }
    } else if (path_tracer && d < settings.max_depth && !bsdf.is_black() && !vertex.own_next_ray && p < 1.0f) {
      steps.push_back(TraceStep{"", "",
                                at + words(": Russian roulette, ", "：俄罗斯轮盘赌，") +
                                    "p = context.continue_probability(" + std::to_string(depth) + ", throughput " +
                                    text(glm::vec3(throughput)) + ")",
                                words("the path ended here", "路径在这里结束"),
                                "p = " + text(p) + words(": the path goes on with probability p", "：路径以概率 p 继续"),
                                "", true});
    }
    if (path_tracer && vertex.own_next_ray && not_followed.empty())
      not_followed = words("your path samples its bounce at " + at + " without bsdf_sample_f, which the trace follows",
                           "你的路径在" + at + " 采样弹射时没有用跟踪所依据的 bsdf_sample_f");
    surfaces.push_back(surface);
  }

  // The sample's value: path_radiance's against the contract's rules on the same surfaces, light
  // samples and bounces; or, for the direct-light integrator (the framework's, around your
  // estimate_direct_light), the light of this very sample's light sample.
  TraceStep step{path_tracer ? path_stage : "08_direct_light", path_tracer ? path_function : "estimate_direct_light",
                 path_tracer
                     ? path_function + "(context, camera_ray, sampler)" + words(": this sample's value", "：这个样本的值")
                     : words("this sample's value: the framework's direct_light_li with your estimate_direct_light",
                             "这个样本的值：框架的 direct_light_li（调用你的 estimate_direct_light）"),
                 radiance.value ? text(*radiance.value) : radiance.failure, ""};
  if (!radiance.value) {
    step.expected = words("a radiance, three finite numbers", "一个辐亮度，即三个有限的数");
    step.agrees = false;
    steps.push_back(marked_at_stub(words, step, radiance));
    return;
  }
  const glm::dvec3 value(*radiance.value);
  const int last_depth = static_cast<int>(path.size()) - 1;
  PathRules rules;  // the contract's
  rules.mis = mis;
  const std::optional<glm::dvec3> expected =
      not_followed.empty() ? path_value(surfaces, contracts, rules) : std::nullopt;
  const std::string not_checked = words("not checked: ", "没有检查：");
  if (!not_followed.empty()) {
    step.expected = not_checked + not_followed;  // (other arguments are marked at the bounce)
  } else if (path_tracer && last_depth > settings.max_depth) {
    step.expected = words("a path that ends at the surface at depth max_depth", "在深度 max_depth 处的表面结束的路径");
    step.agrees = false;
    step.note = words("your path went on after the surface at depth max_depth = ",
                      "你的路径在深度 max_depth = ") +
                std::to_string(settings.max_depth) + words("", " 处的表面之后还在继续");
  } else if (!expected && (!path_tracer || !light_not_followed.empty() || unsampled_light.empty())) {
    step.expected = not_checked + (light_not_followed.empty()
                                       ? words("a light sample could not be followed", "有一个光源样本无法跟踪")
                                       : light_not_followed);
  } else if (!expected) {
    // A diffuse surface whose light your path did not sample.
    const std::string where =
        words("surface ", "表面 ") + std::to_string(unsampled_light.empty() ? 0 : unsampled_light.front());
    PathRules none = rules;
    none.no_light_sample_is_zero = true;
    PathRules emission_only = none;  // (with MIS: the emission a diffuse bounce finds, unweighted)
    if (mis)
      emission_only.mis_weigh_emission = false;
    else
      emission_only.emission_after_diffuse = true;
    // What each diffuse surface must add: "estimate_direct_light", or with MIS its weighted light sample.
    const std::string light_sample = mis ? words("a weighted light sample", "一个加权的光源样本")
                                         : words("estimate_direct_light", " estimate_direct_light ");
    const std::string handout = mis ? words("docs/09b_mis.md, section 4", "docs/zh/09b_mis.md，第 4 节")
                                    : words("docs/09_path.md, section 2", "docs/zh/09_path.md，第 2 节");
    const std::optional<glm::dvec3> without = path_value(surfaces, contracts, none);
    const std::optional<glm::dvec3> by_emission = path_value(surfaces, contracts, emission_only);
    if (by_emission && without && near(value, *by_emission, kValueTolerance) &&
        !near(value, *without, kValueTolerance)) {
      step.expected = text(*by_emission) + words("  (your path's emission, without light sampling)",
                                                 "  （你的路径的自发光，没有光源采样）");
      step.note = words("your path samples no light and counts the emission its bounces reach instead: the same mean, "
                        "with more noise; the contract asks for " + light_sample + " at every diffuse surface",
                        "你的路径不采样光源，而是计入弹射所到达的自发光：均值相同，噪声更多；契约要求在每个漫反射表面"
                        "使用" + light_sample);
    } else if (without && near(value, *without, kValueTolerance)) {
      step.expected = words("the direct light at " + where, where + " 处的直接光照");
      step.agrees = false;
      step.note = words("your path adds no direct light at " + where + ", a diffuse surface: add " + light_sample +
                            " there (" + handout + ")",
                        "你的路径没有在" + where + "（一个漫反射表面）加上直接光照：要在那里加上" + light_sample + "（" +
                            handout + "）");
    } else {
      step.expected = words("not checked: your path sampled no light at " + where + " with sample_li",
                            "没有检查：你的路径在" + where + " 没有用 sample_li 采样光源");
    }
  } else {
    step.expected =
        text(*expected) + words("  (the contract's rules on your path's surfaces, light samples and bounces)",
                                "  （契约的规则作用于你的路径的这些表面、光源样本和弹射）");
    step.agrees = near(value, *expected, kValueTolerance);
    if (!step.agrees && path_tracer) {
      // A mistake that gives your value comes first; a roulette of your own that gives it too is
      // named beside it (one sample cannot tell them apart), and alone it is no disagreement.
      const std::string mistake = fitted_mistakes(words, surfaces, contracts, rules, *radiance.value, *expected);
      const std::string own_roulette = fitted_own_roulette(words, surfaces, contracts, rules, *radiance.value);
      if (!mistake.empty()) {
        step.note = mistake;
        if (!own_roulette.empty()) step.note += words(" (or else ", "（也可能是：") + own_roulette + words(")", "）");
      } else if (!own_roulette.empty()) {
        step.agrees = true;
        step.expected = text(*expected) + words("  (with context.continue_probability's p)",
                                                "  （用 context.continue_probability 的 p）");
        step.note = own_roulette;
      }
    }
    if (!step.agrees && !path_tracer)
      step.note =
          words("the light sample your estimate_direct_light drew in this sample gives the contract's value above",
                "你的 estimate_direct_light 在这个样本中抽取的光源样本，按契约的规则给出的是上面的值");
    if (step.agrees && !stopped_short.empty()) {
      step.agrees = false;
      step.note = stopped_short;
    }
  }
  if (recorder.overflowed)
    step.note += (step.note.empty() ? "" : words("; ", "；")) +
                 words("only the first calls were followed", "只跟踪了前面的一部分调用");
  steps.push_back(step);
}

}  // namespace raylab
