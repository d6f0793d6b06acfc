#include "server_process.h"

#include <arpa/inet.h>
#include <fcntl.h>
#include <gtest/gtest.h>
#include <netinet/in.h>
#include <poll.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <exception>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <thread>

namespace impulse::net_test {

namespace {

using Clock = std::chrono::steady_clock;

int remainingMs(Clock::time_point deadline) {
  const auto left = std::chrono::duration_cast<milliseconds>(deadline - Clock::now()).count();
  return left < 0 ? 0 : int(left);
}

std::string tempPath(const char* pattern) {
  std::string path = std::string("/tmp/") + pattern;
  const int fd = mkstemps(path.data(), 4);
  if (fd < 0) throw std::runtime_error("mkstemps failed");
  close(fd);
  return path;
}

}  // namespace

// ----------------------------------------------------------- ServerProcess

ServerProcess::ServerProcess(std::vector<std::string> args) {
  logPath_ = tempPath("impulse-server-XXXXXX.log");
  int out[2];
  if (pipe2(out, O_CLOEXEC) != 0) throw std::runtime_error("pipe failed");
  std::vector<std::string> argv = {IMPULSE_SERVER_BINARY, "--port", "0"};
  argv.insert(argv.end(), args.begin(), args.end());

  pid_ = fork();
  if (pid_ < 0) throw std::runtime_error("fork failed");
  if (pid_ == 0) {
    // The server dies with the test process, whatever happens to it.
    prctl(PR_SET_PDEATHSIG, SIGKILL);
    // Under AddressSanitizer freed memory sits in a quarantine (256 MiB by
    // default) that would swamp the memory-bound checks; keep it small.
    // Other builds ignore the variable.
    std::string asan = "quarantine_size_mb=4";
    if (const char* existing = getenv("ASAN_OPTIONS")) asan = std::string(existing) + ":" + asan;
    setenv("ASAN_OPTIONS", asan.c_str(), 1);
    const int log = open(logPath_.c_str(), O_WRONLY | O_TRUNC);
    dup2(out[1], STDOUT_FILENO);
    dup2(log, STDERR_FILENO);
    std::vector<char*> pointers;
    for (auto& arg : argv) pointers.push_back(arg.data());
    pointers.push_back(nullptr);
    execv(pointers[0], pointers.data());
    _exit(127);
  }
  close(out[1]);

  // The first stdout line carries the port.
  const auto deadline = Clock::now() + std::chrono::seconds(20);
  std::string line;
  char c = 0;
  while (line.empty() || line.back() != '\n') {
    pollfd pfd{out[0], POLLIN, 0};
    if (poll(&pfd, 1, remainingMs(deadline)) <= 0 || read(out[0], &c, 1) != 1) break;
    line += c;
  }
  // Keep the pipe open: a write to a closed stdout would kill the server.
  if (line.empty() || line.back() != '\n') {
    stop();
    throw std::runtime_error("impulse-server did not print its port; log:\n" + log());
  }
  line.pop_back();
  firstLine_ = line;
  port_ = std::uint16_t(std::stoi(line.substr(line.rfind(':') + 1)));
}

ServerProcess::~ServerProcess() {
  stop();
  // Also while an exception from the test body unwinds (gtest records that
  // failure only afterwards).
  if (::testing::Test::HasFailure() || std::uncaught_exceptions() > 0) {
    std::fprintf(stderr, "---- impulse-server log ----\n%s----\n", log().c_str());
  }
  unlink(logPath_.c_str());
}

int ServerProcess::stop(milliseconds timeout) {
  if (pid_ <= 0) return -1;
  kill(pid_, SIGTERM);
  const auto deadline = Clock::now() + timeout;
  int status = 0;
  while (true) {
    const pid_t done = waitpid(pid_, &status, WNOHANG);
    if (done == pid_) break;
    if (Clock::now() >= deadline) {
      kill(pid_, SIGKILL);
      waitpid(pid_, &status, 0);
      pid_ = -1;
      return -1;
    }
    std::this_thread::sleep_for(milliseconds(5));
  }
  pid_ = -1;
  if (WIFEXITED(status)) return WEXITSTATUS(status);
  return 128 + WTERMSIG(status);
}

long ServerProcess::residentKb() const {
  std::ifstream status("/proc/" + std::to_string(pid_) + "/status");
  std::string key;
  while (status >> key) {
    if (key == "VmRSS:") {
      long kb = 0;
      status >> kb;
      return kb;
    }
  }
  return -1;
}

std::string ServerProcess::log() const {
  std::ifstream file(logPath_);
  std::stringstream text;
  text << file.rdbuf();
  return text.str();
}

// ----------------------------------------------------------- RawConnection

RawConnection::RawConnection(std::uint16_t port, int receiveBuffer) {
  fd_ = socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
  if (fd_ < 0) throw std::runtime_error("socket failed");
  if (receiveBuffer > 0) {
    setsockopt(fd_, SOL_SOCKET, SO_RCVBUF, &receiveBuffer, sizeof receiveBuffer);
  }
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_port = htons(port);
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  if (connect(fd_, reinterpret_cast<sockaddr*>(&address), sizeof address) != 0) {
    throw std::runtime_error("connect failed");
  }
}

RawConnection::~RawConnection() {
  if (fd_ >= 0) close(fd_);
}

void RawConnection::send(const std::string& bytes) {
  // Gives up after a few seconds without progress: a server that stopped
  // reading must not hang the test.
  std::size_t sent = 0;
  while (sent < bytes.size()) {
    pollfd pfd{fd_, POLLOUT, 0};
    if (poll(&pfd, 1, 5000) <= 0) return;
    const ssize_t n =
        ::send(fd_, bytes.data() + sent, bytes.size() - sent, MSG_NOSIGNAL | MSG_DONTWAIT);
    if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK)) continue;
    if (n <= 0) return;  // closed by the server: the tests check replies
    sent += std::size_t(n);
  }
}

