// Loads the image I/O module (image_io_module.h). The framework's only platform-specific
// code: POSIX dlopen, or LoadLibrary/GetProcAddress on Windows. A build configured with
// RAYLAB_WITH_OPENIMAGEIO=OFF (the Windows check under Wine, tools/windows-check) has no
// module: every call that needs it then says so.
//
// Where the module is, tried in this order:
//   1. $RAYLAB_IMAGE_IO_MODULE, if set (a program moved away from its build; tests): only there;
//   2. beside the program (or shared library) that holds this code, where the build puts it
//      (CMake's runtime output directory): a build tree's bin/ or a copied bin/ folder;
//   3. where this build wrote it (programs built into other folders, e.g. the self-test
//      graders in tests/submissions/);
//   4. the bare file name, for the system's own search (LD_LIBRARY_PATH, ...).
#include "image_io_module.h"

#include <cstdlib>
#include <stdexcept>
#include <string>
#include <vector>

#if defined(_WIN32)
#ifndef NOMINMAX
#define NOMINMAX
#endif
#include <windows.h>
#else
#include <dlfcn.h>
#endif

#if !defined(RAYLAB_NO_IMAGE_IO) && (!defined(RAYLAB_IMAGE_IO_MODULE_FILE) || !defined(RAYLAB_IMAGE_IO_MODULE_BUILD_PATH))
#error "RAYLAB_IMAGE_IO_MODULE_FILE and _BUILD_PATH (the module's name and path) must be set by framework/CMakeLists.txt"
#endif

namespace raylab::image_io {
namespace {

#if !defined(RAYLAB_NO_IMAGE_IO)
#if defined(_WIN32)
// The folder of the program or DLL this function was linked into, with a trailing backslash.
std::string own_folder() {
  HMODULE self = nullptr;
  if (!::GetModuleHandleExA(GET_MODULE_HANDLE_EX_FLAG_FROM_ADDRESS | GET_MODULE_HANDLE_EX_FLAG_UNCHANGED_REFCOUNT,
                            reinterpret_cast<LPCSTR>(&own_folder), &self))
    return "";
  char path[MAX_PATH * 4];
  const DWORD length = ::GetModuleFileNameA(self, path, sizeof path);
  if (length == 0 || length >= sizeof path) return "";
  const std::string text(path, length);
  const auto slash = text.find_last_of("\\/");
  return slash == std::string::npos ? "" : text.substr(0, slash + 1);
}
void* open_module(const std::string& path, std::string& reason) {
  HMODULE handle = ::LoadLibraryA(path.c_str());
  if (handle == nullptr) reason = path + ": LoadLibrary failed (error " + std::to_string(::GetLastError()) + ")";
  return reinterpret_cast<void*>(handle);
}
void* find_symbol(void* module, const char* name) {
  return reinterpret_cast<void*>(::GetProcAddress(static_cast<HMODULE>(module), name));
}
#else
// The folder of the binary this function was linked into, with a trailing '/'; "" if unknown.
std::string own_folder() {
  Dl_info info{};
  if (dladdr(reinterpret_cast<void*>(&own_folder), &info) == 0 || info.dli_fname == nullptr)
    return "";
  const std::string path = info.dli_fname;
  const auto slash = path.find_last_of('/');
  return slash == std::string::npos ? "" : path.substr(0, slash + 1);
}
void* open_module(const std::string& path, std::string& reason) {
  void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (handle == nullptr) {
    const char* text = dlerror();
    reason = text != nullptr ? std::string(text) : path + ": not loaded";
  }
  return handle;
}
void* find_symbol(void* module, const char* name) { return dlsym(module, name); }
#endif

const ModuleFunctions& load() {
  std::vector<std::string> candidates;
  if (const char* chosen = std::getenv("RAYLAB_IMAGE_IO_MODULE"); chosen != nullptr && *chosen != '\0') {
    candidates = {chosen};
  } else {
    candidates = {own_folder() + RAYLAB_IMAGE_IO_MODULE_FILE, RAYLAB_IMAGE_IO_MODULE_BUILD_PATH,
                  RAYLAB_IMAGE_IO_MODULE_FILE};
  }
  void* handle = nullptr;
  std::string tried;
  for (const std::string& candidate : candidates) {
    std::string reason;
    handle = open_module(candidate, reason);
    if (handle != nullptr) break;
    tried += "\n  " + reason;
  }
  if (handle == nullptr)
    throw std::runtime_error("image I/O: cannot load the OpenImageIO module " +
                             std::string(RAYLAB_IMAGE_IO_MODULE_FILE) + " (built beside the programs; "
                             "rebuild, or set RAYLAB_IMAGE_IO_MODULE to its path):" + tried);
  const auto entry = reinterpret_cast<EntryPoint>(find_symbol(handle, RAYLAB_IMAGE_IO_ENTRY_POINT));
  const ModuleFunctions* functions = entry != nullptr ? entry() : nullptr;
  if (functions == nullptr || functions->version != kModuleVersion)
    throw std::runtime_error("image I/O: the loaded " + std::string(RAYLAB_IMAGE_IO_MODULE_FILE) +
                             " is not this build's image module (stale file? rebuild)");
  return *functions;  // the module stays loaded for the process's life
}
#else
const ModuleFunctions& load() {
  throw std::runtime_error("image I/O: this build has no OpenImageIO (configured with RAYLAB_WITH_OPENIMAGEIO=OFF), "
                           "so it cannot read images, write EXR files or compare images");
}
#endif

}  // namespace

const ModuleFunctions& load_image_io_module() {
  static const ModuleFunctions& functions = load();  // once, thread-safe; retried if it threw
  return functions;
}

}  // namespace raylab::image_io
