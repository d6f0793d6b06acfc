// impulse-cli: drives impulse-server from a script (file or stdin), one
// command per line, and prints each reply as one JSON line on stdout.
// Exit status: 0 when every line succeeded, 1 when some line failed, 2 when
// the arguments or the connection failed.
#include <condition_variable>
#include <cstdio>
#include <cstdlib>
#include <deque>
#include <fstream>
#include <iostream>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

#include <CLI/CLI.hpp>

#include "help.h"
#include "impulse/client/client.h"
#include "report.h"
#include "script_runner.h"

namespace {

using namespace impulse;
using cli::Milliseconds;

// Script lines. A file is read directly; stdin is read on its own thread so
// the connection keeps being serviced (snapshots drained) while a person types.
class LineSource {
 public:
  enum class Status { Line, Waiting, End };

  explicit LineSource(std::istream* file) : file_(file) {
    if (file_ != nullptr) return;
    // The thread shares only this state, never the LineSource, so leaving it
    // blocked in getline at exit is harmless.
    thread_ = std::thread([state = state_] {
      std::string line;
      while (std::getline(std::cin, line)) {
        std::lock_guard lock(state->mutex);
        state->lines.push_back(std::move(line));
        state->ready.notify_one();
      }
      std::lock_guard lock(state->mutex);
      state->done = true;
      state->ready.notify_one();
    });
  }
  ~LineSource() {
    if (thread_.joinable()) thread_.detach();
  }

  Status next(std::string& line, Milliseconds wait) {
    if (file_ != nullptr) return std::getline(*file_, line) ? Status::Line : Status::End;
    std::unique_lock lock(state_->mutex);
    state_->ready.wait_for(lock, wait, [&] { return !state_->lines.empty() || state_->done; });
    if (!state_->lines.empty()) {
      line = std::move(state_->lines.front());
      state_->lines.pop_front();
      return Status::Line;
    }
    return state_->done ? Status::End : Status::Waiting;
  }

 private:
  struct State {
    std::mutex mutex;
    std::condition_variable ready;
    std::deque<std::string> lines;
    bool done = false;
  };
  std::istream* file_;
  std::shared_ptr<State> state_ = std::make_shared<State>();
  std::thread thread_;
};

struct Arguments {
  client::ConnectOptions connect;
  Milliseconds timeout{10000};
  std::string script;
};

int run(const Arguments& arguments) {
  std::ifstream file;
  if (!arguments.script.empty()) {
    file.open(arguments.script);
    if (!file) {
      std::fprintf(stderr, "impulse-cli: cannot open %s\n", arguments.script.c_str());
      return 2;
    }
  }
  std::optional<cli::ScriptRunner> runner;
  try {
    client::Client client(arguments.connect);
    cli::printReport(cli::welcomeReport(client.welcome()));
    runner.emplace(client, arguments.timeout);
    LineSource lines(arguments.script.empty() ? nullptr : &file);
    std::size_t lineCount = 0;
    std::string line;
    while (true) {
      const auto status = lines.next(line, Milliseconds(20));
      if (status == LineSource::Status::End) break;
      if (status == LineSource::Status::Waiting) {
        runner->idle();
        continue;
      }
      runner->feed({++lineCount, std::move(line)});
    }
    runner->finish();
    return runner->failures() == 0 ? 0 : 1;
  } catch (const client::ConnectionError& error) {
    const std::size_t lineNumber = runner ? runner->currentLine() : 0;
    const std::string command = runner ? runner->currentCommand() : "connect";
    cli::printReport(cli::errorReport(lineNumber, command, std::string("connection: ") + error.what()));
    return 2;
  }
}

}  // namespace

int main(int argc, char** argv) {
  Arguments arguments;
  arguments.connect.name = "impulse-cli";
  std::string connect = "127.0.0.1:7777";
  long timeoutMs = 10000;
  CLI::App app("Runs SCRIPT (or stdin) against impulse-server, one command per line, and "
               "prints one JSON object per line.",
               "impulse-cli");
  app.add_option("--connect", connect, "server, HOST:PORT (default 127.0.0.1:7777)")
      ->option_text("HOST:PORT");
  app.add_option("--timeout", timeoutMs, "wait at most this long for a reply, 1-3600000 (default 10000)")
      ->check(CLI::Range(1L, 3600000L))
      ->option_text("MS");
  if (const char* token = std::getenv("IMPULSE_TOKEN")) arguments.connect.token = token;
  app.add_option("--token", arguments.connect.token, "access token sent in Hello (see docs/server.md)")
      ->option_text("T");
  app.add_option("--room", arguments.connect.room,
                 "room to join, made on first join (default: the room \"default\")")
      ->option_text("NAME");
  std::vector<double> roomBounds;
  app.add_option("--room-bounds", roomBounds,
                 "world bounds of the room this connection makes, in metres (admin role; default: the "
                 "server's (-25, -25) to (50, 45))")
      ->expected(4)
      ->option_text("X1 Y1 X2 Y2");
  app.add_option("script", arguments.script, "script file; '-' or none: stdin")
      ->option_text("SCRIPT");
  app.footer(cli::scriptHelp());
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    return app.exit(error) == 0 ? 0 : 2;
  }
  if (roomBounds.size() == 4) {
    arguments.connect.roomBounds = client::Box{{roomBounds[0], roomBounds[1]}, {roomBounds[2], roomBounds[3]}};
  }
  const auto target = client::parseHostPort(connect);
  if (!target) {
    std::fprintf(stderr, "impulse-cli: --connect wants HOST:PORT, not '%s'\n", connect.c_str());
    return 2;
  }
  arguments.connect.host = target->first;
  arguments.connect.port = target->second;
  if (arguments.script == "-") arguments.script.clear();
  arguments.timeout = Milliseconds(timeoutMs);
  arguments.connect.timeout = arguments.timeout;
  return run(arguments);
}
