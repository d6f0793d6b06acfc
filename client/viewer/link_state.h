#pragma once

namespace impulse::viewer {

/// The viewer's link to the server.
enum class LinkState { Connecting, Connected, Lost };

}  // namespace impulse::viewer
