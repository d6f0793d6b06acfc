// Drops a rubber ball and a wooden box onto a floor, steps the world at
// 60 Hz for three seconds and prints where they are. Builds against the
// installed engine alone (find_package(Impulse) or pkg-config impulse).
#include <array>
#include <cstdio>

#include "impulse/world.h"

int main() {
  impulse::World world;  // gravity (0, -9.81), 4 sub-steps, bounds (-25, -25) to (50, 45)

  // A static floor: a 20 m x 1 m slab whose top is at y = 0.
  const std::array<impulse::Vec2, 4> slab = {
      impulse::Vec2(-10, -1), impulse::Vec2(10, -1), impulse::Vec2(10, 0), impulse::Vec2(-10, 0)};
  const auto floor = world.createPolygon(slab, {.properties = {.isStatic = true}});

  const auto ball = world.createCircle({-2, 4}, 0.5f, {.material = impulse::Material::Rubber});
  const std::array<impulse::Vec2, 4> crate = {
      impulse::Vec2(1, 2), impulse::Vec2(2, 2), impulse::Vec2(2, 3), impulse::Vec2(1, 3)};
  const auto box = world.createPolygon(crate, {.material = impulse::Material::Wood});

  // Every input is checked: a refused body says why and changes nothing.
  const std::array<impulse::Vec2, 2> segment = {impulse::Vec2(0, 5), impulse::Vec2(1, 5)};
  const auto refused = world.createPolygon(segment);
  std::printf("refused: %s\n", refused.error.c_str());
  if (!floor.ok() || !ball.ok() || !box.ok() || refused.ok()) return 1;

  constexpr float kDt = 1.0f / 60;
  for (int tick = 1; tick <= 180; ++tick) {
    world.step(kDt);
    if (tick % 60 != 0) continue;
    std::printf("t = %.1f s, %d bodies, %d awake\n", world.simulatedTime(), world.bodyCount(),
                world.awakeBodyCount());
    for (const auto& [name, id] : {std::pair{"ball", ball.id}, std::pair{"box", box.id}}) {
      const impulse::BodyState state = *world.bodyState(id);
      std::printf("  %-4s at (%6.3f, %6.3f) m, speed (%6.3f, %6.3f) m/s, %s\n", name,
                  state.position.x(), state.position.y(), state.linearVelocity.x(),
                  state.linearVelocity.y(), state.awake ? "awake" : "asleep");
    }
  }
  std::printf("state hash %016llx\n", static_cast<unsigned long long>(world.stateHash()));
  return 0;
}
