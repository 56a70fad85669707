#include "solver/config/option_json.h"

#include <algorithm>

namespace sdog {
namespace {

// Integers in configurations stay far below int's range.
constexpr long long kLargestInteger = 100000000;

}  // namespace

double read_option_value(const Field& f, OptionType type, const Bounds& bounds,
                         const std::vector<std::string>& choices) {
  switch (type) {
    case OptionType::kBoolean:
      return f.boolean() ? 1 : 0;
    case OptionType::kChoice: {
      const std::string text = f.text();
      const auto it = std::find(choices.begin(), choices.end(), text);
      if (it == choices.end())
        f.fail("expected one of " + join(choices, ", ") + ", got \"" + text + "\"");
      return static_cast<double>(it - choices.begin());
    }
    case OptionType::kInteger: {
      if (!f.value().is_number_integer()) f.fail("expected an integer");
      const long long i = f.value().get<long long>();
      if (!bounds.contains(static_cast<double>(i)) || i > kLargestInteger)
        f.fail("expected an integer " + bounds.symbols() + ", got " + std::to_string(i));
      return static_cast<double>(i);
    }
    case OptionType::kReal:
      break;
  }
  const double d = f.number();
  if (!bounds.contains(d))
    f.fail("expected a number " + bounds.symbols() + ", got " + format_number(d));
  return d;
}

nlohmann::json option_value_json(OptionType type, const std::optional<double>& value,
                                 const std::vector<std::string>& choices,
                                 const std::string& unset) {
  if (!value) return unset;
  switch (type) {
    case OptionType::kBoolean:
      return *value != 0;
    case OptionType::kChoice:
      return choices[static_cast<size_t>(*value)];
    case OptionType::kInteger:
      return static_cast<int>(*value);
    case OptionType::kReal:
      break;
  }
  return *value;
}

}  // namespace sdog
