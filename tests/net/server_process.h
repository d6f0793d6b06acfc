#pragma once
// Test harness: the real impulse-server started on a free loopback port, raw
// sockets for malformed input, and impulse-cli runs.

#include <sys/types.h>

#include <chrono>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "impulse.pb.h"
#include "impulse/wire/framing.h"

namespace impulse::net_test {

using std::chrono::milliseconds;

/// impulse-server --port 0 [args]; stopped with SIGTERM when destroyed.
class ServerProcess {
 public:
  explicit ServerProcess(std::vector<std::string> args = {});
  ~ServerProcess();
  ServerProcess(const ServerProcess&) = delete;
  ServerProcess& operator=(const ServerProcess&) = delete;

  std::uint16_t port() const { return port_; }
  pid_t pid() const { return pid_; }
  /// The exact first stdout line.
  const std::string& firstLine() const { return firstLine_; }
  /// SIGTERM, then waits; the exit status (-1 if it had to be killed).
  int stop(milliseconds timeout = milliseconds(5000));
  /// Resident memory of the server, KiB.
  long residentKb() const;
  /// Everything the server logged on stderr so far.
  std::string log() const;

 private:
  pid_t pid_ = -1;
  std::uint16_t port_ = 0;
  std::string firstLine_;
  std::string logPath_;
};

/// A plain blocking TCP connection for sending arbitrary bytes.
class RawConnection {
 public:
  /// `receiveBuffer` > 0 shrinks SO_RCVBUF before connecting.
  explicit RawConnection(std::uint16_t port, int receiveBuffer = 0);
  ~RawConnection();
  RawConnection(const RawConnection&) = delete;
  RawConnection& operator=(const RawConnection&) = delete;

  void send(const std::string& bytes);
  void sendMessage(const v1::ClientMessage& message);
  void sendHello(std::uint32_t version = 1, bool wantSnapshots = false);
  /// Half-close: the server sees end of stream.
  void shutdownWrite();
  /// The next server message, or nothing on timeout or close.
  std::optional<v1::ServerMessage> receive(milliseconds timeout);
  /// The first Error among the next messages (skipping others).
  std::optional<std::string> receiveError(milliseconds timeout);
  /// True once the server closed the connection (reads return 0 or reset).
  bool waitClosed(milliseconds timeout);

 private:
  int fd_ = -1;
  wire::FrameReader reader_{std::size_t(256) << 20};
  std::string pending_;
};

struct CliRun {
  int exitCode = -1;
  std::vector<std::string> lines;
};

/// Runs impulse-cli --connect 127.0.0.1:PORT [extraArguments] on `script`
/// (written to a file, or fed on stdin).
CliRun runCli(std::uint16_t port, const std::string& script, bool viaStdin = false,
              const std::string& extraArguments = "");

}  // namespace impulse::net_test
