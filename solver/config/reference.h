#pragma once
// The configuration reference (docs/reference/configuration.md) rendered from the option tables,
// so that the documentation lists exactly the keys, defaults and bounds the program uses.
#include <string>

namespace sdog {

/// Markdown: one table per object of the configuration (its top level, weights, solver,
/// patch_solver, coarse, twolevel, admm) with every key, its value, default and meaning.
std::string configuration_reference();

}  // namespace sdog
