#pragma once
/// Numbers as people write them: no trailing zeros ("-25", "0.1", not
/// "-25.000000" or "0.1000000000000000055"), for the CLI and the viewer.

#include <string>

namespace impulse::client {

/// `value` rounded to at most `maxDecimals` decimals, trailing zeros and a
/// trailing point dropped, "-0" written "0"; "nan", "inf" and "-inf" as such.
std::string formatNumber(double value, int maxDecimals = 6);

/// The shortest text that reads back as exactly `value` (std::to_chars), for
/// output a program parses: "0.1", "-25", "1e-07".
std::string formatExact(double value);

}  // namespace impulse::client
