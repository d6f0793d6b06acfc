#pragma once
/// Server log lines on stderr (stdout carries only the "listening on" line).

#include <chrono>
#include <string>
#include <string_view>

namespace impulse::server {

/// "2026-11-25T19:31:23.456Z impulse-server MESSAGE": the time in ISO 8601
/// (UTC, milliseconds), numbers as people write them ("60 Hz", not
/// "60.000000 Hz").
std::string formatLogLine(std::chrono::system_clock::time_point at, std::string_view message);
void logLine(std::string_view message);

}  // namespace impulse::server
