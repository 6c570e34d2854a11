// Scene files: JSON (docs/scene-format.md) read through nlohmann-json, meshes through
// tinyobjloader. Every error names the file, the place and what was expected.
#include "raylab/scene_loader.h"

#include "raylab/error.h"

#include <nlohmann/json.hpp>
#include <tiny_obj_loader.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <map>
#include <sstream>
#include <unordered_map>

namespace raylab {
namespace {

using nlohmann::json;

// Reads values out of a parsed document, naming the JSON path of anything wrong.
class SceneReader {
 public:
  explicit SceneReader(std::string source) : source_(std::move(source)) {}

  [[noreturn]] void fail(const std::string& path, const std::string& what) const {
    throw InputError(source_ + ": at " + (path.empty() ? "/" : path) + ": " + what);
  }

  const std::string& source() const { return source_; }

  void expect_object(const json& value, const std::string& path) const {
    if (!value.is_object()) fail(path, "expected an object {...}, got " + describe(value));
  }

  // Rejects keys outside `allowed`: a typo must not be silently ignored.
  void check_keys(const json& object, const std::string& path,
                  std::initializer_list<const char*> allowed) const {
    for (const auto& item : object.items()) {
      bool known = false;
      std::string list;
      for (const char* key : allowed) {
        known = known || item.key() == key;
        list += std::string(list.empty() ? "" : ", ") + key;
      }
      if (!known) fail(path + "/" + item.key(), "unknown key '" + item.key() + "' (expected one of: " + list + ")");
    }
  }

  const json& require(const json& object, const std::string& path, const char* key) const {
    const auto it = object.find(key);
    if (it == object.end()) fail(path, std::string("missing key '") + key + "'");
    return *it;
  }

  double number(const json& value, const std::string& path, double min, double max) const {
    if (!value.is_number()) fail(path, "expected a number, got " + describe(value));
    const double x = value.get<double>();
    if (!std::isfinite(x) || x < min || x > max) {
      std::ostringstream what;
      what << "expected a number in [" << min << ", " << max << "], got " << value.dump();
      fail(path, what.str());
    }
    return x;
  }

  int integer(const json& value, const std::string& path, long long min, long long max) const {
    if (!value.is_number_integer()) fail(path, "expected a whole number, got " + describe(value));
    const long long x = value.get<long long>();
    if (x < min || x > max)
      fail(path, "expected a whole number in [" + std::to_string(min) + ", " +
                     std::to_string(max) + "], got " + value.dump());
    return static_cast<int>(x);
  }

  std::string string(const json& value, const std::string& path) const {
    if (!value.is_string()) fail(path, "expected a string, got " + describe(value));
    return value.get<std::string>();
  }

  template <int N>
  glm::vec<N, float> vector(const json& value, const std::string& path) const {
    if (!value.is_array() || value.size() != N)
      fail(path, "expected an array of " + std::to_string(N) + " numbers, got " + describe(value));
    glm::vec<N, float> v;
    for (int i = 0; i < N; ++i)
      v[i] = static_cast<float>(number(value[i], path + "/" + std::to_string(i), -1e30, 1e30));
    return v;
  }

  // A colour: three numbers >= 0, or one number for grey.
  glm::vec3 color(const json& value, const std::string& path) const {
    if (value.is_number()) return glm::vec3(static_cast<float>(number(value, path, 0, 1e6)));
    const glm::vec3 c = vector<3>(value, path);
    if (c.x < 0 || c.y < 0 || c.z < 0) fail(path, "colour components must be >= 0");
    return c;
  }

  static std::string describe(const json& value) {
    std::string text = value.dump();
    if (text.size() > 40) text = text.substr(0, 37) + "...";
    return std::string(value.type_name()) + " " + text;
  }

