// libFuzzer target: a structured sequence of engine API calls replayed on a
// world (the bytes choose the calls and their numbers, hostile ones
// included: NaN, infinities, 3.4e38, denormals): bodies, pushes, joints of
// every kind and force fields. Checked: a refused call leaves the world
// bit-identical; after every step each body is finite and within the speed
// limits, and the body limit holds.
#include <fuzzer/FuzzedDataProvider.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include "world_invariants.h"
#include "impulse/field_kinds.h"
#include "impulse/world.h"

namespace {

using impulse::BodyId;
using impulse::FieldId;
using impulse::JointId;
using impulse::Real;
using impulse::Vec2;
using impulse::World;

// Small enough for millions of runs, large enough for piles and contacts.
constexpr int kMaxCalls = 32;
constexpr int kMaxBodies = 16;
constexpr Real kDt = Real(1) / Real(60);

// Numbers an attacker would try, besides arbitrary ones.
constexpr std::array<Real, 12> kHostile = {
    std::numeric_limits<Real>::quiet_NaN(), std::numeric_limits<Real>::infinity(),
    -std::numeric_limits<Real>::infinity(), std::numeric_limits<Real>::max(),
    -std::numeric_limits<Real>::max(), std::numeric_limits<Real>::denorm_min(),
    Real(1e30), Real(-1e38), 0, Real(500), Real(1000), Real(-0.0)};

class Calls {
 public:
  Calls(const std::uint8_t* data, std::size_t size) : in_(data, size) {}

  bool more() { return in_.remaining_bytes() > 0; }
  std::uint8_t pick() { return in_.ConsumeIntegral<std::uint8_t>(); }

  // Mostly a scene-sized number, sometimes a hostile one, sometimes any float.
  Real number(Real low, Real high) {
    switch (in_.ConsumeIntegralInRange(0, 7)) {
      case 0:
        return kHostile[in_.ConsumeIntegralInRange<std::size_t>(0, kHostile.size() - 1)];
      case 1:
        return in_.ConsumeFloatingPoint<Real>();
      default:
        return in_.ConsumeFloatingPointInRange<Real>(low, high);
    }
  }
  Vec2 position() { return Vec2(number(-30, 55), number(-30, 50)); }
  Vec2 vector(Real magnitude) { return Vec2(number(-magnitude, magnitude), number(-magnitude, magnitude)); }

  BodyId body(const std::vector<BodyId>& ids) {
    if (ids.empty() || in_.ConsumeIntegralInRange(0, 15) == 0) return BodyId{in_.ConsumeIntegral<std::uint32_t>()};
    return ids[in_.ConsumeIntegralInRange<std::size_t>(0, ids.size() - 1)];
  }

  impulse::BodyOptions options() {
    impulse::BodyOptions o;
    o.material = static_cast<impulse::Material>(in_.ConsumeIntegralInRange(0, impulse::kMaterialCount - 1));
    o.properties.isStatic = in_.ConsumeIntegralInRange(0, 5) == 0;
    o.properties.ignoreGravity = in_.ConsumeBool();
    o.linearVelocity = vector(600);
    o.angularVelocity = number(-1200, 1200);
    return o;
  }

  std::vector<Vec2> polygon() {
    std::vector<Vec2> points(in_.ConsumeIntegralInRange<std::size_t>(1, 18));
    const Vec2 centre = position();
    for (Vec2& p : points) p = centre + vector(3);
    return points;
  }

  bool flag() { return in_.ConsumeBool(); }

  // Any kind, with scene-sized or hostile numbers in every setting.
  impulse::JointSettings jointSettings() {
    switch (in_.ConsumeIntegralInRange(0, 6)) {
      case 0:
        return impulse::DistanceJointSettings{number(0, 10), number(0, 1e4f), number(0, 100)};
      case 1:
        return impulse::RopeJointSettings{number(0, 10)};
      case 2:
        return impulse::RevoluteJointSettings{flag(), number(-4, 0), number(0, 4), flag(),
                                              number(-20, 20), number(0, 1e4f), number(0, 1e3f),
                                              number(0, 100)};
      case 3:
        return impulse::PrismaticJointSettings{vector(1), flag(), number(-4, 0), number(0, 4), flag(),
                                               number(-20, 20), number(0, 1e4f), number(0, 1e3f),
                                               number(0, 100)};
      case 4:
        return impulse::WeldJointSettings{number(0, 1e4f), number(0, 1e4f)};
      case 5:
        return impulse::WheelJointSettings{vector(1), number(0, 1e4f), number(0, 100), flag(),
                                           number(-20, 20), number(0, 1e4f)};
      default:
        return impulse::MouseJointSettings{number(0, 1e5f), number(0, 1e4f), number(0, 100)};
    }
  }

  impulse::JointDef joint(const std::vector<BodyId>& ids) {
    // A null body B is the world, as the wire allows.
    const BodyId bodyB = in_.ConsumeIntegralInRange(0, 3) == 0 ? BodyId{} : body(ids);
    return {body(ids), bodyB, position(), position(), flag(), jointSettings()};
  }

