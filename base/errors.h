#pragma once
// Exceptions thrown by the libraries. Executables map them to exit codes:
// InputError, OutputError and SolverError -> 1 (a file or a setting must be fixed), UsageError ->
// 2 (an option must be changed).
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

/// A solver run cannot continue (divergence, a failed factorisation); the message names the
/// iteration and the cause.
class SolverError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace sdog
