#pragma once
/// Level files: a scene as text that a person reads, edits and diffs. The
/// text is protobuf's JSON mapping of the same Scene message a binary scene
/// file holds (proto field names, one field a line), so every scene converts
/// both ways and the bytes come back bit-exact (docs/scenes.md, "Level
/// files"). impulse-cli's save/load and the viewer pick the form by the
/// file's extension: ".json" is text, anything else binary.

#include <optional>
#include <string>
#include <string_view>

namespace impulse::wire {

/// True when `path` names a level file (ends in ".json").
bool isSceneTextFile(std::string_view path);

/// `data`, a serialised Scene, as JSON text; nothing (with `error`) when it
/// does not parse as a Scene.
std::optional<std::string> sceneToJson(const std::string& data, std::string& error);
/// JSON text of a Scene as the serialised Scene; nothing (with `error`
/// naming the problem) when it is not one.
std::optional<std::string> sceneFromJson(std::string_view json, std::string& error);

/// What a scene file at `path` holds for the serialised scene `data`: the
/// JSON text for a level file, `data` itself otherwise.
std::optional<std::string> sceneFileContent(std::string_view path, const std::string& data,
                                            std::string& error);
/// The serialised scene in `content`, read from a scene file at `path`.
std::optional<std::string> sceneFromFileContent(std::string_view path, std::string content,
                                                std::string& error);

}  // namespace impulse::wire
