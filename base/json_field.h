#pragma once
// Reading JSON input files (run configurations, workspaces, FOLD crease patterns) with errors that
// name the file and the JSON path of the offending value ("c.json: $.solver.epsilon: expected a
// number").
#include <Eigen/Core>
#include <cmath>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <vector>

#include "base/errors.h"
#include "base/text_format.h"

namespace sdog {

// Walks a JSON value with its path; every error names the file and the path.
class Field {
 public:
  Field(const nlohmann::json& value, std::string path, std::string source)
      : v_(value), path_(std::move(path)), source_(std::move(source)) {}

  [[noreturn]] void fail(const std::string& what) const {
    throw InputError(source_ + ": " + path_ + ": " + what);
  }
  const std::string& path() const { return path_; }
  /// "file: $.path", for messages raised later.
  std::string where() const { return source_ + ": " + path_; }
  const nlohmann::json& value() const { return v_; }

  /// The object's members; unknown keys are errors.
  void expect_object(const std::vector<std::string>& known) const {
    if (!v_.is_object()) fail("expected an object");
    const std::set<std::string> allowed(known.begin(), known.end());
    for (auto it = v_.begin(); it != v_.end(); ++it)
      if (!allowed.count(it.key()))
        throw InputError(source_ + ": " + path_ + "." + it.key() +
                         ": unknown key (known: " + join(known, ", ") + ")");
  }
  bool has(const char* key) const { return v_.contains(key); }
  Field operator[](const char* key) const { return Field(v_.at(key), path_ + "." + key, source_); }
  Field operator[](size_t i) const {
    return Field(v_.at(i), path_ + "[" + std::to_string(i) + "]", source_);
  }

  double number() const {
    if (!v_.is_number()) fail("expected a number");
    const double d = v_.get<double>();
    if (!std::isfinite(d)) fail("expected a finite number");
    return d;
  }
  double positive() const {
    const double d = number();
    if (!(d > 0)) fail("expected a number > 0, got " + format_number(d));
    return d;
  }
  double at_least(double min) const {
    const double d = number();
    if (!(d >= min))
      fail("expected a number >= " + format_number(min) + ", got " + format_number(d));
    return d;
  }
  double non_negative() const { return at_least(0); }
  int integer(int min) const {
    if (!v_.is_number_integer()) fail("expected an integer");
    const long long i = v_.get<long long>();
    if (i < min || i > 100000000)
      fail("expected an integer >= " + std::to_string(min) + ", got " + std::to_string(i));
    return static_cast<int>(i);
  }
  bool boolean() const {
    if (!v_.is_boolean()) fail("expected true or false");
    return v_.get<bool>();
  }
  std::string text() const {
    if (!v_.is_string()) fail("expected a string");
    return v_.get<std::string>();
  }
  template <int N>
  Eigen::Matrix<double, N, 1> vector() const {
    if (!v_.is_array() || v_.size() != N)
      fail("expected an array of " + std::to_string(N) + " numbers");
    Eigen::Matrix<double, N, 1> out;
    for (int i = 0; i < N; ++i) out[i] = (*this)[static_cast<size_t>(i)].number();
    return out;
  }
  size_t array_size() const {
    if (!v_.is_array()) fail("expected an array");
    return v_.size();
  }

 private:
  const nlohmann::json& v_;
  std::string path_;
  std::string source_;
};

}  // namespace sdog