 private:
  std::string source_;
};

Camera read_camera(const SceneReader& r, const json& node, const std::string& path) {
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

Material read_material(const SceneReader& r, const json& node, const std::string& path,
                       const std::string& name) {
  r.expect_object(node, path);
  r.check_keys(node, path, {"type", "diffuse_color", "checkerboard", "kd", "ks",
                            "specular_exponent", "index_of_refraction"});
  Material m;
  m.name = name;
  const std::string type = r.string(r.require(node, path, "type"), path + "/type");
  if (type == "diffuse_glossy") m.kind = MaterialKind::DiffuseGlossy;
  else if (type == "reflective") m.kind = MaterialKind::Reflective;
  else if (type == "reflective_refractive") m.kind = MaterialKind::ReflectiveRefractive;
  else r.fail(path + "/type", "unknown material type '" + type +
                                   "' (expected diffuse_glossy, reflective or reflective_refractive)");
  if (node.contains("diffuse_color")) m.diffuse_color = r.color(node["diffuse_color"], path + "/diffuse_color");
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
TriangleMesh read_inline_mesh(const SceneReader& r, const json& node, const std::string& path) {
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
      r.fail(tpath, "expected three vertex indices, got " + SceneReader::describe(triangles[i]));
    for (int k = 0; k < 3; ++k)
      mesh.indices.push_back(static_cast<std::uint32_t>(
          r.integer(triangles[i][k], tpath + "/" + std::to_string(k), 0, last)));
  }
  return mesh;
}

void transform_mesh(TriangleMesh& mesh, float scale, const glm::vec3& translate) {
  for (glm::vec3& p : mesh.positions) p = p * scale + translate;
}

Scene read_scene(const SceneReader& r, const json& root, const std::string& base_directory) {
  r.expect_object(root, "");
  r.check_keys(root, "", {"camera", "background", "max_depth", "materials", "objects", "lights"});
  Scene scene;
  scene.source = r.source();
  scene.camera = read_camera(r, r.require(root, "", "camera"), "/camera");
  if (root.contains("background")) scene.background = r.color(root["background"], "/background");
  if (root.contains("max_depth")) scene.max_depth = r.integer(root["max_depth"], "/max_depth", 0, 64);

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
  if (!objects.is_array()) r.fail("/objects", "expected an array of objects, got " + SceneReader::describe(objects));
  for (std::size_t i = 0; i < objects.size(); ++i) {
    const std::string path = "/objects/" + std::to_string(i);
    const json& object = objects[i];
    r.expect_object(object, path);
    const std::string type = r.string(r.require(object, path, "type"), path + "/type");
    if (type == "sphere") {
      r.check_keys(object, path, {"type", "center", "radius", "material"});
      Sphere sphere;
      sphere.center = r.vector<3>(r.require(object, path, "center"), path + "/center");
      sphere.radius = static_cast<float>(r.number(r.require(object, path, "radius"), path + "/radius", 1e-30, 1e30));
      if (!(sphere.radius > 0)) r.fail(path + "/radius", "expected a radius > 0");
      sphere.material = material_of(object, path);
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
      transform_mesh(mesh, scale, translate);
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
      r.check_keys(lights[i], path, {"type", "position", "intensity"});
      const std::string type = r.string(r.require(lights[i], path, "type"), path + "/type");
      if (type != "point") r.fail(path + "/type", "unknown light type '" + type + "' (expected point)");
      PointLight light;
      light.position = r.vector<3>(r.require(lights[i], path, "position"), path + "/position");
      light.intensity = r.color(r.require(lights[i], path, "intensity"), path + "/intensity");
      scene.lights.push_back(light);
    }
  }
  return scene;
}

}  // namespace

Scene parse_scene(const std::string& json_text, const std::string& source,
                  const std::string& base_directory) {
  json root;
  try {
    root = json::parse(json_text, nullptr, /*allow_exceptions=*/true, /*ignore_comments=*/true);
  } catch (const json::parse_error& e) {
    // nlohmann's text is "[json.exception.parse_error.101] parse error at line L, column C: ...".
    std::string what = e.what();
    const std::string marker = "parse error at ";
    const auto at = what.find(marker);
    if (at != std::string::npos) what = what.substr(at + marker.size());
    throw InputError(source + ": not valid JSON: " + what);
  }
  return read_scene(SceneReader(source), root, base_directory);
}

Scene load_scene(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  if (!file) throw InputError(path + ": cannot open scene file (does it exist?)");
  std::ostringstream text;
  text << file.rdbuf();
  const std::string base = std::filesystem::path(path).parent_path().string();
  return parse_scene(text.str(), path, base.empty() ? "." : base);
}

TriangleMesh load_obj_mesh(const std::string& path) {
  if (!std::ifstream(path)) throw InputError(path + ": cannot open OBJ file (does it exist?)");
  tinyobj::ObjReaderConfig config;
  config.triangulate = true;
  config.vertex_color = false;
  tinyobj::ObjReader reader;
  if (!reader.ParseFromFile(path, config)) {
    std::string reason = reader.Error();
    while (!reason.empty() && (reason.back() == '\n' || reason.back() == ' ')) reason.pop_back();
    throw InputError(path + ": malformed OBJ: " + reason);
  }
  const tinyobj::attrib_t& attrib = reader.GetAttrib();
  const std::size_t vertex_count = attrib.vertices.size() / 3;
  const std::size_t texcoord_count = attrib.texcoords.size() / 2;
  for (float value : attrib.vertices)
    if (!std::isfinite(value)) throw InputError(path + ": malformed OBJ: a vertex position is not a finite number");

  TriangleMesh mesh;
  mesh.name = path;
  // OBJ indexes positions and texture coordinates separately; raylab meshes have one index
  // per vertex, so each distinct (position, texcoord) pair becomes one vertex.
  std::unordered_map<long long, std::uint32_t> vertex_of_pair;
  bool any_texcoord = false;
  for (const tinyobj::shape_t& shape : reader.GetShapes())
    for (const tinyobj::index_t& index : shape.mesh.indices) any_texcoord = any_texcoord || index.texcoord_index >= 0;
  for (const tinyobj::shape_t& shape : reader.GetShapes()) {
    std::size_t face_start = 0;
    for (std::size_t face = 0; face < shape.mesh.num_face_vertices.size(); ++face) {
      const unsigned corners = shape.mesh.num_face_vertices[face];
      if (corners != 3) {
        face_start += corners;
        continue;  // points and lines (tinyobjloader keeps them) are not surfaces
      }
      for (unsigned k = 0; k < 3; ++k) {
        const tinyobj::index_t index = shape.mesh.indices[face_start + k];
        if (index.vertex_index < 0 || static_cast<std::size_t>(index.vertex_index) >= vertex_count)
          throw InputError(path + ": malformed OBJ: face " + std::to_string(face + 1) + " of '" +
                           shape.name + "' uses vertex " + std::to_string(index.vertex_index + 1) +
                           " but the file has " + std::to_string(vertex_count));
        if (index.texcoord_index >= 0 && static_cast<std::size_t>(index.texcoord_index) >= texcoord_count)
          throw InputError(path + ": malformed OBJ: face " + std::to_string(face + 1) +
                           " uses texture coordinate " + std::to_string(index.texcoord_index + 1) +
                           " but the file has " + std::to_string(texcoord_count));
        const long long key = static_cast<long long>(index.vertex_index) * (static_cast<long long>(texcoord_count) + 1) +
                              (index.texcoord_index + 1);
        auto [it, inserted] = vertex_of_pair.emplace(key, static_cast<std::uint32_t>(mesh.positions.size()));
        if (inserted) {
          const float* p = &attrib.vertices[3 * static_cast<std::size_t>(index.vertex_index)];
          mesh.positions.emplace_back(p[0], p[1], p[2]);
          if (any_texcoord) {
            glm::vec2 st(0.0f);
            if (index.texcoord_index >= 0) {
              const float* t = &attrib.texcoords[2 * static_cast<std::size_t>(index.texcoord_index)];
              st = glm::vec2(t[0], t[1]);
            }
            mesh.texcoords.push_back(st);
          }
        }
        mesh.indices.push_back(it->second);
      }
      face_start += corners;
    }
  }
  if (mesh.indices.empty()) throw InputError(path + ": malformed OBJ: no triangles (no 'f' lines)");
  return mesh;
}

}  // namespace raylab
