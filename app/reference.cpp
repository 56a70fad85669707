#include "app/reference.h"

#include "app/commands.h"
#include "app/studio_options.h"
#include "base/text_format.h"

namespace sdog::cli {
namespace {

std::string option_names(const CLI::Option& o) {
  if (o.get_positional()) return "`" + o.get_name() + "`";
  std::vector<std::string> names;
  for (const auto& s : o.get_snames()) names.push_back("`-" + s + "`");
  for (const auto& l : o.get_lnames()) names.push_back("`--" + l + "`");
  return join(names, ", ");
}

std::string option_table(const CLI::App& app) {
  std::string out = "| option | value | default | meaning |\n|---|---|---|---|\n";
  for (const CLI::Option* o : app.get_options()) {
    if (o->get_lnames() == std::vector<std::string>{"help"}) continue;
    const bool flag = o->get_expected_min() == 0;
    const std::string value = flag ? "" : markdown_cell(o->get_type_name());
    const std::string fallback =
        o->get_default_str().empty() ? "" : "`" + markdown_cell(o->get_default_str()) + "`";
    out += "| " + option_names(*o) + " | " + value + " | " + fallback + " | " +
           markdown_cell(o->get_description()) + " |\n";
  }
  return out;
}

std::string section(const std::string& title, const CLI::App& app) {
  return "\n## `" + title + "`\n\n" + markdown_cell(app.get_description()) + "\n\n" +
         option_table(app);
}

}  // namespace

std::string command_line_reference() {
  CLI::App sdog;
  Runner run;
  register_sdog_commands(sdog, run, "sdog");
  std::string out;
  for (const CLI::App* command : sdog.get_subcommands({}))
    out += section("sdog " + command->get_name(), *command);
  CLI::App studio;
  StudioArgs args;
  add_studio_options(studio, args);
  return out + section("sdog-studio", studio);
}

}  // namespace sdog::cli