void RawConnection::sendMessage(const v1::ClientMessage& message) {
  send(wire::encodeFrame(message));
}

void RawConnection::sendHello(std::uint32_t version, bool wantSnapshots) {
  v1::ClientMessage hello;
  hello.mutable_hello()->set_protocol_version(version);
  hello.mutable_hello()->set_client_name("raw-test");
  hello.mutable_hello()->set_want_snapshots(wantSnapshots);
  sendMessage(hello);
}

void RawConnection::shutdownWrite() { shutdown(fd_, SHUT_WR); }

std::optional<v1::ServerMessage> RawConnection::receive(milliseconds timeout) {
  const auto deadline = Clock::now() + timeout;
  while (true) {
    while (!pending_.empty()) {
      const auto result = reader_.feed(std::span<const char>(pending_.data(), pending_.size()));
      pending_.erase(0, result.consumed);
      if (result.status == wire::FrameReader::Status::Error) return std::nullopt;
      if (result.status == wire::FrameReader::Status::Frame) {
        v1::ServerMessage message;
        if (!wire::parseFrame(reader_.frame(), message)) return std::nullopt;
        return message;
      }
    }
    pollfd pfd{fd_, POLLIN, 0};
    if (poll(&pfd, 1, remainingMs(deadline)) <= 0) return std::nullopt;
    char buffer[65536];
    const ssize_t n = recv(fd_, buffer, sizeof buffer, 0);
    if (n <= 0) return std::nullopt;
    pending_.append(buffer, std::size_t(n));
  }
}

std::optional<std::string> RawConnection::receiveError(milliseconds timeout) {
  const auto deadline = Clock::now() + timeout;
  while (auto message = receive(milliseconds(remainingMs(deadline)))) {
    if (message->has_error()) return message->error().message();
  }
  return std::nullopt;
}

bool RawConnection::waitClosed(milliseconds timeout) {
  const auto deadline = Clock::now() + timeout;
  while (true) {
    pollfd pfd{fd_, POLLIN, 0};
    if (poll(&pfd, 1, remainingMs(deadline)) <= 0) return false;
    char buffer[65536];
    const ssize_t n = recv(fd_, buffer, sizeof buffer, 0);
    if (n == 0 || (n < 0 && errno == ECONNRESET)) return true;
    if (n < 0) return false;
  }
}

// ------------------------------------------------------------------- CLI

CliRun runCli(std::uint16_t port, const std::string& script, bool viaStdin,
              const std::string& extraArguments) {
  const std::string path = tempPath("impulse-cli-XXXXXX.txt");
  {
    std::ofstream file(path);
    file << script;
  }
  const std::string command = std::string(IMPULSE_CLI_BINARY) +
                              " --connect 127.0.0.1:" + std::to_string(port) + " " +
                              extraArguments + (viaStdin ? " < " : " ") + path;
  CliRun run;
  FILE* pipe = popen(command.c_str(), "r");
  if (pipe == nullptr) return run;
  std::string line;
  char buffer[65536];
  while (fgets(buffer, sizeof buffer, pipe) != nullptr) {
    line += buffer;
    if (!line.empty() && line.back() == '\n') {
      line.pop_back();
      run.lines.push_back(line);
      line.clear();
    }
  }
  const int status = pclose(pipe);
  run.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  unlink(path.c_str());
  return run;
}

}  // namespace impulse::net_test
