#pragma once
/// Refusals in the words of the person who typed the command: impulse-cli's
/// word for the command ("circle", not the wire name "spawn_circle"), its
/// usage's names for the arguments ("circle X", not "spawn_circle.center.x"),
/// and numbers as people write them ("-25", not "-25.000000"). Clients show
/// a refusal as it comes (impulse-cli's error lines, the viewer's status)
/// and the server's log prints it.

#include <string>
#include <string_view>

#include "impulse.pb.h"

namespace impulse::server {

/// impulse-cli's word for a command (the command table's word column):
/// "circle", "pause" or "resume", "distance" for a distance joint. A
/// message no word can produce (a joint of no kind) keeps its wire name.
std::string_view commandWord(const v1::ClientMessage& message);

/// `error`, a refusal of `message` written with the protocol's field paths,
/// in the user's words.
std::string inUserWords(const v1::ClientMessage& message, std::string_view error);

}  // namespace impulse::server
