// File output that never leaves a half-written file: write to a temporary file beside the
// target, then rename over it.
#pragma once
#include <string>

namespace dc {

// Throws std::runtime_error("cannot write 'path': reason") on failure; the target is then
// untouched.
void write_file_atomic(const std::string& path, const std::string& content);

// Reads a whole file; throws InputError at "path:0:0" ("cannot read 'path': No such file").
std::string read_file(const std::string& path);

}  // namespace dc
