#pragma once
// impulse-cli --help's footer, written from the tables the CLI already
// uses: the script grammar (script.h), the materials (impulse/material.h)
// and the shape limits (impulse/shape.h, impulse/constants.h), so it lists
// what the CLI takes and never a stale copy.

#include <string>

namespace impulse::cli {

std::string scriptHelp();

}  // namespace impulse::cli
