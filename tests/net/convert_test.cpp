// Engine <-> wire conversion: exact one way, validated the other.
#include "impulse/wire/convert.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "impulse/wire/scene_convert.h"
#include "impulse/world.h"

namespace impulse::wire {
namespace {

TEST(Convert, RealFromWireRefusesNonFiniteAndFloatOverflow) {
  EXPECT_EQ(*realFromWire(1.5, "r").value, 1.5f);
  const auto nan = realFromWire(std::nan(""), "spawn.radius");
  ASSERT_FALSE(nan.ok());
  EXPECT_EQ(nan.error, "spawn.radius is not a finite number");
  EXPECT_FALSE(realFromWire(-std::numeric_limits<double>::infinity(), "r").ok());
  // Finite as a double, infinite as the engine's float.
  const auto huge = realFromWire(1e300, "gravity.x");
  ASSERT_FALSE(huge.ok());
  EXPECT_NE(huge.error.find("gravity.x is too large"), std::string::npos) << huge.error;
}

TEST(Convert, VecFromWireNamesTheComponent) {
  v1::Vec2 v;
  v.set_x(1);
  v.set_y(std::numeric_limits<double>::infinity());
  const auto decoded = vecFromWire(v, "center");
  ASSERT_FALSE(decoded.ok());
  EXPECT_EQ(decoded.error, "center.y is not a finite number");
}

TEST(Convert, MaterialsMapWithUnspecifiedAsSolid) {
  EXPECT_EQ(materialFromWire(v1::MATERIAL_UNSPECIFIED), Material::Solid);
  EXPECT_EQ(materialFromWire(v1::SOLID), Material::Solid);
  EXPECT_EQ(materialFromWire(v1::RUBBER), Material::Rubber);
  EXPECT_EQ(materialFromWire(v1::STONE), Material::Stone);
  EXPECT_EQ(materialFromWire(v1::FOAM), Material::Foam);
  EXPECT_FALSE(materialFromWire(9).has_value());
  EXPECT_FALSE(materialFromWire(-1).has_value());
  for (int i = 0; i < kMaterialCount; ++i) {
    const auto material = *materialFromIndex(i);
    EXPECT_EQ(materialFromWire(toWire(material)), material);
    EXPECT_EQ(materialFromName(materialName(material)), material);
  }
  EXPECT_EQ(materialFromName("ice"), Material::Ice);
  EXPECT_EQ(materialFromName("glass"), Material::Glass);
  EXPECT_FALSE(materialFromName("plastic").has_value());
}

TEST(Convert, OptionsAreCheckedFieldByField) {
  v1::BodyOptions options;
  options.set_material(v1::METAL);
  options.set_is_static(true);
  options.mutable_velocity()->set_x(2);
  const auto decoded = optionsFromWire(options);
  ASSERT_TRUE(decoded.ok()) << decoded.error;
  EXPECT_EQ(decoded.value->material, Material::Metal);
  EXPECT_TRUE(decoded.value->properties.isStatic);
  EXPECT_EQ(decoded.value->linearVelocity.x(), 2.0f);

  options.set_material(static_cast<v1::Material>(9));
  EXPECT_NE(optionsFromWire(options).error.find("material 9 is not a material"), std::string::npos);
  options.set_material(v1::SOLID);
  options.set_angular_velocity(std::numeric_limits<float>::quiet_NaN());
  EXPECT_EQ(optionsFromWire(options).error, "options.angular_velocity is not a finite number");
}

TEST(Convert, PerBodyPropertiesDecodeAndNameTheirField) {
  v1::BodyOptions options;
  const auto plain = optionsFromWire(options);
  ASSERT_TRUE(plain.ok()) << plain.error;
  EXPECT_FALSE(plain.value->materialOverride.density) << "unset: the material's";
  EXPECT_FALSE(plain.value->materialOverride.staticFriction);
  EXPECT_EQ(plain.value->properties.gravityScale, 1);

  options.set_density(250);
  options.set_friction(0.5);
  options.set_restitution(0.25);
  options.set_linear_damping(2);
  options.set_angular_damping(3);
  options.set_gravity_scale(0);
  const auto given = optionsFromWire(options);
  ASSERT_TRUE(given.ok()) << given.error;
  const MaterialOverride& o = given.value->materialOverride;
  EXPECT_EQ(o.density, 250.0f);
  EXPECT_EQ(o.staticFriction, 0.5f) << "friction sets both";
  EXPECT_EQ(o.dynamicFriction, 0.5f);
  EXPECT_EQ(o.restitution, 0.25f);
  EXPECT_EQ(given.value->properties.linearDrag, 2.0f);
  EXPECT_EQ(given.value->properties.angularDrag, 3.0f);
  EXPECT_EQ(given.value->properties.gravityScale, 0.0f) << "set to 0, not the unset 1";

  options.set_gravity_scale(std::numeric_limits<double>::infinity());
  EXPECT_EQ(optionsFromWire(options).error, "options.gravity_scale is not a finite number");
  options.set_gravity_scale(1);
  options.set_angular_damping(1e300);
  EXPECT_EQ(optionsFromWire(options).error.rfind("options.angular_damping is too large", 0), 0u);
}

TEST(Convert, DescriptorCarriesThePropertiesInForce) {
  BodyDescription description;
  description.id = BodyId{7};
  description.shape = Shape::makeCircle(0.5f);
  description.material = Material::Glass;
  description.density = 123.5f;
  description.restitution = 0.75f;
  description.staticFriction = 0.5f;
  description.dynamicFriction = 0.25f;
  description.properties.linearDrag = 1.5f;
  description.properties.angularDrag = 0.125f;
  description.properties.gravityScale = -2;
  v1::BodyDescriptor descriptor;
  toWire(description, &descriptor);
  EXPECT_EQ(descriptor.material(), v1::GLASS);
  EXPECT_EQ(descriptor.density(), 123.5);
  EXPECT_EQ(descriptor.restitution(), 0.75);
  EXPECT_EQ(descriptor.static_friction(), 0.5);
  EXPECT_EQ(descriptor.dynamic_friction(), 0.25);
  EXPECT_EQ(descriptor.linear_damping(), 1.5);
  EXPECT_EQ(descriptor.angular_damping(), 0.125);
  EXPECT_EQ(descriptor.gravity_scale(), -2);
}

TEST(Convert, StateRoundTripIsExact) {
  BodyState state;
  state.id = BodyId{12345};
  state.position = Vec2(0.1f, -7.3f);
  state.angle = 2.7182817f;
  state.linearVelocity = Vec2(1e-7f, 3e5f);
  state.angularVelocity = -0.333333f;
  state.awake = true;
  v1::BodyState message;
  toWire(state, &message);
  const BodyState back = stateFromWire(message);
  EXPECT_EQ(back.id, state.id);
  EXPECT_EQ(back.position, state.position);
  EXPECT_EQ(back.angle, state.angle);
  EXPECT_EQ(back.linearVelocity, state.linearVelocity);
  EXPECT_EQ(back.angularVelocity, state.angularVelocity);
  EXPECT_EQ(back.awake, state.awake);
}

TEST(Convert, PolygonShapeRoundTripKeepsVerticesAndNormals) {
  const Shape box = Shape::makePolygon(makeRegularPolygon(6, 0.75f));
  v1::Shape message;
  toWire(box, &message);
  ASSERT_EQ(message.polygon().vertices_size(), 6);
  const auto back = shapeFromWire(message);
  ASSERT_TRUE(back.ok()) << back.error;
  ASSERT_EQ(back.value->type(), ShapeType::Polygon);
  ASSERT_EQ(back.value->polygon().count, 6);
  for (int i = 0; i < 6; ++i) {
    EXPECT_EQ(back.value->polygon().vertices[i], box.polygon().vertices[i]);
    EXPECT_NEAR(back.value->polygon().normals[i].x(), box.polygon().normals[i].x(), 1e-6);
    EXPECT_NEAR(back.value->polygon().normals[i].y(), box.polygon().normals[i].y(), 1e-6);
  }
}

TEST(Convert, ShapeFromWireRefusesBadVertexCountsAndEmptyShapes) {
  v1::Shape message;
  EXPECT_FALSE(shapeFromWire(message).ok());
  for (int i = 0; i < 17; ++i) message.mutable_polygon()->add_vertices();
  EXPECT_NE(shapeFromWire(message).error.find("17 vertices"), std::string::npos);
}

TEST(Convert, PresetInfoRoundTrip) {
  PresetInfo preset;
  preset.id = 3;
  preset.title = "Polygon tutorial";
  preset.explanation = {"Place three points", "then press P"};
  preset.markers = {{Vec2(1, 2), 0.25f}};
  preset.drawingAllowed = true;
  v1::PresetInfo message;
  toWire(preset, &message);
  const PresetInfo back = presetFromWire(message);
  EXPECT_EQ(back.id, 3);
  EXPECT_EQ(back.title, preset.title);
  EXPECT_EQ(back.explanation, preset.explanation);
  ASSERT_EQ(back.markers.size(), 1u);
  EXPECT_EQ(back.markers[0].center, Vec2(1, 2));
  EXPECT_EQ(back.markers[0].radius, 0.25f);
  EXPECT_TRUE(back.drawingAllowed);
}

// Every joint kind, with every value set, survives engine -> CreateJoint ->
// engine -> JointDescriptor -> engine unchanged.
TEST(Convert, EveryJointKindRoundTrips) {
  RevoluteJointSettings revolute{true, -0.5f, 0.75f, true, 2, 30, 4, 0.5f};
  PrismaticJointSettings prismatic{Vec2(0.6f, 0.8f), true, -1, 2, true, 3, 40, 5, 0.25f};
  WheelJointSettings wheel{Vec2(0, 1), 800, 20, true, -6, 90};
  const std::vector<JointSettings> kinds = {
      DistanceJointSettings{1.5f, 200, 3}, RopeJointSettings{2.5f}, revolute, prismatic,
      WeldJointSettings{1000, 50},        wheel,                   MouseJointSettings{500, 80, 9}};
  for (const JointSettings& settings : kinds) {
    v1::CreateJoint command;
    command.set_body_a(7);
    toWire(Vec2(1, 2), command.mutable_anchor_a());
    toWire(settings, &command);
    const auto def = jointDefFromWire(command);
    ASSERT_TRUE(def.ok()) << def.error;
    JointDescription description;
    description.settings = def.value->settings;
    v1::JointDescriptor descriptor;
    toWire(description, &descriptor);
    v1::CreateJoint again;
    const auto back = jointFromWire(descriptor);
    ASSERT_TRUE(back.has_value());
    again.set_body_a(7);
    toWire(Vec2(1, 2), again.mutable_anchor_a());
    toWire(back->settings, &again);
    EXPECT_EQ(again.SerializeAsString(), command.SerializeAsString()) << jointKindName(settings);
  }
}

TEST(Convert, JointDefFromWireNamesTheBadField) {
  v1::CreateJoint command;
  command.mutable_wheel()->mutable_axis()->set_y(std::nan(""));
  EXPECT_EQ(jointDefFromWire(command).error, "create_joint.wheel.axis.y is not a finite number");
  command.mutable_revolute()->set_max_motor_torque(1e300);
  EXPECT_TRUE(jointDefFromWire(command).error.starts_with(
      "create_joint.revolute.max_motor_torque is too large"));
  command.clear_kind();
  EXPECT_TRUE(jointDefFromWire(command).error.starts_with("create_joint.kind: none of"));
  v1::UpdateJoint update;
  update.mutable_target()->set_x(std::nan(""));
  EXPECT_EQ(jointUpdateFromWire(update).error, "update_joint.target.x is not a finite number");
  update.clear_target();
  EXPECT_FALSE(jointUpdateFromWire(update).value->motorSpeed.has_value());
}

// A saved scene carries the world's origin; one saved before origins (no
// field) loads at (0, 0) with every position as saved.
TEST(Convert, SceneCarriesTheWorldOrigin_OneWithoutLoadsAtZero) {
  World original;
  ASSERT_TRUE(original.shiftOrigin(Vec2d(100000, -80000)).ok());
  ASSERT_TRUE(original.createCircle(Vec2(1, 2), Real(0.5)).ok());
  original.step(Real(1) / 60);
  const std::string bytes = saveScene(original);

  World loaded;
  ASSERT_TRUE(loadScene(loaded, bytes).ok());
  EXPECT_EQ(loaded.origin(), original.origin());
  EXPECT_EQ(loaded.stateHash(), original.stateHash());

  v1::Scene withoutOrigin;
  ASSERT_TRUE(withoutOrigin.ParseFromString(bytes));
  withoutOrigin.clear_origin();
  World old;
  ASSERT_TRUE(loadScene(old, withoutOrigin.SerializeAsString()).ok());
  EXPECT_EQ(old.origin(), Vec2d::Zero());
  EXPECT_EQ(old.stateHash(), original.stateHash());
}

}  // namespace
}  // namespace impulse::wire
