#pragma once
// impulse-cli output: one JSON object per script line (nlohmann::ordered_json,
// so members keep the order a reader expects: line, command, ok, ...).

#include <cstddef>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "impulse.pb.h"
#include "impulse/client/world_mirror.h"

namespace impulse::cli {

using Json = nlohmann::ordered_json;

/// A number as people write it: integral values without a fraction ("60",
/// not "60.0"); values the engine keeps in single precision as the shortest
/// decimal that reads back as the same float ("5.0745635", not
/// "5.074563503265381"); anything else as the shortest exact double.
Json number(double value);

/// Writes one report line to stdout, flushed (a person may be watching).
void printReport(const std::string& json);

/// {"line":N,"command":NAME}, for a caller to add members to.
Json lineReport(std::size_t line, std::string_view command);
/// A failed line: {"line":N,"command":NAME,"ok":false,"error":"line N: ..."}.
std::string errorReport(std::size_t line, std::string_view command, std::string_view problem);
std::string welcomeReport(const v1::Welcome& welcome);
/// CommandResult, BodyInfo or Pong. The server words its errors as the
/// script writes its commands ("circle X is not a finite number").
std::string replyReport(std::size_t line, std::string_view command, const v1::ServerMessage& reply);
/// `save`: the scene's size and file, or the error writing it.
std::string sceneSavedReport(std::size_t line, std::string_view command, const std::string& file,
                             std::size_t bytes, const std::string& error);
std::string bodiesReport(std::size_t line, const client::WorldMirror& mirror);
std::string snapshotReport(std::size_t line, const v1::Snapshot& snapshot, std::size_t frameBytes);
/// {"events":{"tick":T,"sequence":S,"contact_begins":[...],...}}: one line
/// per Events message received after `events on`, lists that are empty left
/// out.
std::string eventsReport(const v1::Events& events);

}  // namespace impulse::cli
