#pragma once
// Reading an input file whole, for the readers that parse text in memory (SVG, FOLD).
#include <string>

namespace sdog {

/// The bytes of the file at `path`. Throws InputError "PATH: cannot open file (<strerror>)" when it
/// cannot be opened or read (also for a directory).
std::string read_text_file(const std::string& path);

}  // namespace sdog
