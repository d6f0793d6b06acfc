#pragma once
// impulse-cli output: one JSON object per script line.

#include <cstddef>
#include <string>
#include <string_view>

#include "impulse.pb.h"
#include "impulse/client/world_mirror.h"
#include "json.h"

namespace impulse::cli {

/// {"line":N,"command":NAME, then the members a caller adds.
Json lineReport(std::size_t line, std::string_view command);
/// A failed line: {"line":N,"command":NAME,"ok":false,"error":"line N: ..."}.
std::string errorReport(std::size_t line, std::string_view command, std::string_view problem);
std::string welcomeReport(const v1::Welcome& welcome);
/// CommandResult, BodyInfo or Pong.
std::string replyReport(std::size_t line, std::string_view command, const v1::ServerMessage& reply);
std::string bodiesReport(std::size_t line, const client::WorldMirror& mirror);
std::string snapshotReport(std::size_t line, const v1::Snapshot& snapshot, std::size_t frameBytes);

}  // namespace impulse::cli
