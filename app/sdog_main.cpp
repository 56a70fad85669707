// sdog: command-line front end of Scalable DOGs. Exit codes: 0 success, 1 bad input or output
// (the message names the file and what to fix), 2 usage error, 3 internal error.
#include <CLI/CLI.hpp>
#include <iostream>

#include "app/blas_kernels.h"
#include "app/cli_common.h"
#include "app/commands.h"
#include "base/errors.h"

int main(int argc, char** argv) {
  sdog::use_avx2_blas_kernels(argv);
  CLI::App app;
  sdog::cli::Runner run;
  sdog::cli::register_sdog_commands(app, run, sdog::cli::command_line_text(argc, argv));
  try {
    if (const auto done = sdog::cli::parse_command_line(app, argc, argv)) return *done;
    run();
    return 0;
  } catch (const sdog::Error& e) {
    std::cerr << "sdog: " << e.what() << "\n";
    return sdog::exit_code(e.kind());
  } catch (const std::exception& e) {
    std::cerr << "sdog: internal error: " << e.what() << " (please report this with the input)\n";
    return 3;
  }
}
