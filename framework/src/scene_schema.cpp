// The scene schema (docs/scene-format.md): what a scene file may hold, read with JsonReader
// (json_reader.h); OBJ meshes come from obj_loader.cpp. Every error names the file, the
// JSON path and what was expected.
#include "raylab/scene_loader.h"

#include "input_file.h"
#include "json_reader.h"

#include <cmath>
#include <filesystem>
#include <map>
#include <sstream>

namespace raylab {
namespace {

Camera read_camera(const JsonReader& r, const json& node, const std::string& path) {
  r.expect_object(node, path);
  r.check_keys(node, path, {"position", "look_at", "up", "fov_y_degrees", "width", "height"});
  Camera camera;
  if (node.contains("position")) camera.position = r.vector<3>(node["position"], path + "/position");
  if (node.contains("look_at")) camera.look_at = r.vector<3>(node["look_at"], path + "/look_at");
  if (node.contains("up")) camera.up = r.vector<3>(node["up"], path + "/up");
  if (node.contains("fov_y_degrees"))
    camera.fov_y_degrees = static_cast<float>(r.number(node["fov_y_degrees"], path + "/fov_y_degrees", 1e-3, 179.0));
  if (node.contains("width")) camera.width = r.integer(node["width"], path + "/width", 1, kMaxImageSide);
  if (node.contains("height")) camera.height = r.integer(node["height"], path + "/height", 1, kMaxImageSide);
  try {
    validate_camera(camera);
  } catch (const std::invalid_argument& e) {
    r.fail(path, e.what());
  }
  return camera;
}

Material read_material(const JsonReader& r, const json& node, const std::string& path,
                       const std::string& name) {
  r.expect_object(node, path);
  Material m;
  m.name = name;
  const std::string type = r.string(r.require(node, path, "type"), path + "/type");
  if (type == "diffuse_glossy") m.kind = MaterialKind::DiffuseGlossy;
  else if (type == "reflective") m.kind = MaterialKind::Reflective;
  else if (type == "reflective_refractive") m.kind = MaterialKind::ReflectiveRefractive;
  else if (type == "diffuse") m.kind = MaterialKind::Diffuse;
  else if (type == "mirror") m.kind = MaterialKind::Mirror;
  else if (type == "microfacet") m.kind = MaterialKind::Microfacet;
  else r.fail(path + "/type", "unknown material type '" + type +
                                   "' (expected diffuse_glossy, reflective, reflective_refractive, diffuse, mirror or "
                                   "microfacet)");
  switch (m.kind) {
    case MaterialKind::Diffuse:
      r.check_keys(node, path, {"type", "diffuse_color", "checkerboard", "emission"});
      m.kd = 1.0f;  // under Whitted shading: all diffuse, no highlight
      m.ks = 0.0f;
      break;
    case MaterialKind::Mirror:
      r.check_keys(node, path, {"type", "reflectance", "emission"});
      break;
    case MaterialKind::Microfacet:
      r.check_keys(node, path, {"type", "reflectance", "alpha", "emission"});
      break;
    default:
      r.check_keys(node, path, {"type", "diffuse_color", "checkerboard", "kd", "ks", "specular_exponent",
                                "index_of_refraction", "emission"});
      break;
  }
  if (node.contains("emission")) m.emission = r.color(node["emission"], path + "/emission", "emitted radiance");
  if (node.contains("reflectance")) {
    m.reflectance = r.color(node["reflectance"], path + "/reflectance", "reflectance");
    if (glm::any(glm::greaterThan(m.reflectance, glm::vec3(1.0f))))
      r.fail(path + "/reflectance", "a surface reflects at most all the light: components must be <= 1");
  }
  if (node.contains("alpha"))
    m.alpha = static_cast<float>(r.number(node["alpha"], path + "/alpha", kMinMicrofacetAlpha, 1.0));
  if (node.contains("diffuse_color")) m.diffuse_color = r.color(node["diffuse_color"], path + "/diffuse_color");
  if (m.kind == MaterialKind::Diffuse && glm::any(glm::greaterThan(m.diffuse_color, glm::vec3(1.0f))))
    r.fail(path + "/diffuse_color", "a diffuse surface reflects at most all the light: its albedo components must be <= 1");
  if (node.contains("kd")) m.kd = static_cast<float>(r.number(node["kd"], path + "/kd", 0, 1e3));
  if (node.contains("ks")) m.ks = static_cast<float>(r.number(node["ks"], path + "/ks", 0, 1e3));
  if (node.contains("specular_exponent"))
    m.specular_exponent = static_cast<float>(r.number(node["specular_exponent"], path + "/specular_exponent", 0, 1e6));
  if (node.contains("index_of_refraction"))
    m.index_of_refraction = static_cast<float>(r.number(node["index_of_refraction"], path + "/index_of_refraction", 1e-3, 100));
  if (node.contains("checkerboard")) {
    const std::string cpath = path + "/checkerboard";
    const json& c = node["checkerboard"];
    r.expect_object(c, cpath);
    r.check_keys(c, cpath, {"scale", "color_a", "color_b"});
    Checkerboard board;
    if (c.contains("scale")) board.scale = static_cast<float>(r.number(c["scale"], cpath + "/scale", 1e-6, 1e6));
    if (c.contains("color_a")) board.color_a = r.color(c["color_a"], cpath + "/color_a");
    if (c.contains("color_b")) board.color_b = r.color(c["color_b"], cpath + "/color_b");
    m.checkerboard = board;
  }
  return m;
}

// A mesh written inline: positions, optional texcoords (one per position), triangles.
TriangleMesh read_inline_mesh(const JsonReader& r, const json& node, const std::string& path) {
  TriangleMesh mesh;
  const json& positions = r.require(node, path, "positions");
  if (!positions.is_array() || positions.empty())
    r.fail(path + "/positions", "expected a non-empty array of [x, y, z]");
  for (std::size_t i = 0; i < positions.size(); ++i)
    mesh.positions.push_back(r.vector<3>(positions[i], path + "/positions/" + std::to_string(i)));
  if (node.contains("texcoords")) {
    const json& texcoords = node["texcoords"];
    if (!texcoords.is_array() || texcoords.size() != positions.size())
      r.fail(path + "/texcoords", "expected one [s, t] per position (" + std::to_string(positions.size()) + ")");
    for (std::size_t i = 0; i < texcoords.size(); ++i)
      mesh.texcoords.push_back(r.vector<2>(texcoords[i], path + "/texcoords/" + std::to_string(i)));
  }
  const json& triangles = r.require(node, path, "triangles");
  if (!triangles.is_array() || triangles.empty())
    r.fail(path + "/triangles", "expected a non-empty array of [i0, i1, i2]");
  const long long last = static_cast<long long>(positions.size()) - 1;
  for (std::size_t i = 0; i < triangles.size(); ++i) {
    const std::string tpath = path + "/triangles/" + std::to_string(i);
    if (!triangles[i].is_array() || triangles[i].size() != 3)
      r.fail(tpath, "expected three vertex indices, got " + JsonReader::describe(triangles[i]));
    for (int k = 0; k < 3; ++k)
      mesh.indices.push_back(static_cast<std::uint32_t>(
          r.integer(triangles[i][k], tpath + "/" + std::to_string(k), 0, last)));
  }
  return mesh;
}

// Scales then translates an OBJ mesh; a vertex pushed beyond the float range is an error at
// `path` (the object), naming the vertex.
void transform_mesh(const JsonReader& r, const std::string& path, TriangleMesh& mesh, float scale,
                    const glm::vec3& translate) {
  for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
    glm::vec3& p = mesh.positions[v];
    const glm::vec3 before = p;
    p = p * scale + translate;
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) {
      std::ostringstream what;
      what << "scale " << scale << " and translate (" << translate.x << ", " << translate.y << ", "
           << translate.z << ") move vertex (" << before.x << ", " << before.y << ", " << before.z
           << ") of " << mesh.name << " beyond the float range (about 3.4e38)";
      r.fail(path, what.str());
    }
  }
}

