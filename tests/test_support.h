#pragma once
// Paths and helpers shared by the test executables.
#include <gtest/gtest.h>

#include <unistd.h>
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace sdog::test {

inline std::string dataset(const std::string& name) {
  return std::string(SDOG_DATASETS_DIR) + "/" + name;
}

/// The project's own crease patterns (datasets/*.svg and *.fold), sorted.
inline std::vector<std::string> all_datasets() {
  std::vector<std::string> out;
  for (const auto& e : std::filesystem::directory_iterator(SDOG_DATASETS_DIR))
    if (e.path().extension() == ".svg" || e.path().extension() == ".fold")
      out.push_back(e.path().string());
  std::sort(out.begin(), out.end());
  return out;
}

/// ../shared/reference/patterns, or empty when ../shared is absent.
inline std::string reference_patterns_dir() {
  const std::string dir = std::string(SDOG_SHARED_DIR) + "/reference/patterns";
  return std::filesystem::is_directory(dir) ? dir : std::string();
}

inline std::vector<std::string> all_reference_patterns() {
  std::vector<std::string> out;
  const std::string dir = reference_patterns_dir();
  if (dir.empty()) return out;
  for (const auto& e : std::filesystem::directory_iterator(dir))
    if (e.path().extension() == ".svg" || e.path().extension() == ".fold")
      out.push_back(e.path().string());
  std::sort(out.begin(), out.end());
  return out;
}

#define SDOG_REQUIRE_SHARED()                                                             \
  do {                                                                                    \
    if (::sdog::test::reference_patterns_dir().empty())                                   \
      GTEST_SKIP() << "../shared/reference/patterns is absent: reference checks skipped"; \
  } while (0)

/// The temporary directories this test process made: removed when it exits, unless a test
/// failed (then they stay for inspection, named in the log) or SDOG_KEEP_TEST_FILES is set.
class TempDirs {
 public:
  static TempDirs& instance() {
    static TempDirs dirs;
    return dirs;
  }
  void add(const std::filesystem::path& dir) { dirs_.push_back(dir); }
  ~TempDirs() {
    const bool failed = ::testing::UnitTest::GetInstance()->failed_test_count() > 0;
    if (failed || std::getenv("SDOG_KEEP_TEST_FILES")) {
      for (const auto& d : dirs_) std::fprintf(stderr, "kept test files: %s\n", d.c_str());
      return;
    }
    std::error_code ignored;
    for (const auto& d : dirs_) std::filesystem::remove_all(d, ignored);
  }

 private:
  std::vector<std::filesystem::path> dirs_;
};

/// A fresh empty temporary directory for one test (see TempDirs for when it is removed).
inline std::string temp_dir(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() /
                   ("sdog_test_" + name + "_" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  TempDirs::instance().add(dir);
  return dir.string();
}

inline std::string write_file(const std::string& dir, const std::string& name,
                              const std::string& text) {
  const std::string path = dir + "/" + name;
  std::ofstream(path) << text;
  return path;
}

}  // namespace sdog::test
