#include "key_map.h"

#include <SDL_keyboard.h>

namespace impulse::viewer {

std::optional<ControlKey> controlForKey(SDL_Keycode key, Uint16 modifiers) {
  if ((modifiers & KMOD_CTRL) != 0) return std::nullopt;
  const bool shift = (modifiers & KMOD_SHIFT) != 0;
  // Shift+1-4: the joint presets 11-14 (F1 is 10).
  if (shift && key >= SDLK_1 && key <= SDLK_4) {
    return ControlKey{Control::LoadPreset, 11 + int(key - SDLK_1)};
  }
  // Shift+5-7: the field presets 15-17.
  if (shift && key >= SDLK_5 && key <= SDLK_7) {
    return ControlKey{Control::LoadPreset, 15 + int(key - SDLK_5)};
  }
  if (key >= SDLK_0 && key <= SDLK_9) return ControlKey{Control::LoadPreset, int(key - SDLK_0)};
  // Keypad 1-8 and F5-F12: the eight materials (SDL numbers both runs
  // consecutively).
  if (key >= SDLK_KP_1 && key <= SDLK_KP_8) {
    return ControlKey{Control::SelectMaterial, int(key - SDLK_KP_1)};
  }
  if (key >= SDLK_F5 && key <= SDLK_F12) {
    return ControlKey{Control::SelectMaterial, int(key - SDLK_F5)};
  }
  switch (key) {
    case SDLK_F1: return ControlKey{Control::LoadPreset, 10};
    case SDLK_p: return ControlKey{Control::PolygonMode};
    case SDLK_o: return ControlKey{Control::CircleMode};
    case SDLK_r: return ControlKey{Control::CapsuleMode};
    case SDLK_l: return ControlKey{Control::SegmentMode};
    case SDLK_h: return ControlKey{shift ? Control::CloseChain : Control::ChainMode};
    case SDLK_e: return ControlKey{Control::RayMode};
    case SDLK_c: return ControlKey{shift ? Control::ClearAll : Control::ClearUserBodies};
    case SDLK_x: return ControlKey{Control::TogglePanel};
    case SDLK_m: return ControlKey{Control::ToggleInspector};
    case SDLK_q: return ControlKey{Control::ToggleStatic};
    case SDLK_g: return ControlKey{Control::ToggleGravity};
    case SDLK_w: return ControlKey{Control::GravityUp};
    case SDLK_a: return ControlKey{Control::GravityLeft};
    case SDLK_s: return ControlKey{Control::GravityDown};
    case SDLK_d: return ControlKey{Control::GravityRight};
    case SDLK_RETURN:
    case SDLK_KP_ENTER: return ControlKey{Control::ResetGravity};
    case SDLK_UP: return ControlKey{Control::PushUp};
    case SDLK_LEFT: return ControlKey{Control::PushLeft};
    case SDLK_DOWN: return ControlKey{Control::PushDown};
    case SDLK_RIGHT: return ControlKey{Control::PushRight};
    case SDLK_SPACE: return ControlKey{Control::TogglePause};
    case SDLK_PERIOD: return ControlKey{Control::StepOnce};
    case SDLK_DELETE:
    case SDLK_BACKSPACE: return ControlKey{Control::RemoveBody};
    case SDLK_f:
    case SDLK_HOME: return ControlKey{Control::FitView};
    case SDLK_k: return ControlKey{Control::ToggleContacts};
    case SDLK_b: return ControlKey{Control::ToggleBounds};
    case SDLK_v: return ControlKey{Control::ToggleVelocities};
    case SDLK_n: return ControlKey{Control::ToggleEventFlashes};
    case SDLK_j: return ControlKey{Control::PinSelected};
    case SDLK_ESCAPE: return ControlKey{Control::CancelOrQuit};
    case SDLK_LEFTBRACKET: return ControlKey{Control::SlowerTime};
    case SDLK_RIGHTBRACKET: return ControlKey{Control::FasterTime};
    case SDLK_BACKSLASH: return ControlKey{Control::NormalTime};
    // T Y U I, side by side: 3, 4, 5 and 6 sides.
    case SDLK_t: return ControlKey{Control::StandardShape, 3};
    case SDLK_y: return ControlKey{Control::StandardShape, 4};
    case SDLK_u: return ControlKey{Control::StandardShape, 5};
    case SDLK_i: return ControlKey{Control::StandardShape, 6};
    case SDLK_MINUS:
    case SDLK_KP_MINUS: return ControlKey{Control::ShapeSmaller};
    case SDLK_EQUALS:
    case SDLK_KP_PLUS: return ControlKey{Control::ShapeLarger};
    default: return std::nullopt;
  }
}

std::string presetKeyName(int id) {
  constexpr SDL_Keycode kPresetKeys[] = {SDLK_0, SDLK_1, SDLK_2, SDLK_3, SDLK_4, SDLK_5,
                                         SDLK_6, SDLK_7, SDLK_8, SDLK_9, SDLK_F1};
  for (const Uint16 modifiers : {Uint16(KMOD_NONE), Uint16(KMOD_SHIFT)}) {
    for (const SDL_Keycode key : kPresetKeys) {
      if (controlForKey(key, modifiers) != ControlKey{Control::LoadPreset, id}) continue;
      return std::string(modifiers == KMOD_NONE ? "" : "Shift+") + SDL_GetKeyName(key);
    }
  }
  return {};
}

bool followsKeyRepeat(Control control) {
  switch (control) {
    case Control::SlowerTime:
    case Control::FasterTime:
    case Control::ShapeSmaller:
    case Control::ShapeLarger: return true;
    default: return false;
  }
}

std::optional<SceneKey> sceneKeyFor(SDL_Keycode key, Uint16 modifiers) {
  if ((modifiers & KMOD_CTRL) == 0) return std::nullopt;
  if (key >= SDLK_1 && key <= SDLK_9) return SceneKey{SceneAction::StampShape, int(key - SDLK_1)};
  switch (key) {
    case SDLK_s: return SceneKey{SceneAction::SaveScene};
    case SDLK_o:
    case SDLK_l: return SceneKey{SceneAction::LoadScene};
    case SDLK_d: return SceneKey{SceneAction::SaveShape};
    default: return std::nullopt;
  }
}

}  // namespace impulse::viewer
