// OBJ meshes through tinyobjloader: triangles with positions and texture coordinates, every
// error naming the file (and the face) and what is wrong.
#include "raylab/scene_loader.h"

#include "raylab/error.h"

#include "input_file.h"

#include <tiny_obj_loader.h>

#include <cmath>
#include <string>
#include <unordered_map>

namespace raylab {

namespace {

// The OBJ text tinyobjloader is given, made safe for tinyobjloader 2.0rc10, which has
// undefined behaviour on two inputs that fuzzing found (docs/fuzzing.md); line numbers stay
// the same:
//  - every `vw` line (vertex weights, an extension raylab does not use) becomes a comment:
//    tinyobjloader converts its joint numbers to int unchecked (1e10 overflows);
//  - a number whose exponent has more than 9 digits, on a line of numbers (v, vt, vn, vp, t),
//    is an error naming the line: tinyobjloader's exponent overflows int.
std::string prepared_for_tinyobjloader(const std::string& text, const std::string& path) {
  std::string result = text;
  std::size_t line = 1;
  for (std::size_t start = 0; start < result.size(); ++line) {
    // Lines end as tinyobjloader ends them: at "\n", "\r\n" or a lone "\r".
    std::size_t end = result.find_first_of("\r\n", start);
    if (end == std::string::npos) end = result.size();
    std::size_t i = start;
    while (i < end && (result[i] == ' ' || result[i] == '\t')) ++i;
    std::size_t keyword_end = i;
    while (keyword_end < end && result[keyword_end] != ' ' && result[keyword_end] != '\t') ++keyword_end;
    const std::string keyword = result.substr(i, keyword_end - i);
    if (keyword == "vw") {
      result[i] = '#';
    } else if (keyword == "v" || keyword == "vt" || keyword == "vn" || keyword == "vp" || keyword == "t") {
      for (std::size_t j = keyword_end; j < end; ++j) {
        if (result[j] != 'e' && result[j] != 'E') continue;
        std::size_t k = j + 1;
        if (k < end && (result[k] == '+' || result[k] == '-')) ++k;
        std::size_t digits = 0;
        while (k + digits < end && result[k + digits] >= '0' && result[k + digits] <= '9') ++digits;
        if (digits > 9)
          throw InputError(path + ": malformed OBJ: line " + std::to_string(line) +
                           ": a number's exponent has more than 9 digits");
      }
    }
    start = end + (result.compare(end, 2, "\r\n") == 0 ? 2 : 1);
  }
  return result;
}

}  // namespace

TriangleMesh load_obj_mesh(const std::string& path) {
  return parse_obj_mesh(read_input_file(path, "OBJ file"), path);
}

TriangleMesh parse_obj_mesh(const std::string& text, const std::string& path) {
  tinyobj::ObjReaderConfig config;
  config.triangulate = true;
  config.vertex_color = false;
  tinyobj::ObjReader reader;
  // From memory, with no material text: `mtllib` names no file that is opened (raylab's
  // materials come from the scene), so `mtllib /dev/zero` cannot make it read forever.
  if (!reader.ParseFromString(prepared_for_tinyobjloader(text, path), "", config)) {
    std::string reason = reader.Error();
    while (!reason.empty() && (reason.back() == '\n' || reason.back() == ' ')) reason.pop_back();
    throw InputError(path + ": malformed OBJ: " + reason);
  }
  const tinyobj::attrib_t& attrib = reader.GetAttrib();
  const std::size_t vertex_count = attrib.vertices.size() / 3;
  const std::size_t texcoord_count = attrib.texcoords.size() / 2;
  for (float value : attrib.vertices)
    if (!std::isfinite(value)) throw InputError(path + ": malformed OBJ: a vertex position (v) is not a finite float (beyond about 3.4e38)");
  for (float value : attrib.texcoords)
    if (!std::isfinite(value)) throw InputError(path + ": malformed OBJ: a texture coordinate (vt) is not a finite float (beyond about 3.4e38)");

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
