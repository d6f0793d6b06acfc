#include "scene_files.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <utility>

#include "impulse/client/scene_file.h"
#include "impulse/shape.h"
#include "impulse/wire/scene_text.h"

namespace impulse::viewer {

namespace {

std::vector<Vec2> parseShapeLine(const std::string& line) {
  std::istringstream words(line);
  std::vector<Vec2> points;
  double x = 0;
  double y = 0;
  while (words >> x >> y) points.emplace_back(Real(x), Real(y));
  return points;
}

}  // namespace

ShapeLibrary::ShapeLibrary(std::string path) : path_(std::move(path)) {
  std::ifstream file(path_);
  std::string line;
  while (std::getline(file, line) && shapes_.size() < kMaxShapes) {
    std::vector<Vec2> points = parseShapeLine(line);
    const PolygonBuild build = buildPolygon(points);
    if (build.error != ShapeError::None) continue;
    shapes_.emplace_back(build.polygon.vertices.begin(),
                         build.polygon.vertices.begin() + build.polygon.count);
  }
}

std::string ShapeLibrary::add(std::span<const Vec2> points) {
  const PolygonBuild build = buildPolygon(points);
  if (build.error != ShapeError::None)
    return "Shape not kept: " + std::string(describe(build.error));
  if (shapes_.size() == kMaxShapes) shapes_.erase(shapes_.begin());
  shapes_.emplace_back(build.polygon.vertices.begin(),
                       build.polygon.vertices.begin() + build.polygon.count);
  if (std::string error = write(); !error.empty()) return error;
  return "Shape " + std::to_string(shapes_.size()) + " kept in " + path_ + ": Ctrl+" +
         std::to_string(shapes_.size()) + " stamps it at the cursor";
}

std::vector<Vec2> ShapeLibrary::placed(std::size_t index, const Vec2& at) const {
  if (index >= shapes_.size()) return {};
  std::vector<Vec2> points;
  for (const Vec2& local : shapes_[index]) points.push_back(local + at);
  return points;
}

std::string ShapeLibrary::write() const {
  std::ostringstream text;
  text.precision(9);  // enough digits to give back every float
  for (const auto& shape : shapes_) {
    for (std::size_t i = 0; i < shape.size(); ++i)
      text << (i ? " " : "") << shape[i].x() << ' ' << shape[i].y();
    text << '\n';
  }
  const std::string error = client::writeSceneFile(path_, text.str());
  return error.empty() ? std::string() : "Shape library not written: " + error;
}

SceneFiles::SceneFiles(std::string sceneFile, std::string shapeFile)
    : sceneFile_(std::move(sceneFile)), shapes_(std::move(shapeFile)) {}

std::string SceneFiles::save() {
  outbox_.push_back({client::saveScene(), "save scene"});
  return "Saving the scene to " + sceneFile_ + "...";
}

std::string SceneFiles::sceneArrived(const std::string& data) {
  std::string error;
  const auto content = wire::sceneFileContent(sceneFile_, data, error);
  if (content) error = client::writeSceneFile(sceneFile_, *content);
  if (!error.empty()) return "Scene not saved: " + error;
  return "Scene saved to " + sceneFile_ + " (" + std::to_string(content->size()) +
         " bytes): Ctrl+O loads it";
}

std::string SceneFiles::load() { return load(sceneFile_); }

std::string SceneFiles::load(const std::string& path) {
  std::string error;
  auto content = client::readSceneFile(path, error);
  auto data = content ? wire::sceneFromFileContent(path, std::move(*content), error)
                      : std::nullopt;
  if (!data) return "Scene not loaded: " + error;
  outbox_.push_back({client::loadScene(std::move(*data)), "load scene"});
  loading_ = path;
  return "Loading the scene from " + path;
}

std::vector<std::string> SceneFiles::filesBeside() const {
  const auto directory = std::filesystem::path(sceneFile_).parent_path();
  std::error_code error;
  std::vector<std::string> files;
  for (const auto& entry : std::filesystem::directory_iterator(
           directory.empty() ? std::filesystem::path(".") : directory, error)) {
    const auto extension = entry.path().extension();
    if (entry.is_regular_file(error) && (extension == ".scene" || extension == ".json")) {
      files.push_back(entry.path().string());
    }
  }
  std::sort(files.begin(), files.end());
  return files;
}

std::string SceneFiles::saveShape(std::span<const Vec2> drawing) {
  if (drawing.size() >= 3) return shapes_.add(drawing);
  if (lastDrawn_.empty()) return "No polygon to keep: draw one (P, clicks) first";
  return shapes_.add(lastDrawn_);
}

std::string SceneFiles::stamp(std::size_t index, const Vec2& at,
                              const client::SpawnOptions& options) {
  const std::vector<Vec2> points = shapes_.placed(index, at);
  if (points.empty()) {
    return "No shape " + std::to_string(index + 1) + " in " + shapes_.path() +
           " (Ctrl+D keeps a drawn polygon)";
  }
  std::vector<client::Point> vertices;
  for (const Vec2& p : points) vertices.push_back({p.x(), p.y()});
  outbox_.push_back({client::spawnPolygon(vertices, options), "polygon"});
  return "Shape " + std::to_string(index + 1) + " stamped";
}

void SceneFiles::sent(const v1::ClientMessage& message) {
  if (!message.has_spawn_polygon()) return;
  lastDrawn_.clear();
  for (const v1::Vec2& v : message.spawn_polygon().vertices())
    lastDrawn_.emplace_back(Real(v.x()), Real(v.y()));
}

std::vector<Outgoing> SceneFiles::takeCommands() { return std::exchange(outbox_, {}); }

}  // namespace impulse::viewer
