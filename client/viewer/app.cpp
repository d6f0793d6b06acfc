#include "app.h"

#include <imgui.h>

#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "body_metrics.h"
#include "impulse/client/commands.h"
#include "key_map.h"
#include "scene_frame.h"
#include "side_panel.h"
#include "view_area.h"

namespace impulse::viewer {

namespace {

// The inspector refreshes the selected body's details this often (seconds).
constexpr double kInspectInterval = 0.2;
// One wheel notch zooms by this factor.
constexpr float kWheelZoom = 1.15f;
// A right press that moves less than this (pixels) is a click, not a pan.
constexpr int kClickSlop = 4;

// The names Controls gives the spawns of its drawing tools.
bool isDrawnShape(const std::string& what) {
  return what == "polygon" || what == "circle" || what == "capsule" || what == "segment" ||
         what == "chain";
}

std::runtime_error sdlError(const std::string& what) {
  return std::runtime_error(what + ": " + SDL_GetError());
}

}  // namespace

App::App(ViewerOptions options)
    : options_(std::move(options)), sceneFiles_(options_.sceneFile, options_.shapeFile) {
  if (SDL_Init(SDL_INIT_VIDEO) != 0) throw sdlError("SDL_Init");
  const std::string title = "Impulse - room " + roomName() + " - " + options_.connect.host + ":" +
                            std::to_string(options_.connect.port);
  window_ = SDL_CreateWindow(title.c_str(), SDL_WINDOWPOS_CENTERED, SDL_WINDOWPOS_CENTERED,
                             options_.width, options_.height, SDL_WINDOW_RESIZABLE);
  if (window_ == nullptr) throw sdlError("SDL_CreateWindow");
  SDL_SetWindowMinimumSize(window_, 480, 320);
  const Uint32 flags = options_.vsync ? SDL_RENDERER_PRESENTVSYNC : 0;
  renderer_ = SDL_CreateRenderer(window_, -1, SDL_RENDERER_ACCELERATED | flags);
  if (renderer_ == nullptr) renderer_ = SDL_CreateRenderer(window_, -1, SDL_RENDERER_SOFTWARE);
  if (renderer_ == nullptr) throw sdlError("SDL_CreateRenderer");
  SDL_SetRenderDrawBlendMode(renderer_, SDL_BLENDMODE_BLEND);

  start_ = SDL_GetPerformanceCounter();
  gui_ = std::make_unique<Gui>(window_, renderer_, options_.fontPath);
  connection_ =
      std::make_unique<Connection>(options_.connect, world_, [this] { return now(); }, options_.predict);
}

App::~App() {
  connection_.reset();
  gui_.reset();
  if (renderer_ != nullptr) SDL_DestroyRenderer(renderer_);
  if (window_ != nullptr) SDL_DestroyWindow(window_);
  SDL_Quit();
}

double App::now() const {
  return double(SDL_GetPerformanceCounter() - start_) / double(SDL_GetPerformanceFrequency());
}

WindowLayout App::layout() const {
  int w = 0;
  int h = 0;
  SDL_GetRendererOutputSize(renderer_, &w, &h);
  return layoutWindow(w, h);
}

ViewTransform App::view() const {
  return ViewTransform(layout().scene, controls_.frame(), controls_.camera());
}

const client::MirrorBody* App::mirrored(std::uint32_t id) const {
  const client::Client* client = connection_->client();
  return client != nullptr ? client->mirror().find(BodyId{id}) : nullptr;
}

ControlContext App::context() const {
  ControlContext context;
  const client::Client* client = connection_->client();
  if (client != nullptr) {
    context.serverPaused = client->mirror().paused();
    context.gravity = client->mirror().gravity();
    context.timeScale = client->mirror().timeScale();
  }
  if (inspected_ && controls_.selectedBody() &&
      inspected_->descriptor().id() == *controls_.selectedBody()) {
    context.selectedMass = inspected_->descriptor().is_static() ? 0.0 : inspected_->mass();
  }
  if (const auto hit = bodyAt(controls_.pointer())) context.bodyUnderPointer = hit->id;
  context.userBodies = userBodies();
  // The newest state, not the interpolated one: the joint's anchor is where
  // the server has the body.
  if (const auto grabbed = controls_.grabbedBody()) {
    if (const client::MirrorBody* body = mirrored(*grabbed)) {
      context.grabbed =
          GrabbedBody{body->state.position, double(massOf(lookOf(*body)).mass), body->state.angle};
    }
  }
  if (const auto selected = controls_.selectedBody()) {
    if (const client::MirrorBody* body = mirrored(*selected)) {
      context.selectedPosition = body->state.position;
    }
  }
  return context;
}

std::vector<std::uint32_t> App::userBodies() const {
  std::vector<std::uint32_t> ids;
  for (const DrawnBody& body : world_.bodies()) {
    if (!body.look->isStatic || spawned_.contains(body.state.id)) ids.push_back(body.state.id);
  }
  return ids;
}

std::optional<BodyHit> App::bodyAt(const Vec2& point) const {
  // Moving bodies before scenery: a ball resting on the floor is what a click
  // on it means.
  // A segment or chain is hit within a few pixels of its line.
  constexpr float kLineReachPixels = 5;
  const Real lineReach = kLineReachPixels / view().scale();
  std::optional<BodyHit> staticHit;
  for (auto it = world_.bodies().rbegin(); it != world_.bodies().rend(); ++it) {
    const Transform xf{it->state.position, Rot::fromAngle(it->state.angle)};
    if (!bodyTouches(*it->look, xf, point, lineReach)) continue;
    const BodyHit hit{it->state.id, it->look->isStatic, it->state.position, it->state.angle};
    if (!hit.isStatic) return hit;
    if (!staticHit) staticHit = hit;
  }
  return staticHit;
}

void App::act(ControlKey key) {
  controls_.keyPressed(key, context(), now());
  if (key.control == Control::FitView) fitFrame();
  if (key.control == Control::LoadPreset) framePresetLanding();
}

// A room opened on its bodies keeps that frame, and its area of interest
// may hold none of where the preset lands: the view moves there (grown as
// a bodies' frame is, so nothing sits on its edge), and the area follows.
void App::framePresetLanding() {
  const int link = currentLink();
  if (link == 0 || framedConnection_ != link) return;
  const AABB bounds = roomBounds();
  if (opensOnBodies(bounds)) controls_.setFrame(presetLanding(bounds).expanded(kBodiesAreaMargin));
}

void App::actOnScene(SceneKey key) {
  const Controls& c = controls_;
  switch (key.action) {
    case SceneAction::SaveScene: return controls_.notify(sceneFiles_.save(), now());
    case SceneAction::LoadScene: return controls_.notify(sceneFiles_.load(), now());
    case SceneAction::SaveShape: {
      // Only a polygon's points make a shape to keep (a chain's do not).
      const bool polygon = c.mode() == DrawMode::Polygon;
      return controls_.notify(
          sceneFiles_.saveShape(polygon ? std::span(c.placedPoints()) : std::span<const Vec2>()), now());
    }
    case SceneAction::StampShape:
      return controls_.notify(sceneFiles_.stamp(std::size_t(key.index), c.pointer(),
                                                {.material = c.material(),
                                                 .isStatic = c.nextStatic(),
                                                 .ignoreGravity = !c.nextFeelsGravity()}),
                              now());
  }
}

void App::handleKey(const SDL_KeyboardEvent& key) {
  if (const auto sceneKey = sceneKeyFor(key.keysym.sym, key.keysym.mod)) {
    if (key.type == SDL_KEYDOWN && key.repeat == 0) actOnScene(*sceneKey);
    return;
  }
  // A panel field with the focus (the inspector's) takes the key presses:
  // "1" typed there loads no preset, its Enter resets no gravity. Releases
  // still reach the controls, so no held key repeats for ever.
  if (key.type == SDL_KEYDOWN && ImGui::GetIO().WantTextInput) return;
  const auto control = controlForKey(key.keysym.sym, key.keysym.mod);
  if (!control || (key.repeat != 0 && !followsKeyRepeat(control->control))) return;
  if (key.type == SDL_KEYDOWN) {
    act(*control);
  } else {
    controls_.keyReleased(*control);
  }
}

void App::handleButton(const SDL_MouseButtonEvent& button) {
  const bool down = button.type == SDL_MOUSEBUTTONDOWN;
  const Vec2 at = view().toWorld(float(button.x), float(button.y));
  if (button.button == SDL_BUTTON_LEFT) {
    leftHeld_ = down;
    leftPressed_ = leftPressed_ || down;
    // Presses on the panel belong to its widgets; a release always ends a drag.
    if (!down) {
      controls_.pointerReleased(at);
    } else if (layout().scene.contains(float(button.x), float(button.y))) {
      controls_.pointerPressed(at, bodyAt(at), now());
    }
    return;
  }
  if (button.button != SDL_BUTTON_RIGHT && button.button != SDL_BUTTON_MIDDLE) return;
  if (down && layout().scene.contains(float(button.x), float(button.y))) {
    altPressedAt_ = SDL_Point{button.x, button.y};
    altDragged_ = false;
  } else if (!down && altPressedAt_) {
    // A right click that did not pan removes the body under it.
    if (button.button == SDL_BUTTON_RIGHT && !altDragged_) {
      const auto hit = bodyAt(at);
      controls_.removeClicked(hit ? std::optional(hit->id) : std::nullopt, now());
    }
    altPressedAt_.reset();
  }
}

void App::handleMotion(const SDL_MouseMotionEvent& motion) {
  const float dx = float(motion.x) - pointerX_;
  const float dy = float(motion.y) - pointerY_;
  pointerX_ = float(motion.x);
  pointerY_ = float(motion.y);
  if (altPressedAt_) {
    if (std::abs(motion.x - altPressedAt_->x) + std::abs(motion.y - altPressedAt_->y) > kClickSlop) {
      altDragged_ = true;
    }
    if (altDragged_) controls_.pan(dx, dy);
  }
  controls_.pointerMoved(view().toWorld(pointerX_, pointerY_));
}

void App::handleEvent(const SDL_Event& event) {
  gui_->processEvent(event);
  switch (event.type) {
    case SDL_QUIT: quit_ = true; break;
    case SDL_KEYDOWN:
    case SDL_KEYUP: handleKey(event.key); break;
    case SDL_MOUSEBUTTONDOWN:
    case SDL_MOUSEBUTTONUP: handleButton(event.button); break;
    case SDL_MOUSEMOTION: handleMotion(event.motion); break;
    case SDL_MOUSEWHEEL:
      if (event.wheel.y != 0 && layout().scene.contains(pointerX_, pointerY_)) {
        controls_.zoomAt(std::pow(kWheelZoom, float(event.wheel.y)), pointerX_, pointerY_,
                         layout().scene);
      }
      break;
    default: break;
  }
}

void App::exchange() {
  const double t = now();
  connection_->update();
  if (connection_->connected() && options_.preset && !presetRequested_) {
    act({Control::LoadPreset, *options_.preset});
    presetRequested_ = true;
  }
  controls_.update(context(), t);
  std::vector<Outgoing> commands = controls_.takeCommands();
  for (const Outgoing& command : commands) sceneFiles_.sent(command.message);
  for (Outgoing& command : sceneFiles_.takeCommands()) commands.push_back(std::move(command));
  for (Outgoing& command : commands) {
    if (!connection_->send(std::move(command.message), command.what)) {
      controls_.notify("Not connected: " + command.what + " not sent", t);
    }
  }
  if (std::optional<std::string> stopped = connection_->advancePrediction()) controls_.notify(*stopped, t);
  if (controls_.selectedBody() && connection_->connected() && t >= nextInspect_) {
    connection_->send(client::queryBody(*controls_.selectedBody()), "inspect");
    nextInspect_ = t + kInspectInterval;
  }
  if (!controls_.selectedBody()) inspected_.reset();
  handleReplies();
  followEvents(t);
  frameRoom();
  followView();
  recordFigures();
}

int App::currentLink() const { return connection_->connected() ? connection_->connections() : 0; }

void App::frameRoom() {
  const int link = currentLink();
  if (link == 0 || framedConnection_ == link) return;
  const AABB bounds = roomBounds();
  if (opensOnBodies(bounds) && connection_->client()->mirror().snapshotsApplied() == 0) return;
  framedConnection_ = link;
  if (framedBounds_ && framedBounds_->lower == bounds.lower && framedBounds_->upper == bounds.upper) return;
  fitFrame();
}

AABB App::roomBounds() const {
  const client::Client& client = *connection_->client();
  const auto local = [&](const v1::Vec2& p) {
    return client.mirror().toLocal(Vec2d(p.x(), p.y()));
  };
  return {local(client.welcome().world_min()), local(client.welcome().world_max())};
}

void App::fitFrame() {
  const int link = currentLink();
  if (link == 0 || framedConnection_ != link) return;
  const AABB bounds = roomBounds();
  const client::WorldMirror& mirror = connection_->client()->mirror();
  std::vector<Vec2> bodies;
  bodies.reserve(mirror.bodies().size());
  for (const auto& [id, body] : mirror.bodies()) bodies.push_back(body.state.position);
  controls_.setFrame(openingFrame(bounds, bodies));
  framedBounds_ = bounds;
}

void App::followView() {
  const int link = currentLink();
  if (link == 0) return;
  if (options_.budget && budgetConnection_ != link &&
      connection_->send(client::setBandwidthBudget(*options_.budget), "budget")) {
    budgetConnection_ = link;
  }
  if (!options_.areaMargin || framedConnection_ != link) return;
  const float margin = *options_.areaMargin;
  const AABB wanted = viewArea(view(), margin);
  if (areaConnection_ == link && !areaMoved(sentArea_, wanted, margin / 2)) return;
  // In the mirror's frame: the link turns it into the wire's.
  const client::Box area{{wanted.lower.x(), wanted.lower.y()},
                         {wanted.upper.x(), wanted.upper.y()}};
  if (connection_->send(client::setInterestArea(area), "area")) {
    areaConnection_ = link;
    sentArea_ = wanted;
  }
}

void App::followEvents(double now) {
  const bool wanted = controls_.overlays().eventFlashes;
  const int link = currentLink();
  if (eventsConnection_ != 0 && (!wanted || eventsConnection_ != link)) {
    // Off, or the connection subscribed is gone (a new one starts unsubscribed).
    if (eventsConnection_ == link) connection_->send(client::subscribeEvents(false), "events off");
    eventsConnection_ = 0;
    connection_->takeEvents();
    flashes_.clear();
  }
  if (wanted && link != 0 && eventsConnection_ == 0) {
    // Events that came after an unsubscription are stale: not flashed.
    connection_->takeEvents();
    if (connection_->send(client::subscribeEvents(true), "events")) eventsConnection_ = link;
  }
  if (eventsConnection_ == 0) return;
  const double tickSeconds = connection_->tickSeconds();
  for (const v1::Events& events : connection_->takeEvents()) {
    flashes_.add(events, double(events.tick()) * tickSeconds, now);
    ++eventMessages_;
  }
}

void App::handleReplies() {
  for (Reply& reply : connection_->takeReplies()) {
    if (reply.what == "ray") {
      controls_.rayAnswered(reply.message, now());
      continue;
    }
    if (reply.message.has_body_info()) {
      if (controls_.selectedBody() == reply.message.body_info().descriptor().id()) {
        inspected_ = reply.message.body_info();
      }
      continue;
    }
    if (reply.message.has_scene_data()) {
      controls_.notify(sceneFiles_.sceneArrived(reply.message.scene_data().data()), now());
      continue;
    }
    if (!reply.message.has_command_result()) continue;
    const v1::CommandResult& result = reply.message.command_result();
    if (reply.what == "load scene" && result.ok()) {
      controls_.notify("Scene loaded from " + sceneFiles_.loadingFile(), now());
    }
    if (result.ok()) {
      if (isDrawnShape(reply.what)) spawned_.insert(result.body_id());
    } else if (reply.what == "inspect") {
      // The selected body is gone (cleared, preset loaded).
      controls_.deselect();
      inspected_.reset();
    } else {
      controls_.notify("Server refused " + reply.what + ": " + result.error(), now());
    }
  }
}

void App::recordFigures() {
  // Both plots advance with the server's Pongs, so they share a time axis.
  auto stats = connection_->takeStats();
  if (!stats) return;
  stats_ = std::move(stats);
  stepMs_.add(float(stats_->last_step_ms()));
  energy_.add(float(kineticEnergy(world_.bodies())));
}

void App::updateJointFigures() {
  jointFigures_.clear();
  const client::Client* client = connection_->client();
  if (client == nullptr) return;
  for (const auto& [id, joint] : client->mirror().joints()) {
    // The drag's own joint (a mouse joint on the grabbed body) is drawn as
    // the grab line, to the cursor: the mirror keeps the target the joint
    // was made with.
    const bool dragged = std::holds_alternative<MouseJointSettings>(joint.settings) &&
                         joint.bodyA.value == controls_.grabbedBody();
    if (dragged) continue;
    if (auto figure = jointFigure(joint, world_.find(joint.bodyA.value), world_.find(joint.bodyB.value))) {
      jointFigures_.push_back(*figure);
    }
  }
}

void App::drawScene(ImDrawList& list, const ViewTransform& view) {
  scene_.begin(list, view);
  if (const client::Client* client = connection_->client()) {
    scene_.drawFields(list, view, client->mirror().fields());
  }
  scene_.drawBodies(list, view, world_.bodies(), controls_.selectedBody(), controls_.grabbedBody());
  scene_.drawBodies(list, view, world_.spawnedBodies(), std::nullopt, std::nullopt);
  updateJointFigures();
  scene_.drawJoints(list, view, jointFigures_);
  if (const client::Client* client = connection_->client(); client && client->mirror().preset()) {
    scene_.drawMarkers(list, view, client->mirror().preset()->markers);
  }
  scene_.drawFlashes(list, view, flashes_, world_, now());
  overlays_.draw(list, view, world_.bodies(), controls_.overlays());
  if (const auto grabbed = controls_.grabbedBody()) {
    for (const DrawnBody& body : world_.bodies()) {
      if (body.state.id != *grabbed) continue;
      scene_.drawGrab(list, view, *controls_.heldPoint(body.state.position, body.state.angle),
                      controls_.pointer());
    }
  }
  scene_.drawPreview(list, view, controls_);
  if (controls_.mode() == DrawMode::Ray) {
    const auto& answer = controls_.rayTool().answer();
    const DrawnBody* hitBody = answer && answer->hit ? world_.findDrawn(answer->hit->body) : nullptr;
    scene_.drawRay(list, view, controls_.rayTool(), hitBody);
  }
  scene_.end(list);
}

void App::draw() {
  // A click shorter than a frame still reaches the panel as a press.
  gui_->beginFrame({pointerX_, pointerY_, leftHeld_ || leftPressed_});
  leftPressed_ = false;
  const ViewTransform v = view();
  drawScene(*ImGui::GetBackgroundDrawList(), v);

  PanelInput input;
  input.link = connection_->state();
  input.linkText = connection_->describe();
  input.roundTripMs = connection_->roundTripMs();
  input.snapshotsPerSecond = connection_->snapshotsPerSecond();
  input.playoutDelayMs = world_.clock().delay() * 1000;
  input.frameMs = frameMs_;
  input.framesPerSecond = framesPerSecond_;
  input.room = roomName();
  input.presets = &presets_;
  input.sceneFiles = sceneFileList_;
  input.zoom = controls_.camera().zoom;
  input.bodies = world_.bodies().size();
  input.notice = controls_.notice(now());
  input.stats = stats_ ? &*stats_ : nullptr;
  input.stepMs = &stepMs_;
  input.kineticEnergy = &energy_;
  input.eventMessages = eventMessages_;
  input.predicting = connection_->predicting();
  if (const client::Predictor* predictor = connection_->predictor()) {
    input.prediction = PredictionFigures{predictor->tick() - connection_->client()->mirror().tick(),
                                         predictor->shownCorrection(), predictor->largestCorrection()};
  }
  if (const client::Client* client = connection_->client()) {
    const auto& mirror = client->mirror();
    input.origin = mirror.origin();
    if (mirror.preset()) input.preset = &*mirror.preset();
    input.gravity = mirror.gravity();
    input.serverPaused = mirror.paused();
    input.tick = mirror.tick();
    input.simTime = mirror.simTime();
    input.timeScale = mirror.timeScale();
  }
  if (inspected_) input.inspected = &*inspected_;
  const PanelActions actions{[this](ControlKey key) { act(key); },
                             [this](const std::string& file) {
                               controls_.notify(sceneFiles_.load(file), now());
                             },
                             [this](v1::ClientMessage message, std::string what) {
                               if (!connection_->send(std::move(message), what)) {
                                 controls_.notify("Not connected: " + what + " not sent", now());
                               }
                             },
                             [this](bool wanted) { connection_->setPredicting(wanted); }};
  drawSidePanel(layout().panel, {gui_->textFont(), gui_->titleFont()}, controls_, input, actions,
                panelState_);

  SDL_SetRenderDrawColor(renderer_, palette::kBackground.r, palette::kBackground.g,
                         palette::kBackground.b, 255);
  SDL_RenderClear(renderer_);
  gui_->render();
}

bool App::saveCapture(const std::string& path) {
  int w = 0;
  int h = 0;
  SDL_GetRendererOutputSize(renderer_, &w, &h);
  SDL_Surface* surface = SDL_CreateRGBSurfaceWithFormat(0, w, h, 32, SDL_PIXELFORMAT_ARGB8888);
  if (surface == nullptr) return false;
  bool ok = SDL_RenderReadPixels(renderer_, nullptr, SDL_PIXELFORMAT_ARGB8888, surface->pixels,
                                 surface->pitch) == 0 &&
            SDL_SaveBMP(surface, path.c_str()) == 0;
  if (!ok) std::fprintf(stderr, "impulse-viewer: cannot save %s: %s\n", path.c_str(), SDL_GetError());
  SDL_FreeSurface(surface);
  return ok;
}

std::string App::roomName() const {
  return options_.connect.room.empty() ? "default" : options_.connect.room;
}

void App::countFrame(double at) {
  // Frames counted over about a second: a steady figure, not one frame's.
  ++windowFrames_;
  if (at - windowStart_ < 1) return;
  framesPerSecond_ = windowFrames_ / (at - windowStart_);
  windowStart_ = at;
  windowFrames_ = 0;
  // The scene files beside the scene file, for the picker: once a second
  // is often enough for files a person saves.
  sceneFileList_ = sceneFiles_.filesBeside();
}

bool App::frame() {
  const double begin = now();
  SDL_Event event;
  while (SDL_PollEvent(&event) != 0) handleEvent(event);
  exchange();
  world_.update(now());
  if (const client::Predictor* predictor = connection_->predictor()) world_.showPredicted(*predictor);
  flashes_.update(world_.renderTime(), now());
  const double drawn = now();
  draw();
  const double beforePresent = now();
  if (capturePath_) {
    saveCapture(*capturePath_);
    capturePath_.reset();
  }
  SDL_RenderPresent(renderer_);
  const double end = now();
  timing_ = {(drawn - begin) * 1000, (beforePresent - drawn) * 1000, (end - beforePresent) * 1000};
  // The panel shows the work of a frame, without the wait for vsync.
  frameMs_ = timing_.update + timing_.draw;
  ++frames_;
  countFrame(end);
  return !quit_ && !controls_.quitRequested();
}

int App::run() {
  SDL_DisplayMode mode;
  const int refresh =
      SDL_GetWindowDisplayMode(window_, &mode) == 0 && mode.refresh_rate > 0 ? mode.refresh_rate : 60;
  const double minFrame = 1.0 / refresh;
  while (true) {
    const double begin = now();
    const bool lastFrame = options_.frames > 0 && frames_ + 1 >= std::uint64_t(options_.frames);
    if (lastFrame && options_.screenshot) captureNextFrame(*options_.screenshot);
    if (!frame() || lastFrame) break;
    // Without vsync (or when it is ignored), do not spin faster than the display.
    const double spent = now() - begin;
    if (spent < minFrame) SDL_Delay(Uint32((minFrame - spent) * 1000));
  }
  return 0;
}

}  // namespace impulse::viewer
