#include "solver/config/reference.h"

#include "base/text_format.h"
#include "solver/config/run_config_json.h"

namespace sdog {
namespace {

std::string value_text(OptionType type, const Bounds& bounds,
                       const std::vector<std::string>& choices) {
  switch (type) {
    case OptionType::kBoolean:
      return "true or false";
    case OptionType::kChoice:
      return "one of " + join(choices, ", ");
    case OptionType::kInteger:
      return "integer " + bounds.symbols();
    case OptionType::kReal:
      break;
  }
  return "number " + bounds.symbols();
}

std::string default_text(OptionType type, const std::optional<double>& v,
                         const std::vector<std::string>& choices, const std::string& unset) {
  if (!v) return unset;
  switch (type) {
    case OptionType::kBoolean:
      return *v != 0 ? "true" : "false";
    case OptionType::kChoice:
      return choices[static_cast<size_t>(*v)];
    case OptionType::kInteger:
    case OptionType::kReal:
      break;
  }
  return format_number(*v);
}

template <class S>
std::string table(const std::string& title, const OptionTable<S>& options, const S& defaults) {
  std::string out =
      "\n## " + title + "\n\n| key | value | default | meaning |\n|---|---|---|---|\n";
  for (const Option<S>& o : options)
    out += "| `" + o.key + "` | " + value_text(o.type, o.bounds, o.choices) + " | `" +
           default_text(o.type, o.get(defaults), o.choices, o.unset) + "` | " +
           markdown_cell(o.help) + " |\n";
  return out;
}

}  // namespace

std::string configuration_reference() {
  const RunConfig defaults;
  std::string out = table("Top level", run_option_table(), defaults);
  for_each_option_section(defaults, [&](const char* key, const auto& options, const auto& t) {
    out += table(std::string("`") + key + "`", t, options);
  });
  return out;
}

}  // namespace sdog
