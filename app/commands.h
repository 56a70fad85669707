#pragma once
// The sdog subcommands. Each registers its options on the app and, when chosen, stores its body in
// `run` (called after parsing; library exceptions propagate to main, which maps them to exit
// codes).
#include <CLI/CLI.hpp>
#include <functional>
#include <optional>
#include <string>

namespace sdog::cli {

using Runner = std::function<void()>;

void register_mesh_command(CLI::App& app, Runner& run);
void register_render_command(CLI::App& app, Runner& run);
void register_run_command(CLI::App& app, Runner& run);
void register_bench_command(CLI::App& app, Runner& run);
/// `command_line`: the whole command line as typed, recorded in compare.json.
void register_compare_command(CLI::App& app, Runner& run, const std::string& command_line);

/// The sdog application: its description, --version and every subcommand above.
void register_sdog_commands(CLI::App& app, Runner& run, const std::string& command_line);

/// Parses the command line. --help and --version print and give the exit code to end with (0);
/// an unknown command or options that cannot be parsed are a UsageError. Nothing: go on and run.
std::optional<int> parse_command_line(CLI::App& app, int argc, char** argv);

}  // namespace sdog::cli
