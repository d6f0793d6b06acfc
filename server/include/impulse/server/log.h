#pragma once
/// Server log lines on stderr (stdout carries only the "listening on" line).

#include <string_view>

namespace impulse::server {

void logLine(std::string_view message);

}  // namespace impulse::server
