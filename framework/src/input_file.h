// Reading a whole input file (scene JSON, OBJ mesh) into memory, as untrusted input: only a
// regular file is read (a folder, /dev/zero or a pipe named as a scene is an error, not an
// endless read), and at most kMaxInputFileBytes of it. Private to the framework.
#pragma once

#include <cstdint>
#include <string>

namespace raylab {

// 256 MiB: the shipped bunny is 0.1 MiB; a mesh this large already needs gigabytes once parsed.
constexpr std::uintmax_t kMaxInputFileBytes = std::uintmax_t(256) << 20;

// The contents of `path`. `what` names the kind of file in messages ("scene file", "OBJ
// file"). Throws InputError "PATH: cannot open WHAT (does it exist?)", "PATH: is not a regular
// file (a folder or a device), cannot read it as WHAT" or "PATH: WHAT is N bytes, more than
// the 268435456 raylab reads".
std::string read_input_file(const std::string& path, const std::string& what);

}  // namespace raylab
