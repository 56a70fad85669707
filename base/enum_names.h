#pragma once
// Names of enumerators: one table per enum, the one place its names are spelled, used to print
// them, to parse them (command line, configuration files, FOLD and CSV columns) and to list the
// choices (help texts, CLI11 checks, option tables, menus).
//
// A table is a specialisation of EnumNames beside the enum, one row per enumerator in the order of
// their values (0, 1, 2, ...), which choice options rely on and enum_name checks at compile time:
//
//   template <> struct EnumNames<Preset> {
//     static constexpr const char* noun = "preset";
//     static constexpr EnumName<Preset> rows[] = {{Preset::kDefault, "default"}, {Preset::kThesis,
//     "thesis"}};
//   };
#include <algorithm>
#include <cstddef>
#include <iterator>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "base/errors.h"

namespace sdog {

template <class E>
struct EnumName {
  E value;
  const char* name;
};

/// Specialised for every named enum (see above).
template <class E>
struct EnumNames;

namespace enum_names_detail {
template <class E>
constexpr bool in_value_order() {
  std::size_t i = 0;
  for (const EnumName<E>& row : EnumNames<E>::rows)
    if (static_cast<std::size_t>(row.value) != i++) return false;
  return true;
}
}  // namespace enum_names_detail

/// The enumerator's name.
template <class E>
const char* enum_name(E value) {
  static_assert(enum_names_detail::in_value_order<E>(),
                "EnumNames rows must follow the enum's values");
  return EnumNames<E>::rows[static_cast<std::size_t>(value)].name;
}

/// Every enumerator, in order.
template <class E>
const std::vector<E>& enum_values() {
  static const std::vector<E> values = [] {
    std::vector<E> out;
    for (const EnumName<E>& row : EnumNames<E>::rows) out.push_back(row.value);
    return out;
  }();
  return values;
}

/// Every name, in the enum's order (the index of a name is its enumerator's value).
template <class E>
const std::vector<std::string>& enum_names() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> out;
    for (const EnumName<E>& row : EnumNames<E>::rows) out.emplace_back(row.name);
    return out;
  }();
  return names;
}

/// The names, comma separated (help texts and messages).
template <class E>
std::string known_names() {
  std::string out;
  for (const EnumName<E>& row : EnumNames<E>::rows)
    out += (out.empty() ? "" : ", ") + std::string(row.name);
  return out;
}

/// The enumerator named `name`, if any.
template <class E>
std::optional<E> find_enum(std::string_view name) {
  for (const EnumName<E>& row : EnumNames<E>::rows)
    if (name == row.name) return row.value;
  return std::nullopt;
}

/// The enumerator named `name`; else an error of `kind`: "`where`unknown NOUN 'name' (known: ...)".
template <class E>
E parse_enum(const std::string& name, const std::string& where = "",
             ErrorKind kind = ErrorKind::kUsage) {
  if (const auto value = find_enum<E>(name)) return *value;
  throw_error(kind, where + "unknown " + EnumNames<E>::noun + " '" + name +
                        "' (known: " + known_names<E>() + ")");
}

/// A comma-separated list of names ("obj,ply"): at least one, none empty, none twice; else an
/// error of `kind` starting with `where`.
template <class E>
std::vector<E> parse_enum_list(const std::string& text, const std::string& where = "",
                               ErrorKind kind = ErrorKind::kUsage) {
  const std::string noun = EnumNames<E>::noun;
  if (text.empty())
    throw_error(kind, where + "no " + noun + " given (known: " + known_names<E>() + ")");
  std::vector<E> out;
  for (std::size_t start = 0; start <= text.size();) {
    const std::size_t comma = std::min(text.find(',', start), text.size());
    const std::string name = text.substr(start, comma - start);
    start = comma + 1;
    const E value = parse_enum<E>(name, where, kind);
    for (const E seen : out)
      if (seen == value) throw_error(kind, where + noun + " '" + name + "' is listed twice");
    out.push_back(value);
  }
  return out;
}

}  // namespace sdog
