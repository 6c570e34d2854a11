// The interface between the framework (framework/src/image.cpp) and its image I/O module
// (oiio_module.cpp, built as a separate shared module that links OpenImageIO): EXR files,
// reading any image file, comparisons. (PNG and PPM files are written without it, image.cpp.)
//
// Why a module: OpenImageIO brings in about 260 shared libraries. Linked into every program,
// the dynamic loader maps them all at start-up (0.19 s and 128 MiB for `--help`), in every
// render and in every autograder child, although most never need it. Loaded with
// load_image_io_module() on the first call that needs it, only the processes that read images,
// write EXR files or compare images pay for it, once.
//
// Nothing throws across this boundary: each function returns "" on success or the reason it
// failed, and image.cpp turns the reason into the exception its header promises.
#pragma once

#include "raylab/image.h"

#include <string>

namespace raylab::image_io {

// Raised whenever a field is added, removed or changes type, so that a stale module built from
// older sources is refused instead of called with the wrong layout.
constexpr int kModuleVersion = 3;

struct ModuleFunctions {
  int version = kModuleVersion;
  // An OpenEXR file of linear float values (the caller checked the extension).
  std::string (*write_exr)(const Image& image, const std::string& path) = nullptr;
  std::string (*read)(const std::string& path, Image& image) = nullptr;
  // Sizes are equal (the caller checked).
  std::string (*compare)(const Image& actual, const Image& expected, float threshold,
                         ImageDifference& difference) = nullptr;
  std::string (*resize)(const Image& image, int width, int height, Image& resized) = nullptr;
  std::string (*side_by_side_difference)(const Image& actual, const Image& expected,
                                         float full_scale, Image& picture) = nullptr;
  // OpenImageIO's one-time work done ahead (its EXR plugin found, its functions bound), so
  // that the first write is as fast as the next; writes no file. For a background load (image.h).
  void (*warm_up)() = nullptr;
};

// The one symbol the module exports (unmangled, so that the loader can look it up by name).
#define RAYLAB_IMAGE_IO_ENTRY_POINT "raylab_image_io_module_functions"
using EntryPoint = const ModuleFunctions* (*)();

// The module's functions, loaded on the first call (thread-safe) and kept for the process's
// life. Throws std::runtime_error naming the module's path and the loader's reason if the
// module is missing, does not load, or is of another version. (image_io_loader.cpp: the only
// platform-specific code of the framework.)
const ModuleFunctions& load_image_io_module();

}  // namespace raylab::image_io
