// sdog-reference: prints the generated part of a reference page (`make reference-docs` writes it
// into docs/reference/): `sdog-reference command-line` or `sdog-reference configuration`.
#include <iostream>
#include <string>

#include "app/reference.h"
#include "solver/config/reference.h"

int main(int argc, char** argv) {
  const std::string page = argc == 2 ? argv[1] : "";
  if (page == "command-line") {
    std::cout << sdog::cli::command_line_reference();
  } else if (page == "configuration") {
    std::cout << sdog::configuration_reference();
  } else {
    std::cerr << "usage: sdog-reference command-line|configuration\n";
    return 2;
  }
  return 0;
}
