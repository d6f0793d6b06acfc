#pragma once
// The script words that add force fields (docs/protocol.md, "Fields"), one per
// kind; rows of the command table (impulse/wire/command_table.h).

#include <optional>
#include <tuple>

#include "arguments.h"
#include "impulse.pb.h"

namespace impulse::cli {

// gravitation G
std::optional<std::tuple<double>> parseGravitation(Arguments& line);
// fluid DENSITY DRAG ANGULAR_DRAG CX CY X1 Y1 X2 Y2 X3 Y3 ...
std::optional<std::tuple<v1::FluidRegion>> parseFluid(Arguments& line);
// fan X Y DX DY SPEED RANGE SPREAD
std::optional<std::tuple<v1::Fan>> parseFan(Arguments& line);

}  // namespace impulse::cli
