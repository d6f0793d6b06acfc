#pragma once
/// SPEC.md's key table: SDL keys to the viewer's controls.

#include <SDL_keycode.h>

#include <optional>

#include "controls.h"

namespace impulse::viewer {

/// The control a key stands for, or nothing for a key without one.
std::optional<ControlKey> controlForKey(SDL_Keycode key, Uint16 modifiers = KMOD_NONE);

}  // namespace impulse::viewer
