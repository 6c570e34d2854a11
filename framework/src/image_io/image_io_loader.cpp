// Loads the image I/O module (image_io_module.h). The framework's only platform-specific
// code: POSIX dlopen here; a Windows port adds LoadLibrary/GetProcAddress in this file alone.
//
// Where the module is: beside the program (or shared library) that holds this code, where the
// build puts it (CMake's runtime output directory), so a build tree, a copied bin/ folder and
// the student release all find it without any path setting. If it is not there, the system's
// own search (LD_LIBRARY_PATH, ...) gets the bare file name.
#include "image_io_module.h"

#include <stdexcept>
#include <string>

#if defined(_WIN32)
#error "image_io_loader.cpp: loading the image I/O module on Windows is not written yet (LoadLibraryW, GetProcAddress)"
#else
#include <dlfcn.h>
#endif

#ifndef RAYLAB_IMAGE_IO_MODULE_FILE
#error "RAYLAB_IMAGE_IO_MODULE_FILE (the module's file name) must be set by framework/CMakeLists.txt"
#endif

namespace raylab::image_io {
namespace {

// The folder of the binary this function was linked into, with a trailing '/'; "" if unknown.
std::string own_folder() {
  Dl_info info{};
  if (dladdr(reinterpret_cast<void*>(&own_folder), &info) == 0 || info.dli_fname == nullptr)
    return "";
  const std::string path = info.dli_fname;
  const auto slash = path.find_last_of('/');
  return slash == std::string::npos ? "" : path.substr(0, slash + 1);
}

const ModuleFunctions& load() {
  const std::string file = RAYLAB_IMAGE_IO_MODULE_FILE;
  const std::string beside_program = own_folder() + file;
  void* handle = dlopen(beside_program.c_str(), RTLD_NOW | RTLD_LOCAL);
  std::string reason;
  if (handle == nullptr) {
    reason = dlerror();
    handle = dlopen(file.c_str(), RTLD_NOW | RTLD_LOCAL);
  }
  if (handle == nullptr)
    throw std::runtime_error("image I/O: cannot load the OpenImageIO module " + beside_program +
                             " (" + reason + "); it is built beside the programs (rebuild)");
  const auto entry = reinterpret_cast<EntryPoint>(dlsym(handle, RAYLAB_IMAGE_IO_ENTRY_POINT));
  const ModuleFunctions* functions = entry != nullptr ? entry() : nullptr;
  if (functions == nullptr || functions->version != kModuleVersion)
    throw std::runtime_error("image I/O: " + beside_program +
                             " is not this build's image module (stale file? rebuild)");
  return *functions;  // the module stays loaded for the process's life
}

}  // namespace

const ModuleFunctions& load_image_io_module() {
  static const ModuleFunctions& functions = load();  // once, thread-safe; retried if it threw
  return functions;
}

}  // namespace raylab::image_io
