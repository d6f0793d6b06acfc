#include "impulse/wire/scene_text.h"

#include <google/protobuf/util/json_util.h>

#include "impulse_text.pb.h"

namespace impulse::wire {

namespace {

// The full-runtime twin of impulse.proto (see CMakeLists.txt): the wire
// schema is lite, without the reflection JSON needs.
using TextScene = v1::text::Scene;

constexpr std::string_view kTextExtension = ".json";

bool endsNumber(char c) { return !(c >= '0' && c <= '9') && c != '.' && c != 'e' && c != 'E'; }

// Every number written "-0" as "-0.0". The printer writes a float -0 as
// "-0", which protobuf's JSON parser reads as the integer 0 and so as +0;
// the binary form keeps the sign (the engine's normals have -0 parts), and
// "-0.0" reads back as -0. Strings are copied as they are.
std::string negativeZerosAsDecimals(std::string_view json) {
  std::string out;
  out.reserve(json.size());
  bool inString = false;
  for (std::size_t i = 0; i < json.size(); ++i) {
    const char c = json[i];
    out += c;
    if (inString) {
      if (c == '\\' && i + 1 < json.size()) out += json[++i];
      inString = c != '"';
      continue;
    }
    inString = c == '"';
    const bool negativeZero = c == '-' && i + 1 < json.size() && json[i + 1] == '0' &&
                              (i + 2 == json.size() || endsNumber(json[i + 2]));
    if (negativeZero) {
      out += "0.0";
      ++i;
    }
  }
  return out;
}

}  // namespace

bool isSceneTextFile(std::string_view path) { return path.ends_with(kTextExtension); }

std::optional<std::string> sceneToJson(const std::string& data, std::string& error) {
  TextScene scene;
  if (!scene.ParseFromString(data)) {
    error = "the data does not parse as a Scene message";
    return std::nullopt;
  }
  google::protobuf::util::JsonPrintOptions options;
  options.add_whitespace = true;  // one field a line: readable, and diffs line by line
  options.preserve_proto_field_names = true;  // the names proto/impulse.proto and the docs use
  // Zeros too: a person sees every field there is to edit, and -0 (which the
  // binary form keeps, bit for bit) is not taken for an unset 0.
  options.always_print_primitive_fields = true;
  std::string json;
  if (const auto status = google::protobuf::util::MessageToJsonString(scene, &json, options);
      !status.ok()) {
    error = "cannot write the scene as JSON: " + std::string(status.message());
    return std::nullopt;
  }
  return json;
}

std::optional<std::string> sceneFromJson(std::string_view json, std::string& error) {
  TextScene scene;
  const google::protobuf::util::JsonParseOptions options;  // unknown names are mistakes: refused
  const std::string decimals = negativeZerosAsDecimals(json);
  if (const auto status = google::protobuf::util::JsonStringToMessage(decimals, &scene, options);
      !status.ok()) {
    error = "not a scene in JSON: " + std::string(status.message());
    return std::nullopt;
  }
  return scene.SerializeAsString();
}

std::optional<std::string> sceneFileContent(std::string_view path, const std::string& data,
                                            std::string& error) {
  if (!isSceneTextFile(path)) return data;
  return sceneToJson(data, error);
}

std::optional<std::string> sceneFromFileContent(std::string_view path, std::string content,
                                                std::string& error) {
  if (!isSceneTextFile(path)) return content;
  return sceneFromJson(content, error);
}

}  // namespace impulse::wire