Scene read_scene(const JsonReader& r, const json& root, const std::string& base_directory) {
  r.expect_object(root, "");
  r.check_keys(root, "", {"camera", "background", "max_depth", "integrator", "materials", "objects", "lights"});
  Scene scene;
  scene.source = r.source();
  scene.camera = read_camera(r, r.require(root, "", "camera"), "/camera");
  if (root.contains("background")) scene.background = r.color(root["background"], "/background");
  if (root.contains("max_depth")) scene.max_depth = r.integer(root["max_depth"], "/max_depth", 0, 64);
  if (root.contains("integrator")) {
    scene.integrator = r.string(root["integrator"], "/integrator");
    if (scene.integrator != "whitted" && scene.integrator != "direct" && scene.integrator != "path" &&
        scene.integrator != "mis")
      r.fail("/integrator", "unknown integrator '" + scene.integrator + "' (expected whitted, direct, path or mis)");
  }

  std::map<std::string, std::uint32_t> material_index;
  if (root.contains("materials")) {
    const json& materials = root["materials"];
    r.expect_object(materials, "/materials");
    for (const auto& item : materials.items()) {
      material_index[item.key()] = static_cast<std::uint32_t>(scene.materials.size());
      scene.materials.push_back(read_material(r, item.value(), "/materials/" + item.key(), item.key()));
    }
  }
  auto material_of = [&](const json& object, const std::string& path) {
    const std::string name = r.string(r.require(object, path, "material"), path + "/material");
    const auto it = material_index.find(name);
    if (it == material_index.end()) r.fail(path + "/material", "no material named '" + name + "' in /materials");
    return it->second;
  };

  const json& objects = r.require(root, "", "objects");
  if (!objects.is_array()) r.fail("/objects", "expected an array of objects, got " + JsonReader::describe(objects));
  for (std::size_t i = 0; i < objects.size(); ++i) {
    const std::string path = "/objects/" + std::to_string(i);
    const json& object = objects[i];
    r.expect_object(object, path);
    const std::string type = r.string(r.require(object, path, "type"), path + "/type");
    if (type == "sphere") {
      r.check_keys(object, path, {"type", "center", "radius", "material", "facing"});
      Sphere sphere;
      sphere.center = r.vector<3>(r.require(object, path, "center"), path + "/center");
      sphere.radius = static_cast<float>(r.number(r.require(object, path, "radius"), path + "/radius", 1e-30, 1e30));
      if (!(sphere.radius > 0)) r.fail(path + "/radius", "expected a radius > 0");
      sphere.material = material_of(object, path);
      if (object.contains("facing")) {
        const std::string facing = r.string(object["facing"], path + "/facing");
        if (facing != "outward" && facing != "inward")
          r.fail(path + "/facing", "unknown facing '" + facing + "' (expected outward or inward)");
        sphere.faces_inward = facing == "inward";
      }
      scene.spheres.push_back(sphere);
    } else if (type == "mesh") {
      r.check_keys(object, path, {"type", "name", "positions", "texcoords", "triangles", "material"});
      TriangleMesh mesh = read_inline_mesh(r, object, path);
      mesh.name = object.contains("name") ? r.string(object["name"], path + "/name") : path;
      mesh.material = material_of(object, path);
      scene.meshes.push_back(std::move(mesh));
    } else if (type == "obj") {
      r.check_keys(object, path, {"type", "file", "scale", "translate", "material"});
      const std::string file = r.string(r.require(object, path, "file"), path + "/file");
      const std::filesystem::path resolved = std::filesystem::path(base_directory) / file;
      TriangleMesh mesh;
      try {
        mesh = load_obj_mesh(resolved.lexically_normal().string());
      } catch (const InputError& e) {
        r.fail(path + "/file", e.what());  // the scene's place, then the OBJ's own message
      }
      const float scale = object.contains("scale")
          ? static_cast<float>(r.number(object["scale"], path + "/scale", 1e-30, 1e30)) : 1.0f;
      const glm::vec3 translate = object.contains("translate")
          ? r.vector<3>(object["translate"], path + "/translate") : glm::vec3(0.0f);
      transform_mesh(r, path, mesh, scale, translate);
      mesh.material = material_of(object, path);
      scene.meshes.push_back(std::move(mesh));
    } else {
      r.fail(path + "/type", "unknown object type '" + type + "' (expected sphere, mesh or obj)");
    }
  }

  if (root.contains("lights")) {
    const json& lights = root["lights"];
    if (!lights.is_array()) r.fail("/lights", "expected an array of lights");
    for (std::size_t i = 0; i < lights.size(); ++i) {
      const std::string path = "/lights/" + std::to_string(i);
      r.expect_object(lights[i], path);
      r.check_keys(lights[i], path, {"type", "position", "intensity", "power"});
      const std::string type = r.string(r.require(lights[i], path, "type"), path + "/type");
      if (type != "point")
        r.fail(path + "/type", "unknown light type '" + type +
                                   "' (expected point; area lights are objects whose material has an emission)");
      PointLight light;
      light.position = r.vector<3>(r.require(lights[i], path, "position"), path + "/position");
      // Either its intensity I (W/sr) or its power, the flux it sends out (W): I = flux / (4 pi).
      const bool has_intensity = lights[i].contains("intensity"), has_power = lights[i].contains("power");
      if (has_intensity && has_power)
        r.fail(path, "give 'intensity' (W/sr) or 'power' (W), not both (intensity = power / (4 pi))");
      if (has_intensity) light.intensity = r.color(lights[i]["intensity"], path + "/intensity", "intensity");
      else if (has_power) light.intensity = r.color(lights[i]["power"], path + "/power", "power") / (4.0f * kPi);
      else r.fail(path, "missing key 'intensity' (W/sr) or 'power' (W)");
      scene.lights.push_back(light);
    }
  }
  return scene;
}

}  // namespace

Scene parse_scene(const std::string& json_text, const std::string& source,
                  const std::string& base_directory) {
  const json root = parse_json_text(json_text, source);
  return read_scene(JsonReader(source), root, base_directory);
}

Scene load_scene(const std::string& path) {
  const std::string text = read_input_file(path, "scene file");
  const std::string base = std::filesystem::path(path).parent_path().string();
  return parse_scene(text, path, base.empty() ? "." : base);
}

}  // namespace raylab
