#pragma once
/// Scene files: a serialised Scene message (docs/scenes.md) as the file's
/// whole content, no header. impulse-cli's `save` / `load` and the viewer's
/// Ctrl+S / Ctrl+O use them.

#include <cstddef>
#include <optional>
#include <string>

namespace impulse::client {

/// Larger files are refused before they are read (a scene of the server's
/// default 10 000 bodies takes a few MiB).
inline constexpr std::size_t kMaxSceneFileBytes = std::size_t(64) << 20;

/// The file's bytes, or nothing with `error` saying why (cannot open, too large).
std::optional<std::string> readSceneFile(const std::string& path, std::string& error);
/// Writes `data` to `path` through a temporary file renamed into place, so
/// a failed write never leaves half a scene. Empty on success, else why.
std::string writeSceneFile(const std::string& path, const std::string& data);

}  // namespace impulse::client
