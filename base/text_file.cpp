#include "base/text_file.h"

#include <cerrno>
#include <cstdio>
#include <cstring>

#include "base/errors.h"

namespace sdog {

std::string read_text_file(const std::string& path) {
  std::FILE* file = std::fopen(path.c_str(), "rb");
  if (!file) throw InputError(path + ": cannot open file (" + std::strerror(errno) + ")");
  std::string text;
  char buffer[1 << 16];
  std::size_t count = 0;
  while ((count = std::fread(buffer, 1, sizeof buffer, file)) > 0) text.append(buffer, count);
  // Reading a directory fails here (EISDIR), not in fopen.
  const int error = std::ferror(file) ? errno : 0;
  std::fclose(file);
  if (error != 0) throw InputError(path + ": cannot open file (" + std::strerror(error) + ")");
  return text;
}

}  // namespace sdog
