#pragma once
/// The viewer's files: the scene file (Ctrl+S saves the server's world into
/// it, Ctrl+O loads it back; a ".json" name means a level file, text), the
/// scene files beside it that the scene picker offers, and the shape library (Ctrl+D keeps a drawn
/// polygon, Ctrl+1..9 stamp one at the cursor). No window: commands go out
/// through takeCommands(), and each action returns the line to show.

#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include "controls.h"
#include "impulse/client/commands.h"
#include "impulse/math.h"

namespace impulse::viewer {

/// Shapes kept for stamping: polygons local to their centroid, one per line
/// of a text file ("x1 y1 x2 y2 ..."), oldest first.
class ShapeLibrary {
 public:
  static constexpr std::size_t kMaxShapes = 9;  ///< Ctrl+1..9

  /// Reads `path` if it exists; lines that are not valid polygons are skipped.
  explicit ShapeLibrary(std::string path);

  /// Adds the polygon through world `points` (either winding); the oldest
  /// shape goes when the library is full. Returns the line to show.
  std::string add(std::span<const Vec2> points);
  /// Vertices of shape `index` (0-based) moved so its centroid is at `at`;
  /// empty when there is no such shape.
  std::vector<Vec2> placed(std::size_t index, const Vec2& at) const;
  std::size_t size() const { return shapes_.size(); }
  const std::string& path() const { return path_; }

 private:
  std::string write() const;

  std::string path_;
  std::vector<std::vector<Vec2>> shapes_;
};

class SceneFiles {
 public:
  SceneFiles(std::string sceneFile, std::string shapeFile);

  /// Ctrl+S: asks the server for the scene; sceneArrived() writes it.
  std::string save();
  /// The server's SceneData: written to the scene file.
  std::string sceneArrived(const std::string& data);
  /// Ctrl+O: sends the scene file's world to the server.
  std::string load();
  /// The scene picker: sends the world in `path` (binary or level file).
  std::string load(const std::string& path);
  /// Scene files (".scene", ".json") in the scene file's directory, by name.
  std::vector<std::string> filesBeside() const;

  /// Ctrl+D: keeps `drawing` (the polygon being drawn) when it has three
  /// points or more, else the last polygon this viewer spawned.
  std::string saveShape(std::span<const Vec2> drawing);
  /// Ctrl+1..9: spawns shape `index` (0-based) centred at `at`.
  std::string stamp(std::size_t index, const Vec2& at, const client::SpawnOptions& options);
  /// Watches the commands the controls send, to know the last polygon drawn.
  void sent(const v1::ClientMessage& message);

  std::vector<Outgoing> takeCommands();
  const std::string& sceneFile() const { return sceneFile_; }
  /// The file of the last load sent.
  const std::string& loadingFile() const { return loading_; }
  const ShapeLibrary& shapes() const { return shapes_; }

 private:
  std::string sceneFile_;
  std::string loading_;
  ShapeLibrary shapes_;
  std::vector<Vec2> lastDrawn_;
  std::vector<Outgoing> outbox_;
};

}  // namespace impulse::viewer