  JointId jointId(const std::vector<JointId>& ids) {
    if (ids.empty() || in_.ConsumeIntegralInRange(0, 15) == 0) return JointId{in_.ConsumeIntegral<std::uint32_t>()};
    return ids[in_.ConsumeIntegralInRange<std::size_t>(0, ids.size() - 1)];
  }

  impulse::JointUpdate jointUpdate() {
    impulse::JointUpdate update;
    if (flag()) update.target = position();
    if (flag()) update.motorSpeed = number(-20, 20);
    if (flag()) update.maxMotorForce = number(0, 1e4f);
    return update;
  }

  impulse::FieldDef field() {
    switch (in_.ConsumeIntegralInRange(0, 2)) {
      case 0:
        return impulse::GravitationDef{number(0, 10)};
      case 1:
        return impulse::FluidDef{polygon(), number(0, 3000), number(0, 10), number(0, 10), vector(5)};
      default:
        return impulse::FanDef{position(), vector(1), number(0, 50), number(0, 30), number(0, 1.5f)};
    }
  }

  FieldId fieldId(const std::vector<FieldId>& ids) {
    if (ids.empty() || in_.ConsumeIntegralInRange(0, 15) == 0) return FieldId{in_.ConsumeIntegral<std::uint32_t>()};
    return ids[in_.ConsumeIntegralInRange<std::size_t>(0, ids.size() - 1)];
  }

 private:
  FuzzedDataProvider in_;
};

void checkAfterStep(const World& world) {
  FUZZ_CHECK(world.bodyCount() <= kMaxBodies);
  checkWorldSane(world);
}

// What the sequence has made so far (refused and removed ids included: the
// world must refuse them cleanly).
struct Made {
  std::vector<BodyId> bodies;
  std::vector<JointId> joints;
  std::vector<FieldId> fields;
};

bool applyConnectorCall(World& world, Calls& calls, Made& made) {
  switch (calls.pick() % 5) {
    case 0: {
      const auto created = world.createJoint(calls.joint(made.bodies));
      if (created.ok()) made.joints.push_back(created.id);
      return created.ok();
    }
    case 1:
      return world.destroyJoint(calls.jointId(made.joints));
    case 2:
      return world.updateJoint(calls.jointId(made.joints), calls.jointUpdate()).ok();
    case 3: {
      const auto built = impulse::makeField(calls.field());
      if (!built.ok()) return true;  // nothing reached the world
      made.fields.push_back(world.addField(built.field));
      return true;
    }
    default:
      return world.removeField(calls.fieldId(made.fields));
  }
}

// Applies one call; returns false when the world refused it.
bool applyCall(World& world, Calls& calls, Made& made) {
  std::vector<BodyId>& ids = made.bodies;
  switch (calls.pick() % 10) {
    case 0: {
      const auto created = world.createCircle(calls.position(), calls.number(0, 3), calls.options());
      if (created.ok()) ids.push_back(created.id);
      return created.ok();
    }
    case 1: {
      const auto points = calls.polygon();
      const auto created = world.createPolygon(points, calls.options());
      if (created.ok()) ids.push_back(created.id);
      return created.ok();
    }
    case 2: {
      const BodyId id = calls.body(ids);
      const Vec2 impulse = calls.vector(5000);
      if (calls.pick() & 1) return world.applyImpulse(id, impulse, calls.position()).ok();
      return world.applyImpulse(id, impulse).ok();
    }
    case 3: {
      const BodyId id = calls.body(ids);
      return world.applyForce(id, calls.vector(1e6f), calls.position()).ok();
    }
    case 4: {
      const BodyId id = calls.body(ids);
      return world.setVelocity(id, calls.vector(600), calls.number(-1200, 1200)).ok();
    }
    case 5:
      return world.setGravity(calls.vector(1200)).ok();
    case 6:
      return world.destroyBody(calls.body(ids));
    case 7:
      world.queryPoint(calls.position());
      return true;
    case 8:
      return applyConnectorCall(world, calls, made);
    default:
      for (int i = 1 + calls.pick() % 4; i > 0; --i) {
        world.step(kDt);
        checkAfterStep(world);
      }
      return true;
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  impulse::WorldSettings settings;
  settings.maxBodies = kMaxBodies;
  World world(settings);
  // A floor, so that contacts are part of every run.
  world.createPolygon(std::array<Vec2, 4>{Vec2(-1, -1), Vec2(26, -1), Vec2(26, 0), Vec2(-1, 0)},
                      {.properties = {.isStatic = true}});
  Calls calls(data, size);
  Made made;
  for (int call = 0; call < kMaxCalls && calls.more(); ++call) {
    const std::uint64_t before = world.stateHash();
    const int bodies = world.bodyCount();
    const int joints = world.jointCount();
    const int fields = world.fieldCount();
    if (!applyCall(world, calls, made)) {
      FUZZ_CHECK(world.stateHash() == before);
      FUZZ_CHECK(world.bodyCount() == bodies);
      FUZZ_CHECK(world.jointCount() == joints);
      FUZZ_CHECK(world.fieldCount() == fields);
    }
  }
  world.step(kDt);
  checkAfterStep(world);
  return 0;
}
