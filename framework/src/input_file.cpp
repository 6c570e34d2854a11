#include "input_file.h"

#include "raylab/error.h"

#include <filesystem>
#include <fstream>
#include <sstream>
#include <system_error>

namespace raylab {

std::string read_input_file(const std::string& path, const std::string& what) {
  std::error_code error;
  const std::filesystem::file_status status = std::filesystem::status(path, error);
  if (error || !std::filesystem::exists(status))
    throw InputError(path + ": cannot open " + what + " (does it exist?)");
  if (!std::filesystem::is_regular_file(status))
    throw InputError(path + ": is not a regular file (" +
                     (std::filesystem::is_directory(status) ? "a folder" : "a device, pipe or socket") +
                     "), cannot read it as " + what);
  const std::uintmax_t size = std::filesystem::file_size(path, error);
  if (!error && size > kMaxInputFileBytes)
    throw InputError(path + ": " + what + " is " + std::to_string(size) + " bytes, more than the " +
                     std::to_string(kMaxInputFileBytes) + " raylab reads");
  std::ifstream file(path, std::ios::binary);
  if (!file) throw InputError(path + ": cannot open " + what + " (is it readable?)");
  std::string text;
  text.resize(static_cast<std::size_t>(error ? 0 : size));
  file.read(text.data(), static_cast<std::streamsize>(text.size()));
  text.resize(static_cast<std::size_t>(file.gcount()));
  if (file.bad()) throw InputError(path + ": cannot read " + what);
  return text;
}

}  // namespace raylab
