#pragma once
// Runs the sdog executable and captures its exit code, stdout and stderr.
#include <sys/wait.h>

#include <cstdlib>
#include <fstream>
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

/// `args` is appended to the sdog command line verbatim (quote paths with spaces yourself).
inline Run run_sdog(const std::string& args) {
  static int counter = 0;
  const std::string dir = temp_dir("run" + std::to_string(counter++));
  const std::string cmd =
      std::string("'") + SDOG_EXE + "' " + args + " >" + dir + "/out 2>" + dir + "/err";
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

}  // namespace sdog::test
