// The rules of the source layout (docs/development.md), checked on the source files:
// each layer includes only itself and the layers below it, headers under internal/ stay inside
// their layer, and no file or function grows past the size limits.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

// Each layer (a folder) and the layers it may include directly; what they may include, it may too.
const std::map<std::string, std::vector<std::string>> kLayers = {
    {"base", {}},
    {"geometry/pattern", {"base"}},
    {"geometry/input", {"geometry/pattern"}},
    {"geometry/mesh", {"geometry/pattern"}},
    {"geometry/surface", {"geometry/mesh"}},
    {"solver/terms", {"geometry/mesh"}},
    {"solver/problem", {"solver/terms"}},
    {"solver/sqp", {"solver/terms"}},
    {"solver/patches", {"solver/sqp"}},
    {"solver/patches/ceres", {"solver/patches"}},
    {"solver/multilevel", {"solver/terms"}},
    {"solver/modes", {"solver/problem", "solver/patches/ceres", "solver/multilevel"}},
    {"solver/run", {"solver/modes"}},
    {"solver/config", {"solver/run"}},
    {"solver/experiments", {"solver/config", "geometry/input", "geometry/surface"}},
    {"solver/session", {"solver/config"}},
    {"ui/vis", {"solver/run", "geometry/surface"}},
    {"ui/control", {"ui/vis", "solver/session"}},
    {"ui/studio", {"ui/control", "geometry/input"}},
    {"app", {"ui/studio", "solver/experiments"}},
};

constexpr int kMaxFileLines = 600;
constexpr int kMaxFunctionLines = 80;

std::set<std::string> reachable(const std::string& layer) {
  std::set<std::string> out{layer};
  std::vector<std::string> todo{layer};
  while (!todo.empty()) {
    const std::string l = todo.back();
    todo.pop_back();
    for (const auto& below : kLayers.at(l))
      if (out.insert(below).second) todo.push_back(below);
  }
  return out;
}

// The layer of a source folder: the folder itself, without a trailing internal/.
std::string layer_of(std::string folder) {
  const std::string internal = "/internal";
  if (folder.size() > internal.size() &&
      folder.compare(folder.size() - internal.size(), internal.size(), internal) == 0)
    folder.resize(folder.size() - internal.size());
  return folder;
}

struct SourceFile {
  std::string path;  ///< relative to the project root
  std::vector<std::string> lines;
};

std::vector<SourceFile> source_files() {
  std::vector<SourceFile> out;
  const fs::path root = SDOG_SOURCE_DIR;
  for (const char* top : {"base", "geometry", "solver", "ui", "app"}) {
    for (const auto& e : fs::recursive_directory_iterator(root / top)) {
      const auto ext = e.path().extension();
      if (!e.is_regular_file() || (ext != ".h" && ext != ".cpp")) continue;
      SourceFile f{fs::relative(e.path(), root).generic_string(), {}};
      std::ifstream in(e.path());
      for (std::string line; std::getline(in, line);) f.lines.push_back(line);
      out.push_back(std::move(f));
    }
  }
  return out;
}

std::string folder_of(const std::string& path) {
  return fs::path(path).parent_path().generic_string();
}

TEST(Layout, EveryLayerIsListed) {
  for (const auto& f : source_files())
    EXPECT_TRUE(kLayers.count(layer_of(folder_of(f.path))))
        << f.path << " lies in a folder that is no layer of kLayers";
  for (const auto& [layer, below] : kLayers)
    for (const auto& b : below) EXPECT_TRUE(kLayers.count(b)) << layer << " names " << b;
}

