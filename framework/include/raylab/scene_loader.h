// Reading scene files (JSON; format in docs/scene-format.md) and meshes (OBJ).
#pragma once

#include "raylab/scene.h"

#include <string>

namespace raylab {

// Reads a scene file. Throws InputError naming the file, the JSON path (e.g.
// /objects/2/radius) and what was expected, for every malformed or missing part.
Scene load_scene(const std::string& path);

// Parses scene JSON from a string; `source` names it in messages. Relative file references
// (OBJ meshes) are resolved against `base_directory`.
Scene parse_scene(const std::string& json_text, const std::string& source,
                  const std::string& base_directory);

// Reads a triangulated OBJ mesh (positions and texture coordinates) through tinyobjloader.
// Throws InputError naming the file (and line where known) if it is missing, not a regular
// file, or malformed. `mtllib` lines are ignored: no other file is read.
TriangleMesh load_obj_mesh(const std::string& path);

// The same for OBJ text already in memory; `source` names it in messages.
TriangleMesh parse_obj_mesh(const std::string& obj_text, const std::string& source);

}  // namespace raylab
