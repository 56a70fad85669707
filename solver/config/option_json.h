#pragma once
// Options tables (base/option_table.h) as JSON objects: reading a configuration object with
// errors that name the file and the JSON path, and writing the values back (run.json).
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "base/json_field.h"
#include "base/option_table.h"

namespace sdog {

/// The keys of a table.
template <class S>
std::vector<std::string> option_keys(const OptionTable<S>& table) {
  std::vector<std::string> keys;
  for (const Option<S>& o : table) keys.push_back(o.key);
  return keys;
}

/// The value of one option from JSON, checked against its type and bounds.
double read_option_value(const Field& f, OptionType type, const Bounds& bounds,
                         const std::vector<std::string>& choices);
/// One option's value as JSON: a number, an integer, true/false, a choice's name, or the `unset`
/// text of an optional value that is not set.
nlohmann::json option_value_json(OptionType type, const std::optional<double>& value,
                                 const std::vector<std::string>& choices, const std::string& unset);

/// Sets every option of the table that `f` (an object) holds. An optional value may also be
/// given as null or as its `unset` text (as options_json writes it): it is then left unset.
template <class S>
void read_options(const Field& f, const OptionTable<S>& table, S& s) {
  for (const Option<S>& o : table) {
    if (!f.has(o.key.c_str())) continue;
    const Field value = f[o.key.c_str()];
    if (!o.unset.empty() && (value.value().is_null() || value.value() == o.unset))
      o.set(s, std::nullopt);
    else
      o.set(s, read_option_value(value, o.type, o.bounds, o.choices));
  }
}

/// Every option of the table as one JSON object.
template <class S>
nlohmann::json options_json(const OptionTable<S>& table, const S& s) {
  nlohmann::json j = nlohmann::json::object();
  for (const Option<S>& o : table)
    j[o.key] = option_value_json(o.type, o.get(s), o.choices, o.unset);
  return j;
}

}  // namespace sdog
