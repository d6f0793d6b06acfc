#include "impulse/server/log.h"

#include <chrono>
#include <cstdio>
#include <ctime>
#include <string>

#include "impulse/wire/plain_numbers.h"

namespace impulse::server {

namespace {

// ISO 8601 in UTC to the millisecond: "2026-11-25T19:31:23.456Z", which a
// person reads and every log tool parses.
std::string isoTime(std::chrono::system_clock::time_point at) {
  using namespace std::chrono;
  const auto ms = duration_cast<milliseconds>(at.time_since_epoch()).count();
  const std::time_t seconds = static_cast<std::time_t>(ms / 1000);
  std::tm utc{};
  gmtime_r(&seconds, &utc);
  char text[32];
  const std::size_t length = std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%S", &utc);
  char millis[8];
  std::snprintf(millis, sizeof millis, ".%03lldZ", static_cast<long long>(ms % 1000));
  return std::string(text, length) + millis;
}

}  // namespace

std::string formatLogLine(std::chrono::system_clock::time_point at, std::string_view message) {
  return isoTime(at) + " impulse-server " + wire::plainNumbers(message);
}

void logLine(std::string_view message) {
  const std::string line = formatLogLine(std::chrono::system_clock::now(), message);
  std::fprintf(stderr, "%s\n", line.c_str());
}

}  // namespace impulse::server
