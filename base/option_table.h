#pragma once
// Option tables: one row per user-visible field of an options struct, with its configuration key,
// the member it sets, its bounds and a one-line help text. A row is the one definition of its
// option: validate() checks the bounds it gives, the configuration layer reads and writes JSON
// with it (solver/config/), and the reference documentation is rendered from it.
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "base/enum_names.h"

namespace sdog {

enum class OptionType { kReal, kInteger, kBoolean, kChoice };

/// The values a number may take: from min to max, each end included unless it is open.
struct Bounds {
  double min = -std::numeric_limits<double>::infinity();
  double max = std::numeric_limits<double>::infinity();
  bool open_min = false, open_max = false;

  static Bounds any() { return {}; }
  static Bounds positive() { return above(0); }
  static Bounds above(double m) {
    return {m, std::numeric_limits<double>::infinity(), true, false};
  }
  static Bounds at_least(double m) {
    return {m, std::numeric_limits<double>::infinity(), false, false};
  }
  static Bounds between(double a, double b) { return {a, b, false, false}; }
  static Bounds open(double a, double b) { return {a, b, true, true}; }

  bool contains(double v) const;
  /// "> 0", ">= 1", "in [0, 1]", "in (0, 0.5)", "any" (JSON messages, reference tables).
  std::string symbols() const;
  /// "positive", "at least 1", "in [0, 1]" (validation messages: "KEY must be ...").
  std::string words() const;
};

/// One option of the options struct S. Values pass through as doubles: integers, booleans (0, 1)
/// and choices (the index of the name) are exact.
template <class S>
struct Option {
  std::string key;
  OptionType type = OptionType::kReal;
  Bounds bounds;
  std::vector<std::string> choices;  ///< kChoice: the names, indexed by the enum's value
  std::string help;
  std::string unset;  ///< what an optional value means while it is not set, e.g. "0.001 (N - 1)"
  std::function<std::optional<double>(const S&)> get;  ///< nullopt: an optional value not set
  std::function<void(S&, std::optional<double>)> set;
};

template <class S>
using OptionTable = std::vector<Option<S>>;

template <class S>
Option<S> real_option(const char* key, double S::*member, Bounds bounds, const char* help) {
  return {key,
          OptionType::kReal,
          bounds,
          {},
          help,
          {},
          [member](const S& s) { return std::optional<double>(s.*member); },
          [member](S& s, std::optional<double> v) { s.*member = *v; }};
}

/// A number that may be left unset; `unset` says what the code then uses.
template <class S>
Option<S> optional_real_option(const char* key, std::optional<double> S::*member, Bounds bounds,
                               const char* unset, const char* help) {
  return {key,
          OptionType::kReal,
          bounds,
          {},
          help,
          unset,
          [member](const S& s) { return s.*member; },
          [member](S& s, std::optional<double> v) { s.*member = v; }};
}

template <class S>
Option<S> integer_option(const char* key, int S::*member, Bounds bounds, const char* help) {
  return {key,
          OptionType::kInteger,
          bounds,
          {},
          help,
          {},
          [member](const S& s) { return std::optional<double>(s.*member); },
          [member](S& s, std::optional<double> v) { s.*member = static_cast<int>(*v); }};
}

template <class S>
Option<S> boolean_option(const char* key, bool S::*member, const char* help) {
  return {key,
          OptionType::kBoolean,
          Bounds::between(0, 1),
          {},
          help,
          {},
          [member](const S& s) { return std::optional<double>(s.*member ? 1 : 0); },
          [member](S& s, std::optional<double> v) { s.*member = *v != 0; }};
}

/// An enum member, its choices the names of its table (base/enum_names.h).
template <class S, class E>
Option<S> choice_option(const char* key, E S::*member, const char* help) {
  const std::vector<std::string>& names = enum_names<E>();
  const double last = static_cast<double>(names.size()) - 1;
  return {key,
          OptionType::kChoice,
          Bounds::between(0, last),
          names,
          help,
          {},
          [member](const S& s) { return std::optional<double>(static_cast<int>(s.*member)); },
          [member](S& s, std::optional<double> v) {
            s.*member = static_cast<E>(static_cast<int>(*v));
          }};
}

/// The rows of `inner`, the table of a member struct, as rows of S.
template <class S, class T>
OptionTable<S> nested_options(T S::*member, const OptionTable<T>& inner) {
  OptionTable<S> out;
  for (const Option<T>& o : inner)
    out.push_back({o.key, o.type, o.bounds, o.choices, o.help, o.unset,
                   [member, get = o.get](const S& s) { return get(s.*member); },
                   [member, set = o.set](S& s, std::optional<double> v) { set(s.*member, v); }});
  return out;
}

/// The rows of `a` followed by those of `b`.
template <class S>
OptionTable<S> concatenate(OptionTable<S> a, const OptionTable<S>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

/// The row of `key`, or nullptr.
template <class S>
const Option<S>* find_option(const OptionTable<S>& table, const std::string& key) {
  for (const Option<S>& o : table)
    if (o.key == key) return &o;
  return nullptr;
}

/// "" when every value that is set lies within its row's bounds (and is finite), else
/// "KEY must be WORDS" for the first that does not.
template <class S>
std::string check_option_bounds(const OptionTable<S>& table, const S& s) {
  for (const Option<S>& o : table) {
    const std::optional<double> v = o.get(s);
    if (v && !o.bounds.contains(*v)) return o.key + " must be " + o.bounds.words();
  }
  return "";
}

}  // namespace sdog
