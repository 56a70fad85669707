#pragma once
// All-or-nothing output: every file is written under a temporary name next to its final name and
// renamed only when all of them were written, so a failed run leaves no partial results.
#include <string>
#include <vector>

namespace sdog {

class OutputSet {
 public:
  /// Creates `dir` (and parents) if needed; throws OutputError naming it if that fails or it is
  /// not a writable directory.
  explicit OutputSet(std::string dir);
  OutputSet(const OutputSet&) = delete;
  OutputSet& operator=(const OutputSet&) = delete;
  /// Removes the temporary files of an uncommitted set, and the directories it created.
  ~OutputSet();

  /// Temporary path to write `name` (a file name inside the directory) to.
  std::string temporary(const std::string& name);
  /// Writes text to `name` (temporarily); throws OutputError on failure.
  void write_text(const std::string& name, const std::string& text);
  /// Renames every temporary file to its final name; returns the final paths in order.
  std::vector<std::string> commit();

  const std::string& dir() const { return dir_; }

 private:
  std::string dir_;
  std::vector<std::pair<std::string, std::string>> files_;  // (temporary, final)
  std::vector<std::string> created_;  // directories created by the constructor, deepest first
  bool committed_ = false;
};

}  // namespace sdog
