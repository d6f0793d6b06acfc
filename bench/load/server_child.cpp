#include "server_child.h"

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace load {

ServerChild::ServerChild(const std::string& binary, const std::vector<std::string>& arguments) {
  int out[2];
  if (pipe(out) != 0) throw std::runtime_error("pipe failed");
  pid_ = fork();
  if (pid_ < 0) throw std::runtime_error("fork failed");
  if (pid_ == 0) {
    dup2(out[1], STDOUT_FILENO);
    close(out[0]);
    close(out[1]);
    std::vector<std::string> words = {binary, "--port", "0"};
    words.insert(words.end(), arguments.begin(), arguments.end());
    std::vector<char*> argv;
    for (auto& word : words) argv.push_back(word.data());
    argv.push_back(nullptr);
    execv(binary.c_str(), argv.data());
    _exit(127);
  }
  close(out[1]);
  FILE* stream = fdopen(out[0], "r");
  char line[256] = {};
  const bool gotLine = stream != nullptr && fgets(line, sizeof line, stream) != nullptr;
  if (stream != nullptr) fclose(stream);
  // "listening on ADDR:PORT": the port follows the last colon.
  const std::string text = gotLine ? line : "";
  const auto colon = text.rfind(':');
  if (!text.starts_with("listening on ") || colon == std::string::npos) {
    throw std::runtime_error("impulse-server did not start (" + binary + ")");
  }
  port_ = std::uint16_t(std::stoi(text.substr(colon + 1)));
}

ServerChild::~ServerChild() {
  if (pid_ <= 0) return;
  kill(pid_, SIGTERM);
  int status = 0;
  waitpid(pid_, &status, 0);
}

double ServerChild::cpuSeconds() const {
  // /proc/PID/stat: fields 14 and 15 are utime and stime in clock ticks;
  // the command name (field 2) is in parentheses and may hold spaces.
  std::ifstream file("/proc/" + std::to_string(pid_) + "/stat");
  std::string text((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  const auto close = text.rfind(')');
  if (close == std::string::npos) return 0;
  std::istringstream fields(text.substr(close + 2));
  std::string field;
  unsigned long long utime = 0, stime = 0;
  for (int index = 3; fields >> field; ++index) {
    if (index == 14) utime = std::stoull(field);
    if (index == 15) {
      stime = std::stoull(field);
      break;
    }
  }
  return double(utime + stime) / double(sysconf(_SC_CLK_TCK));
}

}  // namespace load
