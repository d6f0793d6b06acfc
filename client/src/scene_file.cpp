#include "impulse/client/scene_file.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <system_error>

namespace impulse::client {

std::optional<std::string> readSceneFile(const std::string& path, std::string& error) {
  std::error_code code;
  const auto size = std::filesystem::file_size(path, code);
  if (code) {
    error = "cannot read " + path + ": " + code.message();
    return std::nullopt;
  }
  if (size > kMaxSceneFileBytes) {
    error = path + " is larger than a scene file may be (" +
            std::to_string(kMaxSceneFileBytes >> 20) + " MiB)";
    return std::nullopt;
  }
  std::ifstream file(path, std::ios::binary);
  std::string data((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  if (!file.good() && !file.eof()) {
    error = "cannot read " + path;
    return std::nullopt;
  }
  return data;
}

std::string writeSceneFile(const std::string& path, const std::string& data) {
  const std::string temporary = path + ".part";
  {
    std::ofstream file(temporary, std::ios::binary | std::ios::trunc);
    file.write(data.data(), std::streamsize(data.size()));
    if (!file) return "cannot write " + temporary;
  }
  std::error_code code;
  std::filesystem::rename(temporary, path, code);
  if (code) {
    std::filesystem::remove(temporary, code);
    return "cannot write " + path + ": " + code.message();
  }
  return {};
}

}  // namespace impulse::client