TEST(Layout, IncludesRunDownTheLayers) {
  const std::regex include(R"re(^#include "((base|geometry|solver|ui|app)/[^"]+)")re");
  int checked = 0;
  for (const auto& f : source_files()) {
    const std::string layer = layer_of(folder_of(f.path));
    if (!kLayers.count(layer)) continue;
    const std::set<std::string> allowed = reachable(layer);
    for (size_t i = 0; i < f.lines.size(); ++i) {
      std::smatch m;
      if (!std::regex_search(f.lines[i], m, include)) continue;
      ++checked;
      const std::string target_folder = folder_of(m[1].str());
      const std::string target = layer_of(target_folder);
      EXPECT_TRUE(allowed.count(target))
          << f.path << ":" << i + 1 << " (layer " << layer << ") includes " << m[1].str()
          << " of layer " << target << ", which is not below it";
      if (target_folder != target) {
        EXPECT_EQ(target, layer) << f.path << ":" << i + 1 << " includes " << m[1].str()
                                 << ", a header internal to " << target;
      }
    }
  }
  EXPECT_GT(checked, 500);
}

TEST(Layout, NoFileIsLong) {
  for (const auto& f : source_files())
    EXPECT_LE(static_cast<int>(f.lines.size()), kMaxFileLines) << f.path;
}

// A function defined at namespace level: a line at column 0 with "(" that does not end in ";"
// and is no namespace, type, preprocessor or comment line, whose signature ends in "{"; its body
// ends at the next "}" in column 0.
TEST(Layout, NoFunctionIsLong) {
  const std::regex not_a_function(
      R"(^(namespace|struct|class|enum|union|extern|template|#|//|\}))");
  int functions = 0;
  for (const auto& f : source_files()) {
    const auto& L = f.lines;
    for (size_t i = 0; i < L.size(); ++i) {
      const std::string& l = L[i];
      if (l.empty() || std::isspace(static_cast<unsigned char>(l[0])) ||
          l.find('(') == std::string::npos || l.back() == ';' ||
          std::regex_search(l, not_a_function))
        continue;
      size_t k = i;
      while (k < L.size() && !L[k].empty() && L[k].back() != '{' && L[k].back() != ';') ++k;
      if (k == L.size() || L[k].empty() || L[k].back() != '{') continue;
      size_t end = k + 1;
      while (end < L.size() && (L[end].empty() || L[end][0] != '}')) ++end;
      ++functions;
      EXPECT_LE(static_cast<int>(end - i + 1), kMaxFunctionLines)
          << f.path << ":" << i + 1 << ": " << l;
      i = end;
    }
  }
  EXPECT_GT(functions, 1000);
}

// tests/ mirrors the sources: a test folder under tests/base, tests/geometry or tests/solver tests
// the source folder of the same name.
// The controllers of the studio are Qt-free: tests drive them without a window.
TEST(Layout, TheControllersIncludeNoQt) {
  int files = 0;
  for (const SourceFile& f : source_files()) {
    if (folder_of(f.path) != "ui/control") continue;
    ++files;
    for (const std::string& line : f.lines)
      if (line.rfind("#include <Q", 0) == 0 || line.rfind("#include <q", 0) == 0 ||
          line.find("QVTK") != std::string::npos)
        ADD_FAILURE() << f.path << ": " << line;
  }
  EXPECT_GE(files, 8);
}

TEST(Layout, TestFoldersMirrorTheSources) {
  const fs::path root = SDOG_SOURCE_DIR;
  int files = 0;
  for (const char* top : {"base", "geometry", "solver", "ui"}) {
    for (const auto& e : fs::recursive_directory_iterator(root / "tests" / top)) {
      if (e.path().extension() != ".cpp") continue;
      const fs::path source = fs::relative(e.path().parent_path(), root / "tests");
      ++files;
      EXPECT_TRUE(fs::is_directory(root / source))
          << e.path().generic_string() << ": no source folder " << source;
      if (source.generic_string() == "geometry" || source.generic_string() == "solver" ||
          source.generic_string() == "ui")
        ADD_FAILURE() << e.path().generic_string()
                      << ": belongs in the folder of the layer it tests";
    }
  }
  EXPECT_GT(files, 50);
}

}  // namespace
