#pragma once
// Runs impulse-cli script lines against a connected server and prints one
// JSON line per command, in line order.
//
// Server commands are pipelined: a line is sent without waiting for the
// replies before it, and replies are printed as they are collected. A line
// that needs what earlier lines did waits for their replies first: local
// words (bodies, wait-snapshot), a `load` (its file may be one an earlier
// `save` writes), a line that reads a variable still waiting for its id,
// a parse error (so output stays in line order). `repeat N [$I] { ... }`
// blocks are collected up to their closing brace, then run N times.

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <string>
#include <vector>

#include "impulse/client/client.h"
#include "script.h"
#include "variables.h"

namespace impulse::cli {

using Milliseconds = std::chrono::milliseconds;

/// A script line and its number in the script (from 1).
struct SourceLine {
  std::size_t number = 0;
  std::string text;
};

class ScriptRunner {
 public:
  /// `client` is connected; `timeout` is the wait for one reply.
  ScriptRunner(client::Client& client, Milliseconds timeout);

  /// The next line of the script.
  void feed(SourceLine line);
  /// No line came for a while (a person typing): prints what has arrived.
  void idle();
  /// End of the script: reports an unclosed block, waits for every reply.
  void finish();
  int failures() const { return failures_; }
  /// The line and command running when the connection failed.
  std::size_t currentLine() const { return currentLine_; }
  const std::string& currentCommand() const { return currentCommand_; }

 private:
  struct Pending {
    SourceLine line;
    std::string command;
    std::uint64_t requestId = 0;
    Milliseconds timeout{};
    std::string file;      // `save`: where the scene goes
    std::string variable;  // `$name = ...`: takes the reply's id
  };

  void runLines(const std::vector<SourceLine>& lines, std::size_t begin, std::size_t end);
  void runRepeat(const std::vector<SourceLine>& lines, std::size_t header, std::size_t close);
  void runLine(const SourceLine& line);
  void runCommand(const SourceLine& line, const std::string& variable, ScriptCommand command);
  /// The room's tick as the client last saw it: the newest snapshot's, or
  /// the Welcome's without snapshots (what `at +N` counts from).
  std::uint64_t lastSeenTick() const;
  void runServerCommand(const SourceLine& line, const std::string& variable,
                        ScriptCommand command);
  void runLongStep(const SourceLine& line, const ScriptCommand& command);
  bool readSceneFile(const SourceLine& line, ScriptCommand& command);
  void runBodies(const SourceLine& line, const std::string& name);
  void runWaitSnapshot(const SourceLine& line, const std::string& name);
  /// `text` with its variables' values, waiting for replies when a
  /// variable needs one; nothing (reported under `command`) when a variable
  /// has no value.
  std::optional<std::string> substituted(const SourceLine& line, std::string_view command,
                                         std::string_view text);

  void drainOne();
  void drainAll();
  void fail(const SourceLine& line, std::string_view command, std::string_view problem);
  void setCurrent(std::size_t line, const std::string& command);
  /// Timeout for a reply to `message` (a Step takes its time on the server).
  Milliseconds replyTimeout(const v1::ClientMessage& message) const;

  client::Client& client_;
  Milliseconds timeout_;
  Variables variables_;
  std::deque<Pending> pending_;
  int failures_ = 0;
  std::size_t currentLine_ = 0;
  std::string currentCommand_ = "connect";
  std::size_t lastSnapshotBytes_ = 0;
  // Snapshot counts when the last command was sent and at the last
  // wait-snapshot report.
  std::uint64_t sentMark_ = 0;
  std::uint64_t reportedMark_ = 0;
  // A top-level `repeat` being collected: its lines, header first, and how
  // many blocks are open.
  std::vector<SourceLine> block_;
  int openBlocks_ = 0;
};

}  // namespace impulse::cli
