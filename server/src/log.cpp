#include "impulse/server/log.h"

#include <chrono>
#include <cstdio>

namespace impulse::server {

void logLine(std::string_view message) {
  using namespace std::chrono;
  const auto now = duration_cast<milliseconds>(system_clock::now().time_since_epoch()).count();
  std::fprintf(stderr, "[impulse-server %lld.%03lld] %.*s\n", static_cast<long long>(now / 1000),
               static_cast<long long>(now % 1000), static_cast<int>(message.size()),
               message.data());
}

}  // namespace impulse::server
