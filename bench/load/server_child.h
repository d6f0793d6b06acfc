#pragma once
// impulse-server as a child process of the load bench: started on a free
// loopback port, its CPU time read from /proc, stopped with SIGTERM.

#include <sys/types.h>

#include <cstdint>
#include <string>
#include <vector>

namespace load {

class ServerChild {
 public:
  /// Starts `binary --port 0 arguments...` and reads its "listening on" line;
  /// throws std::runtime_error when it does not start.
  ServerChild(const std::string& binary, const std::vector<std::string>& arguments);
  ~ServerChild();
  ServerChild(const ServerChild&) = delete;
  ServerChild& operator=(const ServerChild&) = delete;

  std::uint16_t port() const { return port_; }
  /// User + system CPU seconds the server has used so far.
  double cpuSeconds() const;

 private:
  pid_t pid_ = -1;
  std::uint16_t port_ = 0;
};

}  // namespace load
