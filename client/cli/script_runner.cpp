#include "script_runner.h"

#include <algorithm>
#include <charconv>
#include <cstdio>

#include "impulse/client/commands.h"
#include "impulse/client/scene_file.h"
#include "impulse/wire/parse_number.h"
#include "impulse/wire/scene_text.h"
#include "report.h"

namespace impulse::cli {

namespace {

// Commands in flight at once: well under the server's per-client queue caps.
constexpr std::size_t kMaxPipelined = 256;

// The id a reply names (body, joint or field), 0 when none.
std::uint32_t replyId(const v1::ServerMessage& reply) {
  if (!reply.has_command_result()) return 0;
  const auto& result = reply.command_result();
  return std::max({result.body_id(), result.joint_id(), result.field_id()});
}

bool failed(const v1::ServerMessage& reply) {
  return reply.has_command_result() && !reply.command_result().ok();
}

// Commands whose reply names what they made: what `$name = COMMAND` keeps.
bool repliesWithId(const v1::ClientMessage& message) {
  return message.has_spawn_circle() || message.has_spawn_polygon() ||
         message.has_create_joint() || message.has_add_field();
}

// A line's code: before its comment, without the blanks around it.
std::string_view codeOf(std::string_view text) {
  constexpr std::string_view kBlanks = " \t\r";
  const auto code = text.substr(0, text.find('#'));
  const auto begin = code.find_first_not_of(kBlanks);
  if (begin == std::string_view::npos) return {};
  return code.substr(begin, code.find_last_not_of(kBlanks) + 1 - begin);
}

// The first word of a line's code: the command a report names.
std::string firstWord(std::string_view text) {
  const auto code = codeOf(text);
  return std::string(code.substr(0, code.find_first_of(" \t")));
}

// The shortest text that reads back as `value`.
std::string numberText(double value) {
  char text[32];
  const auto end = std::to_chars(text, text + sizeof text, value).ptr;
  return std::string(text, end);
}

// The value of a line's code when it is a number, or two numbers with
// + - * or / between them (what `$x = $x + 1.5` needs); nothing otherwise.
std::optional<std::string> numberValue(std::string_view text) {
  const auto code = codeOf(text);
  if (wire::parseNumber<double>(code)) return std::string(code);
  const auto first = code.find(' ');
  const auto last = code.rfind(' ');
  if (first == std::string_view::npos || last != first + 2) return std::nullopt;
  const auto a = wire::parseNumber<double>(code.substr(0, first));
  const auto b = wire::parseNumber<double>(code.substr(last + 1));
  if (!a || !b) return std::nullopt;
  switch (code[first + 1]) {
    case '+': return numberText(*a + *b);
    case '-': return numberText(*a - *b);
    case '*': return numberText(*a * *b);
    case '/': return numberText(*a / *b);
    default: return std::nullopt;
  }
}

}  // namespace

ScriptRunner::ScriptRunner(client::Client& client, Milliseconds timeout)
    : client_(client), timeout_(timeout) {
  client_.onSnapshot([this](const v1::Snapshot&, std::size_t bytes) { lastSnapshotBytes_ = bytes; });
  client_.onEvents([](const v1::Events& events) { printReport(eventsReport(events)); });
  sentMark_ = reportedMark_ = client_.mirror().snapshotsApplied();
}

void ScriptRunner::feed(SourceLine line) {
  const LineShape shape = lineShape(line.text);
  if (openBlocks_ == 0) {
    if (shape == LineShape::ClosesBlock) return fail(line, "}", "} without a repeat before it");
    if (shape == LineShape::Plain) return runLine(line);
  }
  openBlocks_ += shape == LineShape::OpensBlock ? 1 : shape == LineShape::ClosesBlock ? -1 : 0;
  block_.push_back(std::move(line));
  if (openBlocks_ > 0) return;
  const std::vector<SourceLine> block = std::exchange(block_, {});
  runRepeat(block, 0, block.size() - 1);
}

void ScriptRunner::idle() {
  drainAll();
  client_.poll();
}

void ScriptRunner::finish() {
  if (openBlocks_ > 0) {
    fail(block_.front(), "repeat", "no } closes this repeat, so it did not run");
    block_.clear();
    openBlocks_ = 0;
  }
  drainAll();
}

void ScriptRunner::runLines(const std::vector<SourceLine>& lines, std::size_t begin,
                            std::size_t end) {
  for (std::size_t i = begin; i < end; ++i) {
    if (lineShape(lines[i].text) != LineShape::OpensBlock) {
      runLine(lines[i]);
      continue;
    }
    // Blocks were balanced when collected: the matching } is there.
    std::size_t close = i + 1;
    for (int depth = 1; depth > 0; ++close) {
      const LineShape shape = lineShape(lines[close].text);
      depth += shape == LineShape::OpensBlock ? 1 : shape == LineShape::ClosesBlock ? -1 : 0;
    }
    runRepeat(lines, i, close - 1);
    i = close - 1;
  }
}

void ScriptRunner::runRepeat(const std::vector<SourceLine>& lines, std::size_t header,
                             std::size_t close) {
  const SourceLine& line = lines[header];
  const RepeatWords words = parseRepeat(line.text);
  if (!words.error.empty()) return fail(line, "repeat", words.error);
  const auto count = substituted(line, "repeat", words.count);
  if (!count) return;
  std::string error;
  const auto times = repeatCount(*count, error);
  if (!times) return fail(line, "repeat", error);
  for (long long pass = 1; pass <= *times; ++pass) {
    if (!words.counter.empty()) variables_.set(words.counter, std::to_string(pass));
    runLines(lines, header + 1, close);
  }
}

void ScriptRunner::runLine(const SourceLine& line) {
  const auto assignment = splitAssignment(line.text);
  const std::string_view text = assignment ? assignment->command : std::string_view(line.text);
  const std::string name = firstWord(text);
  const auto code = substituted(line, name, text);
  if (assignment && !code) return variables_.fail(assignment->variable, line.number);
  if (!code) return;
  if (assignment) {
    if (auto number = numberValue(*code)) return variables_.set(assignment->variable, *number);
  }
  ParsedLine parsed = parseScriptLine(*code);
  if (assignment && !parsed.command) variables_.fail(assignment->variable, line.number);
  if (!parsed.error.empty()) return fail(line, name, parsed.error);
  if (!parsed.command) {
    if (assignment) fail(line, "$" + assignment->variable, "nothing after '='");
    return;
  }
  runCommand(line, assignment ? assignment->variable : std::string(), std::move(*parsed.command));
}

std::optional<std::string> ScriptRunner::substituted(const SourceLine& line,
                                                     std::string_view command,
                                                     std::string_view text) {
  auto result = variables_.substitute(text);
  if (result.waiting) {
    drainAll();
    result = variables_.substitute(text);
  }
  if (!result.error.empty()) {
    fail(line, command, result.error);
    return std::nullopt;
  }
  return std::move(result.text);
}

void ScriptRunner::runCommand(const SourceLine& line, const std::string& variable,
                              ScriptCommand command) {
  if (!variable.empty() &&
      (command.kind != ScriptCommand::Kind::Server || !repliesWithId(command.message))) {
    variables_.fail(variable, line.number);
    return fail(line, command.name,
                "$" + variable + " = " + command.name +
                    ": its reply has no id (circle, polygon, the joint and field words have one)");
  }
  switch (command.kind) {
    case ScriptCommand::Kind::Server: return runServerCommand(line, variable, std::move(command));
    case ScriptCommand::Kind::Bodies: return runBodies(line, command.name);
    case ScriptCommand::Kind::WaitSnapshot: return runWaitSnapshot(line, command.name);
  }
}

std::uint64_t ScriptRunner::lastSeenTick() const {
  return client_.mirror().snapshotsApplied() > 0 ? client_.mirror().tick() : client_.welcome().tick();
}

void ScriptRunner::runServerCommand(const SourceLine& line, const std::string& variable,
                                    ScriptCommand command) {
  const std::uint32_t maxTicks = client_.welcome().max_step_ticks();
  if (command.message.has_step() && maxTicks > 0 && command.message.step().ticks() > maxTicks) {
    return runLongStep(line, command);
  }
  if (command.message.has_load_scene() && !readSceneFile(line, command)) return;
  setCurrent(line.number, command.name);
  if (command.ticksAhead) command.message.set_for_tick(lastSeenTick() + *command.ticksAhead);
  sentMark_ = client_.mirror().snapshotsApplied();
  const Milliseconds timeout = replyTimeout(command.message);
  const std::uint64_t id = client_.send(std::move(command.message));
  if (!variable.empty()) variables_.await(variable, line.number);
  pending_.push_back({line, command.name, id, timeout, command.file, variable});
  if (pending_.size() >= kMaxPipelined) drainOne();
}

// The server steps at most Welcome.max_step_ticks per Step: a longer one
// goes as pieces, one after another (so the server's queue never holds
// them all), reported as one line: the last piece's reply, or the first
// refusal.
void ScriptRunner::runLongStep(const SourceLine& line, const ScriptCommand& command) {
  drainAll();
  setCurrent(line.number, command.name);
  const std::uint32_t maxTicks = client_.welcome().max_step_ticks();
  std::uint32_t left = command.message.step().ticks();
  std::optional<v1::ServerMessage> reply;
  while (left > 0 && !(reply && failed(*reply))) {
    const std::uint32_t piece = std::min(left, maxTicks);
    const auto message = client::step(piece);
    sentMark_ = client_.mirror().snapshotsApplied();
    const Milliseconds timeout = replyTimeout(message);
    reply = client_.awaitReply(client_.send(message), timeout);
    if (!reply) {
      throw client::ConnectionError("no reply within " + std::to_string(timeout.count()) + " ms");
    }
    left -= piece;
  }
  failures_ += failed(*reply) ? 1 : 0;
  printReport(replyReport(line.number, command.name, *reply));
}

bool ScriptRunner::readSceneFile(const SourceLine& line, ScriptCommand& command) {
  // The file may be one an earlier line's `save` writes when its reply comes.
  drainAll();
  std::string error;
  auto content = client::readSceneFile(command.file, error);
  auto data = content ? wire::sceneFromFileContent(command.file, std::move(*content), error)
                      : std::nullopt;
  if (!data) {
    fail(line, command.name, "load FILE: " + error);
    return false;
  }
  command.message.mutable_load_scene()->set_data(std::move(*data));
  return true;
}

void ScriptRunner::runBodies(const SourceLine& line, const std::string& name) {
  drainAll();
  setCurrent(line.number, name);
  // The Pong comes after every snapshot the earlier commands caused.
  client_.ping(timeout_);
  printReport(bodiesReport(line.number, client_.mirror()));
}

void ScriptRunner::runWaitSnapshot(const SourceLine& line, const std::string& name) {
  drainAll();
  setCurrent(line.number, name);
  // The newest snapshot that came after the last command was sent (and was
  // not reported yet); otherwise the next one to arrive.
  const bool fresh = client_.mirror().snapshotsApplied() > std::max(sentMark_, reportedMark_);
  const auto snapshot = fresh ? client_.lastSnapshot() : client_.awaitSnapshot(timeout_);
  if (!snapshot) {
    return fail(line, name, "no snapshot within " + std::to_string(timeout_.count()) + " ms");
  }
  reportedMark_ = client_.mirror().snapshotsApplied();
  printReport(snapshotReport(line.number, *snapshot, lastSnapshotBytes_));
}

void ScriptRunner::drainOne() {
  const Pending next = std::move(pending_.front());
  pending_.pop_front();
  setCurrent(next.line.number, next.command);
  const auto reply = client_.awaitReply(next.requestId, next.timeout);
  if (!reply) {
    throw client::ConnectionError("no reply within " + std::to_string(next.timeout.count()) +
                                  " ms");
  }
  if (!next.variable.empty()) {
    if (failed(*reply) || replyId(*reply) == 0) {
      variables_.fail(next.variable, next.line.number);
    } else {
      variables_.set(next.variable, std::to_string(replyId(*reply)));
    }
  }
  failures_ += failed(*reply) ? 1 : 0;
  if (!reply->has_scene_data()) return printReport(replyReport(next.line.number, next.command, *reply));
  const std::string& data = reply->scene_data().data();
  std::string error;
  const auto content = wire::sceneFileContent(next.file, data, error);
  if (content) error = client::writeSceneFile(next.file, *content);
  failures_ += error.empty() ? 0 : 1;
  printReport(sceneSavedReport(next.line.number, next.command, next.file,
                         content ? content->size() : 0, error));
}

void ScriptRunner::drainAll() {
  while (!pending_.empty()) drainOne();
}

void ScriptRunner::fail(const SourceLine& line, std::string_view command,
                        std::string_view problem) {
  // Reports come in line order: every earlier reply first.
  drainAll();
  setCurrent(line.number, std::string(command));
  printReport(errorReport(line.number, command, problem));
  ++failures_;
}

void ScriptRunner::setCurrent(std::size_t line, const std::string& command) {
  currentLine_ = line;
  currentCommand_ = command;
}

Milliseconds ScriptRunner::replyTimeout(const v1::ClientMessage& message) const {
  return timeout_ + Milliseconds(message.has_step() ? message.step().ticks() * 10 : 0);
}

}  // namespace impulse::cli
