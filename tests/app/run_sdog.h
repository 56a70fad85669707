#pragma once
// Runs the sdog executable and captures its exit code, stdout and stderr.
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>

#include "tests/test_support.h"

namespace sdog::test {

struct Run {
  int code = -1;
  std::string out, err;
};

inline std::string slurp(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

/// `args` is appended to the sdog command line verbatim (quote paths with spaces yourself);
/// `prefix` goes before the executable (e.g. "env -u DISPLAY").
inline Run run_sdog(const std::string& args, const std::string& prefix = "") {
  static int counter = 0;
  const std::string dir = temp_dir("run" + std::to_string(counter++));
  const std::string cmd =
      prefix + " '" + SDOG_EXE + "' " + args + " >" + dir + "/out 2>" + dir + "/err";
  const int status = std::system(cmd.c_str());
  Run r;
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  r.out = slurp(dir + "/out");
  r.err = slurp(dir + "/err");
  return r;
}

inline int count_lines(const std::string& s) {
  int n = 0;
  for (char c : s) n += c == '\n';
  return n;
}

/// Runs `args --out DIR/file/sub` where DIR/file is a file, so the output directory cannot be
/// created, and checks the failure: exit code 1, one line naming DIR/file, nothing else in DIR.
inline Run expect_unwritable_output_fails(const std::string& args, const std::string& name) {
  const std::string dir = temp_dir(name);
  write_file(dir, "file", "x");
  const Run r = run_sdog(args + " --out " + dir + "/file/sub");
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_EQ(count_lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find(dir + "/file"), std::string::npos) << r.err;
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir),
                          std::filesystem::directory_iterator()),
            1)
      << "files left in " << dir;
  return r;
}

}  // namespace sdog::test
