#include "app.h"

#include <SDL_ttf.h>

#include <cstdio>
#include <stdexcept>

#include "impulse/client/commands.h"
#include "key_map.h"

namespace impulse::viewer {

namespace {

// The inspector refreshes the selected body's details this often (seconds).
constexpr double kInspectInterval = 0.2;

std::runtime_error sdlError(const std::string& what) {
  return std::runtime_error(what + ": " + SDL_GetError());
}

}  // namespace

App::App(ViewerOptions options) : options_(std::move(options)) {
  if (SDL_Init(SDL_INIT_VIDEO) != 0) throw sdlError("SDL_Init");
  if (TTF_Init() != 0) {
    SDL_Quit();
    throw std::runtime_error(std::string("TTF_Init: ") + TTF_GetError());
  }
  const std::string title = "Impulse - " + options_.connect.host + ":" +
                            std::to_string(options_.connect.port);
  window_ = SDL_CreateWindow(title.c_str(), SDL_WINDOWPOS_CENTERED, SDL_WINDOWPOS_CENTERED,
                             options_.width, options_.height, SDL_WINDOW_RESIZABLE);
  if (window_ == nullptr) throw sdlError("SDL_CreateWindow");
  SDL_SetWindowMinimumSize(window_, 320, 240);
  const Uint32 flags = options_.vsync ? SDL_RENDERER_PRESENTVSYNC : 0;
  renderer_ = SDL_CreateRenderer(window_, -1, SDL_RENDERER_ACCELERATED | flags);
  if (renderer_ == nullptr) renderer_ = SDL_CreateRenderer(window_, -1, SDL_RENDERER_SOFTWARE);
  if (renderer_ == nullptr) throw sdlError("SDL_CreateRenderer");
  SDL_SetRenderDrawBlendMode(renderer_, SDL_BLENDMODE_BLEND);

  start_ = SDL_GetPerformanceCounter();
  scene_ = std::make_unique<WorldRenderer>(renderer_);
  hud_ = std::make_unique<Hud>(renderer_, options_.fontPath);
  connection_ = std::make_unique<Connection>(options_.connect, world_, [this] { return now(); });
}

App::~App() {
  connection_.reset();
  hud_.reset();
  scene_.reset();
  if (renderer_ != nullptr) SDL_DestroyRenderer(renderer_);
  if (window_ != nullptr) SDL_DestroyWindow(window_);
  TTF_Quit();
  SDL_Quit();
}

double App::now() const {
  return double(SDL_GetPerformanceCounter() - start_) / double(SDL_GetPerformanceFrequency());
}

ViewTransform App::view() const {
  int w = 0;
  int h = 0;
  SDL_GetRendererOutputSize(renderer_, &w, &h);
  return ViewTransform(w, h, kSceneSize);
}

ControlContext App::context() const {
  ControlContext context;
  const client::Client* client = connection_->client();
  const auto* preset = client != nullptr && client->mirror().preset()
                           ? &*client->mirror().preset()
                           : nullptr;
  context.drawingAllowed = preset != nullptr && preset->drawingAllowed;
  if (inspected_ && controls_.selectedBody() &&
      inspected_->descriptor().id() == *controls_.selectedBody()) {
    context.selectedMass = inspected_->descriptor().is_static() ? 0.0 : inspected_->mass();
  }
  return context;
}

std::optional<std::uint32_t> App::bodyAt(const Vec2& point) const {
  // Moving bodies before scenery: a ball resting on the floor is what a click
  // on it means.
  std::optional<std::uint32_t> staticHit;
  for (auto it = world_.bodies().rbegin(); it != world_.bodies().rend(); ++it) {
    const Transform xf{it->state.position, Rot::fromAngle(it->state.angle)};
    if (!containsPoint(it->look->shape, xf, point)) continue;
    if (!it->look->isStatic) return it->state.id;
    if (!staticHit) staticHit = it->state.id;
  }
  return staticHit;
}

void App::handleEvent(const SDL_Event& event) {
  const double t = now();
  switch (event.type) {
    case SDL_QUIT: quit_ = true; break;
    case SDL_KEYDOWN:
      // Held keys repeat at the controls' own steady rate, not the OS's.
      if (event.key.repeat != 0) break;
      if (const auto key = controlForKey(event.key.keysym.sym)) {
        controls_.keyPressed(*key, context(), t);
      }
      break;
    case SDL_KEYUP:
      if (const auto key = controlForKey(event.key.keysym.sym)) controls_.keyReleased(*key);
      break;
    case SDL_MOUSEBUTTONDOWN:
      if (event.button.button == SDL_BUTTON_LEFT) {
        const Vec2 at = view().toWorld(float(event.button.x), float(event.button.y));
        controls_.pointerPressed(at, bodyAt(at), t);
      }
      break;
    case SDL_MOUSEBUTTONUP:
      if (event.button.button == SDL_BUTTON_LEFT) {
        controls_.pointerReleased(view().toWorld(float(event.button.x), float(event.button.y)));
      }
      break;
    case SDL_MOUSEMOTION:
      controls_.pointerMoved(view().toWorld(float(event.motion.x), float(event.motion.y)));
      break;
    default: break;
  }
}

void App::exchange() {
  const double t = now();
  connection_->update();
  if (connection_->connected() && options_.preset && !presetRequested_) {
    controls_.keyPressed({Control::LoadPreset, *options_.preset}, context(), t);
    presetRequested_ = true;
  }
  controls_.update(context(), t);
  for (Outgoing& command : controls_.takeCommands()) {
    if (!connection_->send(std::move(command.message), command.what)) {
      controls_.notify("Not connected: " + command.what + " not sent", t);
    }
  }
  if (controls_.selectedBody() && connection_->connected() && t >= nextInspect_) {
    connection_->send(client::queryBody(*controls_.selectedBody()), "inspect");
    nextInspect_ = t + kInspectInterval;
  }
  if (!controls_.selectedBody()) inspected_.reset();
  for (Reply& reply : connection_->takeReplies()) {
    if (reply.message.has_body_info()) {
      if (controls_.selectedBody() == reply.message.body_info().descriptor().id()) {
        inspected_ = reply.message.body_info();
      }
    } else if (reply.message.has_command_result() && !reply.message.command_result().ok()) {
      if (reply.what == "inspect") {
        // The selected body is gone (cleared, preset loaded).
        controls_.deselect();
        inspected_.reset();
      } else {
        controls_.notify("Server refused " + reply.what + ": " +
                             reply.message.command_result().error(),
                         t);
      }
    }
  }
}

void App::draw() {
  const ViewTransform v = view();
  int w = 0;
  int h = 0;
  SDL_GetRendererOutputSize(renderer_, &w, &h);
  scene_->drawBackground(v);
  scene_->drawBodies(v, world_.bodies(), controls_.selectedBody());

  HudInput input;
  input.link = connection_->state();
  input.linkText = connection_->describe();
  input.retryInSeconds = connection_->retryIn();
  input.roundTripMs = connection_->roundTripMs();
  input.snapshotsPerSecond = connection_->snapshotsPerSecond();
  input.playoutDelayMs = world_.clock().delay() * 1000;
  input.frameMs = frameMs_;
  input.bodies = world_.bodies().size();
  input.notice = controls_.notice(now());
  if (const client::Client* client = connection_->client()) {
    const auto& mirror = client->mirror();
    if (mirror.preset()) {
      input.preset = &*mirror.preset();
      scene_->drawMarkers(v, mirror.preset()->markers);
    }
    input.gravity = mirror.gravity();
    input.serverPaused = mirror.paused();
    input.tick = mirror.tick();
  }
  if (inspected_) input.inspected = &*inspected_;
  scene_->drawPreview(v, controls_);
  hud_->draw(controls_, input, w, h);
  hud_->endFrame();
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

bool App::frame() {
  const double begin = now();
  SDL_Event event;
  while (SDL_PollEvent(&event) != 0) handleEvent(event);
  exchange();
  world_.update(now());
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
  // The HUD shows the work of a frame, without the wait for vsync.
  frameMs_ = timing_.update + timing_.draw;
  ++frames_;
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
