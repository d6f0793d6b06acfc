// impulse-cli: drives impulse-server from a script (file or stdin), one
// command per line, and prints each reply as one JSON line on stdout.
// Exit status: 0 when every line succeeded, 1 when some line failed, 2 when
// the arguments or the connection failed.
#include <algorithm>
#include <condition_variable>
#include <cstdio>
#include <cstdlib>
#include <deque>
#include <fstream>
#include <iostream>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include <CLI/CLI.hpp>

#include "impulse/client/client.h"
#include "impulse/client/scene_file.h"
#include "report.h"
#include "script.h"

namespace {

using namespace impulse;
using Milliseconds = std::chrono::milliseconds;

// Commands in flight at once: well under the server's per-client queue caps.
constexpr std::size_t kMaxPipelined = 256;

// The --help footer: the script grammar, from the command table.
std::string scriptHelp() {
  std::string help = "Script commands, one per line ('#' starts a comment):\n";
  const std::string grammar = cli::scriptGrammar();
  for (std::size_t start = 0; start < grammar.size();) {
    const std::size_t end = grammar.find('\n', start) + 1;
    help.append("  ").append(grammar, start, end - start);
    start = end;
  }
  return help +
         "MATERIAL: solid, ice, wood, metal, rubber.\n"
         "--token defaults to the environment's IMPULSE_TOKEN; it is sent in Hello.\n"
         "Exit status: 0 every line succeeded, 1 some line failed, 2 arguments or connection "
         "failed.";
}

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

void print(const std::string& json) {
  std::fputs(json.c_str(), stdout);
  std::fputc('\n', stdout);
  std::fflush(stdout);
}

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

  std::size_t lineNumber = 0;
  std::string command = "connect";
  try {
    client::Client client(arguments.connect);
    std::size_t lastSnapshotBytes = 0;
    client.onSnapshot([&](const v1::Snapshot&, std::size_t bytes) { lastSnapshotBytes = bytes; });
    print(cli::welcomeReport(client.welcome()));

    LineSource lines(arguments.script.empty() ? nullptr : &file);
    int failures = 0;

    // Server commands are pipelined (replies come back in order, one tick
    // apart otherwise); local commands and parse errors first wait for every
    // earlier reply, so output stays in line order.
    struct Pending {
      std::size_t line;
      std::string command;
      std::uint64_t requestId;
      Milliseconds timeout;
      std::string file;  // `save`: where the scene goes
    };
    std::deque<Pending> pending;
    auto drainOne = [&] {
      const Pending next = pending.front();
      pending.pop_front();
      lineNumber = next.line;
      command = next.command;
      const auto reply = client.awaitReply(next.requestId, next.timeout);
      if (!reply) {
        throw client::ConnectionError("no reply within " + std::to_string(next.timeout.count()) +
                                      " ms");
      }
      failures += reply->has_command_result() && !reply->command_result().ok() ? 1 : 0;
      if (reply->has_scene_data()) {
        const std::string error = client::writeSceneFile(next.file, reply->scene_data().data());
        failures += error.empty() ? 0 : 1;
        print(cli::sceneSavedReport(next.line, next.command, next.file,
                                    reply->scene_data().data().size(), error));
        return;
      }
      print(cli::replyReport(next.line, next.command, *reply));
    };
    auto drainAll = [&] {
      while (!pending.empty()) drainOne();
    };

    std::size_t lineCount = 0;
    // Snapshot counts when the last command was sent and at the last
    // wait-snapshot report.
    std::uint64_t sentMark = client.mirror().snapshotsApplied();
    std::uint64_t reportedMark = sentMark;
    std::string line;
    while (true) {
      const auto status = lines.next(line, Milliseconds(20));
      if (status == LineSource::Status::End) break;
      if (status == LineSource::Status::Waiting) {
        drainAll();
        client.poll();
        continue;
      }
      ++lineCount;
      const auto parsed = cli::parseScriptLine(line);
      if (!parsed.error.empty()) {
        drainAll();
        print(cli::errorReport(lineCount, parsed.name, parsed.error));
        ++failures;
        continue;
      }
      if (!parsed.command) continue;
      const auto& name = parsed.command->name;
      switch (parsed.command->kind) {
        case cli::ScriptCommand::Kind::Server: {
          const auto& message = parsed.command->message;
          // A long Step takes its time on the server before the reply.
          const auto timeout = arguments.timeout +
                               Milliseconds(message.has_step() ? message.step().ticks() * 10 : 0);
          lineNumber = lineCount;
          command = name;
          sentMark = client.mirror().snapshotsApplied();
          pending.push_back({lineCount, name, client.send(message), timeout, parsed.command->file});
          if (pending.size() >= kMaxPipelined) drainOne();
          break;
        }
        case cli::ScriptCommand::Kind::Bodies:
          drainAll();
          lineNumber = lineCount;
          command = name;
          // The Pong comes after every snapshot the earlier commands caused.
          client.ping(arguments.timeout);
          print(cli::bodiesReport(lineCount, client.mirror()));
          break;
        case cli::ScriptCommand::Kind::WaitSnapshot: {
          drainAll();
          lineNumber = lineCount;
          command = name;
          // The newest snapshot that came after the last command was sent
          // (and was not reported yet); otherwise the next one to arrive.
          const bool fresh = client.mirror().snapshotsApplied() > std::max(sentMark, reportedMark);
          const auto snapshot =
              fresh ? client.lastSnapshot() : client.awaitSnapshot(arguments.timeout);
          if (!snapshot) {
            print(cli::errorReport(
                lineCount, name,
                "no snapshot within " + std::to_string(arguments.timeout.count()) + " ms"));
            ++failures;
            break;
          }
          reportedMark = client.mirror().snapshotsApplied();
          print(cli::snapshotReport(lineCount, *snapshot, lastSnapshotBytes));
          break;
        }
      }
    }
    drainAll();
    return failures == 0 ? 0 : 1;
  } catch (const client::ConnectionError& error) {
    print(cli::errorReport(lineNumber, command, std::string("connection: ") + error.what()));
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
  app.add_option("script", arguments.script, "script file; '-' or none: stdin")
      ->option_text("SCRIPT");
  app.footer(scriptHelp());
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    return app.exit(error) == 0 ? 0 : 2;
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
