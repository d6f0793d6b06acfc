#pragma once
/// docs/product.md's key table: SDL keys to the viewer's controls.

#include <SDL_keycode.h>

#include <optional>
#include <string>

#include "controls.h"

namespace impulse::viewer {

/// The control a key stands for, or nothing for a key without one.
/// With Ctrl held, no control: Ctrl keys are the scene keys below.
std::optional<ControlKey> controlForKey(SDL_Keycode key, Uint16 modifiers = KMOD_NONE);

/// The key that loads preset `id` as a person writes it ("1", "F1",
/// "Shift+3"), found in controlForKey's table; empty when none does.
std::string presetKeyName(int id);

/// Keys whose control acts again on the keyboard's own repeat while held
/// (time scale, shape size): one step per repeat, as a person expects.
/// Held gravity and push keys repeat at the controls' steady rate instead.
bool followsKeyRepeat(Control control);

/// Ctrl+S, Ctrl+O (or Ctrl+L), Ctrl+D, Ctrl+1..9 (scene_files.h).
enum class SceneAction { SaveScene, LoadScene, SaveShape, StampShape };
struct SceneKey {
  SceneAction action;
  int index = 0;  ///< StampShape: the shape, 0-based
};
std::optional<SceneKey> sceneKeyFor(SDL_Keycode key, Uint16 modifiers);

}  // namespace impulse::viewer
