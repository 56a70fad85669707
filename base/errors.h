#pragma once
// The libraries' errors: one type, sdog::Error, whose kind says what must change and so how an
// executable exits (exit_code). The rule for reporting a problem:
//  - A call that cannot do what it was asked because of its input, its options or its output
//    throws an Error of the matching kind, with one line that names the file, element or option
//    and says what to change: an InputError, UsageError, OutputError or SolverError, or
//    throw_error(kind, ...) when the kind is known only at run time.
//  - An options struct's validate() returns that line (empty when the options are fine) instead
//    of throwing, so that its caller can name where the options came from (a configuration file,
//    the command line) and choose the kind.
//  - A solver iteration that fails during a run (a step that cannot be taken) is reported in its
//    StepReport (failed, with the reason), so that the run can end and report how far it got.
//  - A broken precondition between the project's own parts is a bug: std::logic_error. The
//    executables report it as an internal error, exit code 3.
#include <stdexcept>
#include <string>

namespace sdog {

enum class ErrorKind {
  kInput,   ///< the input (an SVG or FOLD file, a JSON file, a pattern) cannot be used
  kUsage,   ///< an option value cannot work (out of range, options that exclude each other)
  kOutput,  ///< an output cannot be written (directory not creatable, disk full, no permission)
  kSolver,  ///< a solver run cannot continue (divergence, a failed factorisation)
};

/// The exit code of an executable that stops with an error of this kind: 2 for usage errors (an
/// option must be changed), 1 for the others (a file or a setting must be fixed).
inline int exit_code(ErrorKind kind) {
  return kind == ErrorKind::kUsage ? 2 : 1;
}

/// The base of the shorthands below; thrown only as one of them (throw_error picks it by kind).
class Error : public std::runtime_error {
 public:
  ErrorKind kind() const { return kind_; }

 protected:
  Error(ErrorKind kind, const std::string& message) : std::runtime_error(message), kind_(kind) {}

 private:
  ErrorKind kind_;
};

/// The input cannot be used. The message names the file, the element and the position, and says
/// what to change.
struct InputError : Error {
  explicit InputError(const std::string& message) : Error(ErrorKind::kInput, message) {}
};

/// An option value cannot work (resolution out of range, even resolution for a coarse mesh,
/// resolution too low for the pattern's junctions).
struct UsageError : Error {
  explicit UsageError(const std::string& message) : Error(ErrorKind::kUsage, message) {}
};

/// An output cannot be written.
struct OutputError : Error {
  explicit OutputError(const std::string& message) : Error(ErrorKind::kOutput, message) {}
};

/// A solver run cannot continue; the message names the iteration and the cause.
struct SolverError : Error {
  explicit SolverError(const std::string& message) : Error(ErrorKind::kSolver, message) {}
};

/// Throws the shorthand of `kind` (an InputError for kInput, ...), so that callers that catch one
/// shorthand catch it.
[[noreturn]] inline void throw_error(ErrorKind kind, const std::string& message) {
  switch (kind) {
    case ErrorKind::kInput:
      throw InputError(message);
    case ErrorKind::kUsage:
      throw UsageError(message);
    case ErrorKind::kOutput:
      throw OutputError(message);
    case ErrorKind::kSolver:
      break;
  }
  throw SolverError(message);
}

}  // namespace sdog
