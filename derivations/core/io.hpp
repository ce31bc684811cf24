// File output that never leaves a half-written file: write to a temporary file beside the
// target, then rename over it.
#pragma once
#include <string>
#include <vector>

namespace dc {

// Throws std::runtime_error("cannot write 'path': reason") on failure; the target is then
// untouched.
void write_file_atomic(const std::string& path, const std::string& content);

// Reads a whole file; throws InputError at "path:0:0" ("cannot read 'path': No such file").
std::string read_file(const std::string& path);

// The derivation files named on a command line: a directory stands for its *.dc files in sorted
// order (an empty one is an InputError), anything else is taken as a file (a missing file then
// becomes an input error when it is read).
std::vector<std::string> derivation_files(const std::vector<std::string>& inputs);

}  // namespace dc
