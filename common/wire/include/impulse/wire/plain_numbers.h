#pragma once
/// Numbers in messages as people write them. std::to_string(double) gives
/// six fixed decimals ("60.000000", "-25.000000", "0.100000"); server errors
/// and log lines are built with it. plainNumbers() drops the trailing zeros
/// of every such number in a text ("60", "-25", "0.1"; "-0.000000" is "0"),
/// leaving every other character as it is. Used by the server's log and by
/// impulse-cli for the server's errors.

#include <string>
#include <string_view>

namespace impulse::wire {

std::string plainNumbers(std::string_view text);

}  // namespace impulse::wire
