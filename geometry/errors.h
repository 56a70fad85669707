#pragma once
// Exceptions thrown by the libraries. Executables map them to exit codes:
// InputError and OutputError -> 1 (a file must be fixed), UsageError -> 2 (an option must be
// changed).
#include <stdexcept>
#include <string>

namespace sdog {

/// The input (an SVG file, a JSON file, a pattern) cannot be used. The message names the file,
/// the element and the position, and says what to change.
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// An option value cannot work (resolution out of range, even resolution for a coarse mesh,
/// resolution too low for the pattern's junctions).
class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// An output cannot be written (directory not creatable, disk full, permission denied).
class OutputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace sdog
