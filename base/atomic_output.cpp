#include "base/atomic_output.h"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "base/errors.h"

namespace sdog {

namespace fs = std::filesystem;

OutputSet::OutputSet(std::string dir) : dir_(std::move(dir)) {
  std::error_code ec;
  // The directories this set creates, deepest first: removed again if nothing is committed.
  for (fs::path p = fs::absolute(dir_, ec); !p.empty() && !fs::exists(p, ec); p = p.parent_path()) {
    created_.push_back(p.string());
    if (p == p.parent_path()) break;
  }
  // A constructor that throws runs no destructor: remove what it created before throwing.
  auto fail = [&](const std::string& message) {
    for (const auto& d : created_) fs::remove(d, ec);
    throw OutputError(message);
  };
  fs::create_directories(dir_, ec);
  if (ec) fail(dir_ + ": cannot create the output directory (" + ec.message() + ")");
  if (!fs::is_directory(dir_)) fail(dir_ + ": exists and is not a directory");
  // Writable means a file can be made in it: create and remove one, so that an unusable directory
  // is refused now and not after the work (access() would say yes to root everywhere, also in
  // /proc or /sys).
  const std::string probe =
      (fs::path(dir_) / (".sdog-probe." + std::to_string(::getpid()))).string();
  std::ofstream test(probe, std::ios::binary);
  test << 'x';
  test.close();
  const std::string why = std::strerror(errno);
  fs::remove(probe, ec);
  if (!test) fail(dir_ + ": the output directory is not writable (" + why + ")");
}

OutputSet::~OutputSet() {
  if (committed_) return;
  for (const auto& f : files_) {
    std::error_code ec;
    fs::remove(f.first, ec);
  }
  for (const auto& d : created_) {
    std::error_code ec;
    fs::remove(d, ec);  // only removes empty directories
  }
}

std::string OutputSet::temporary(const std::string& name) {
  const std::string final_path = (fs::path(dir_) / name).string();
  const std::string tmp =
      (fs::path(dir_) / ("." + name + "." + std::to_string(::getpid()) + ".tmp")).string();
  files_.push_back({tmp, final_path});
  return tmp;
}

void OutputSet::write_text(const std::string& name, const std::string& text) {
  const std::string tmp = temporary(name);
  std::ofstream out(tmp, std::ios::binary);
  out << text;
  out.close();
  if (!out)
    throw OutputError((fs::path(dir_) / name).string() + ": cannot write (" + std::strerror(errno) +
                      "; writing " + tmp + ")");
}

std::vector<std::string> OutputSet::commit() {
  std::vector<std::string> written;
  for (const auto& [tmp, final_path] : files_) {
    std::error_code ec;
    fs::rename(tmp, final_path, ec);
    if (ec)
      throw OutputError(final_path + ": cannot move the written file into place (" + ec.message() +
                        ")");
    written.push_back(final_path);
  }
  committed_ = true;
  return written;
}

}  // namespace sdog
