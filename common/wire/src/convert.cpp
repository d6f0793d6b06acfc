#include "impulse/wire/convert.h"

#include <array>
#include <cctype>
#include <cmath>
#include <limits>

#include "body_properties.h"

namespace impulse::wire {

namespace {

constexpr std::array<std::string_view, kMaterialCount> kMaterialNames = {
    "SOLID", "ICE", "WOOD", "METAL", "RUBBER", "STONE", "GLASS", "FOAM"};

std::string joinName(std::string_view what, std::string_view field) {
  std::string name(what);
  name += '.';
  name += field;
  return name;
}

}  // namespace

void toWire(const Vec2& v, v1::Vec2* out) {
  out->set_x(v.x());
  out->set_y(v.y());
}

v1::Material toWire(Material material) {
  return static_cast<v1::Material>(static_cast<int>(material) + 1);
}

v1::BodyType toWire(BodyType type) {
  switch (type) {
    case BodyType::Static: return v1::BODY_TYPE_STATIC;
    case BodyType::Kinematic: return v1::BODY_TYPE_KINEMATIC;
    case BodyType::Dynamic: return v1::BODY_TYPE_DYNAMIC;
  }
  return v1::BODY_TYPE_UNSPECIFIED;
}

void toWire(const Segment& segment, v1::Segment* out) {
  toWire(segment.point1, out->mutable_point1());
  toWire(segment.point2, out->mutable_point2());
}

void toWire(const Shape& shape, v1::Shape* out) {
  switch (shape.type()) {
    case ShapeType::Circle:
      out->mutable_circle()->set_radius(shape.circle().radius);
      // Left unset at the centre, as a one-shape body's circle always is.
      if (shape.circle().center != Vec2::Zero()) toWire(shape.circle().center, out->mutable_circle()->mutable_center());
      return;
    case ShapeType::Polygon: {
      auto* polygon = out->mutable_polygon();
      polygon->mutable_vertices()->Reserve(shape.polygon().count);
      for (int i = 0; i < shape.polygon().count; ++i) {
        toWire(shape.polygon().vertices[std::size_t(i)], polygon->add_vertices());
      }
      polygon->set_radius(shape.polygon().radius);
      return;
    }
    case ShapeType::Capsule:
      toWire(shape.capsule().center1, out->mutable_capsule()->mutable_center1());
      toWire(shape.capsule().center2, out->mutable_capsule()->mutable_center2());
      out->mutable_capsule()->set_radius(shape.capsule().radius);
      return;
    case ShapeType::Segment: toWire(shape.segment(), out->mutable_segment()); return;
    case ShapeType::ChainSegment:
      toWire(shape.chainSegment().ghost1, out->mutable_chain_segment()->mutable_ghost1());
      toWire(shape.chainSegment().segment, out->mutable_chain_segment()->mutable_segment());
      toWire(shape.chainSegment().ghost2, out->mutable_chain_segment()->mutable_ghost2());
      return;
  }
}

void toWire(const BodyState& state, v1::BodyState* out) {
  out->set_id(state.id.value);
  toWire(state.position, out->mutable_position());
  out->set_angle(state.angle);
  toWire(state.linearVelocity, out->mutable_velocity());
  out->set_angular_velocity(state.angularVelocity);
  out->set_awake(state.awake);
}

void toWire(const BodyDescription& description, v1::BodyDescriptor* out) {
  out->set_id(description.id.value);
  toWire(description.shape, out->mutable_shape());
  out->set_material(toWire(description.material));
  putBodyProperties(description.properties, *out);
  putCoefficients(description, *out);
  for (std::size_t i = 1; i < description.shapes.size(); ++i) {
    toWire(description.shapes[i].shape, out->add_extra_shapes());
  }
  // A description built by hand may list no shapes: the first shape's flags
  // are then the defaults.
  toWire(description.shapes.empty() ? ShapeInteraction{} : description.shapes.front().interaction,
         out->mutable_shape_flags());
  for (const ShapeDescription& shape : description.shapes) out->add_shape_ids(shape.id.value);
}

void toWire(const ShapeInteraction& interaction, v1::ShapeFlags* out) {
  auto* filter = out->mutable_filter();
  filter->set_category_bits(interaction.filter.categoryBits);
  filter->set_mask_bits(interaction.filter.maskBits);
  filter->set_group_index(interaction.filter.groupIndex);
  out->set_is_sensor(interaction.isSensor);
  out->set_contact_events(interaction.enableContactEvents);
  out->set_hit_events(interaction.enableHitEvents);
  out->set_sensor_events(interaction.enableSensorEvents);
}

ShapeInteraction shapeFlagsFromWire(const v1::ShapeFlags& flags) {
  ShapeInteraction interaction;
  const v1::ShapeFilter& filter = flags.filter();
  if (filter.has_category_bits()) interaction.filter.categoryBits = filter.category_bits();
  if (filter.has_mask_bits()) interaction.filter.maskBits = filter.mask_bits();
  interaction.filter.groupIndex = filter.group_index();
  interaction.isSensor = flags.is_sensor();
  interaction.enableContactEvents = flags.contact_events();
  interaction.enableHitEvents = flags.hit_events();
  interaction.enableSensorEvents = !flags.has_sensor_events() || flags.sensor_events();
  return interaction;
}

void toWire(const PresetInfo& preset, v1::PresetInfo* out) {
  out->set_id(preset.id);
  out->set_title(preset.title);
  for (const auto& line : preset.explanation) out->add_explanation(line);
  for (const auto& marker : preset.markers) {
    auto* m = out->add_markers();
    toWire(marker.center, m->mutable_center());
    m->set_radius(marker.radius);
  }
  out->set_drawing_allowed(preset.drawingAllowed);
}

void toWire(const BodyDescription& description, const BodyState& state, v1::BodyInfo* out) {
  toWire(description, out->mutable_descriptor());
  toWire(state, out->mutable_state());
  out->set_mass(description.mass.mass);
  out->set_inertia(description.mass.inertia);
  out->set_area(description.mass.area);
  putBodyProperties(description.properties, *out);
  putCoefficients(description, *out);
}

Decoded<Real> realFromWire(double value, std::string_view what) {
  if (!std::isfinite(value)) {
    return Decoded<Real>::failure(std::string(what) + " is not a finite number");
  }
  if (std::abs(value) > double(std::numeric_limits<Real>::max())) {
    return Decoded<Real>::failure(std::string(what) + " is too large (" + std::to_string(value) +
                                  ")");
  }
  return Decoded<Real>::success(Real(value));
}

Decoded<Vec2> vecFromWire(const v1::Vec2& v, std::string_view what) {
  auto x = realFromWire(v.x(), joinName(what, "x"));
  if (!x.ok()) return Decoded<Vec2>::failure(std::move(x.error));
  auto y = realFromWire(v.y(), joinName(what, "y"));
  if (!y.ok()) return Decoded<Vec2>::failure(std::move(y.error));
  return Decoded<Vec2>::success(Vec2(*x.value, *y.value));
}

std::optional<Material> materialFromWire(int material) {
  if (material == v1::MATERIAL_UNSPECIFIED) return Material::Solid;
  // Checked before subtracting: the wire may carry INT_MIN, and INT_MIN - 1
  // overflows.
  if (material < 0) return std::nullopt;
  return materialFromIndex(material - 1);
}

std::optional<BodyType> bodyTypeFromWire(int type) {
  switch (type) {
    case v1::BODY_TYPE_STATIC: return BodyType::Static;
    case v1::BODY_TYPE_KINEMATIC: return BodyType::Kinematic;
    case v1::BODY_TYPE_DYNAMIC: return BodyType::Dynamic;
    default: return std::nullopt;
  }
}

std::string materialRange() {
  return "(0-" + std::to_string(kMaterialCount) + ")";
}

namespace {

// An optional wire number into an optional Real, checked as realFromWire.
std::string optionalFromWire(bool present, double value, std::string_view what,
                             std::optional<Real>& out) {
  if (!present) return {};
  auto real = realFromWire(value, what);
  if (!real.ok()) return std::move(real.error);
  out = *real.value;
  return {};
}

// The material overrides (docs/protocol.md) checked for finiteness here;
// their ranges are the engine's to judge (World::createBody names the field).
std::string overridesFromWire(const v1::BodyOptions& options, MaterialOverride& o) {
  std::optional<Real> friction;
  for (std::string error :
       {optionalFromWire(options.has_density(), options.density(), "options.density", o.density),
        optionalFromWire(options.has_friction(), options.friction(), "options.friction", friction),
        optionalFromWire(options.has_restitution(), options.restitution(), "options.restitution",
                         o.restitution)}) {
    if (!error.empty()) return error;
  }
  o.staticFriction = friction;
  o.dynamicFriction = friction;
  return {};
}

}  // namespace

Decoded<BodyOptions> optionsFromWire(const v1::BodyOptions& options) {
  BodyOptions result;
  const auto material = materialFromWire(options.material());
  if (!material) {
    return Decoded<BodyOptions>::failure("options.material " + std::to_string(options.material()) +
                                         " is not a material " + materialRange());
  }
  result.material = *material;
  result.isAwake = !options.has_is_awake() || options.is_awake();
  auto velocity = vecFromWire(options.velocity(), "options.velocity");
  if (!velocity.ok()) return Decoded<BodyOptions>::failure(std::move(velocity.error));
  result.linearVelocity = *velocity.value;
  auto angular = realFromWire(options.angular_velocity(), "options.angular_velocity");
  if (!angular.ok()) return Decoded<BodyOptions>::failure(std::move(angular.error));
  result.angularVelocity = *angular.value;
  for (std::string error :
       {getOptionProperties(options, result.properties), overridesFromWire(options, result.materialOverride)}) {
    if (!error.empty()) return Decoded<BodyOptions>::failure(std::move(error));
  }
  result.interaction = shapeFlagsFromWire(options.shape_flags());
  return Decoded<BodyOptions>::success(result);
}

namespace {

Decoded<Shape> polygonFromWire(const v1::Polygon& wire) {
  const auto& vertices = wire.vertices();
  if (vertices.size() < kMinPolygonVertices || vertices.size() > kMaxPolygonVertices) {
    return Decoded<Shape>::failure("shape.polygon has " + std::to_string(vertices.size()) + " vertices (3-16 allowed)");
  }
  Polygon polygon;
  polygon.count = vertices.size();
  for (int i = 0; i < polygon.count; ++i) {
    auto v = vecFromWire(vertices[i], "shape.polygon.vertex");
    if (!v.ok()) return Decoded<Shape>::failure(std::move(v.error));
    polygon.vertices[std::size_t(i)] = *v.value;
  }
  for (int i = 0; i < polygon.count; ++i) {
    const Vec2 edge = polygon.vertices[std::size_t((i + 1) % polygon.count)] - polygon.vertices[std::size_t(i)];
    const Real length = edge.norm();
    polygon.normals[std::size_t(i)] = length > 0 ? Vec2(rightPerp(edge) / length) : Vec2(Vec2::Zero());
  }
  auto radius = realFromWire(wire.radius(), "shape.polygon.radius");
  if (!radius.ok()) return Decoded<Shape>::failure(std::move(radius.error));
  polygon.radius = *radius.value;
  polygon.centroid = computePolygonCentroid(polygon);
  return Decoded<Shape>::success(Shape::makePolygon(polygon));
}

// Every vector of a shape message decoded, or the first error.
struct ShapePoints {
  std::vector<Vec2> points;
  std::string error;
  bool ok() const { return error.empty(); }
};

ShapePoints pointsFromWire(std::initializer_list<std::pair<const v1::Vec2*, const char*>> fields) {
  ShapePoints out;
  for (const auto& [vector, name] : fields) {
    auto v = vecFromWire(*vector, name);
    if (!v.ok()) return {{}, std::move(v.error)};
    out.points.push_back(*v.value);
  }
  return out;
}

}  // namespace

Decoded<Shape> shapeFromWire(const v1::Shape& shape) {
  switch (shape.kind_case()) {
    case v1::Shape::kCircle: {
      auto radius = realFromWire(shape.circle().radius(), "shape.circle.radius");
      if (!radius.ok()) return Decoded<Shape>::failure(std::move(radius.error));
      ShapePoints center = pointsFromWire({{&shape.circle().center(), "shape.circle.center"}});
      if (!center.ok()) return Decoded<Shape>::failure(std::move(center.error));
      return Decoded<Shape>::success(Shape::makeCircle(*radius.value, center.points[0]));
    }
    case v1::Shape::kPolygon: return polygonFromWire(shape.polygon());
    case v1::Shape::kCapsule: {
      const v1::Capsule& capsule = shape.capsule();
      auto radius = realFromWire(capsule.radius(), "shape.capsule.radius");
      if (!radius.ok()) return Decoded<Shape>::failure(std::move(radius.error));
      ShapePoints ends = pointsFromWire({{&capsule.center1(), "shape.capsule.center1"},
                                         {&capsule.center2(), "shape.capsule.center2"}});
      if (!ends.ok()) return Decoded<Shape>::failure(std::move(ends.error));
      return Decoded<Shape>::success(Shape::makeCapsule(ends.points[0], ends.points[1], *radius.value));
    }
    case v1::Shape::kSegment: {
      ShapePoints ends = pointsFromWire({{&shape.segment().point1(), "shape.segment.point1"},
                                         {&shape.segment().point2(), "shape.segment.point2"}});
      if (!ends.ok()) return Decoded<Shape>::failure(std::move(ends.error));
      return Decoded<Shape>::success(Shape::makeSegment(ends.points[0], ends.points[1]));
    }
    case v1::Shape::kChainSegment: {
      const v1::ChainSegment& chain = shape.chain_segment();
      ShapePoints points = pointsFromWire({{&chain.ghost1(), "shape.chain_segment.ghost1"},
                                           {&chain.segment().point1(), "shape.chain_segment.segment.point1"},
                                           {&chain.segment().point2(), "shape.chain_segment.segment.point2"},
                                           {&chain.ghost2(), "shape.chain_segment.ghost2"}});
      if (!points.ok()) return Decoded<Shape>::failure(std::move(points.error));
      return Decoded<Shape>::success(
          Shape{ChainSegment{points.points[0], {points.points[1], points.points[2]}, points.points[3]}});
    }
    case v1::Shape::KIND_NOT_SET:
      break;
  }
  return Decoded<Shape>::failure("shape has no kind (circle, polygon, capsule, segment or chain_segment)");
}

Vec2 vecFromWireUnchecked(const v1::Vec2& v) { return Vec2(Real(v.x()), Real(v.y())); }

BodyState stateFromWire(const v1::BodyState& state) {
  BodyState result;
  result.id = BodyId{state.id()};
  result.position = vecFromWireUnchecked(state.position());
  result.angle = Real(state.angle());
  result.linearVelocity = vecFromWireUnchecked(state.velocity());
  result.angularVelocity = Real(state.angular_velocity());
  result.awake = state.awake();
  return result;
}

PresetInfo presetFromWire(const v1::PresetInfo& preset) {
  PresetInfo result;
  result.id = preset.id();
  result.title = preset.title();
  result.explanation.assign(preset.explanation().begin(), preset.explanation().end());
  for (const auto& marker : preset.markers()) {
    result.markers.push_back({vecFromWireUnchecked(marker.center()), Real(marker.radius())});
  }
  result.drawingAllowed = preset.drawing_allowed();
  return result;
}

std::string_view materialName(Material material) {
  return kMaterialNames[static_cast<std::size_t>(material)];
}

std::optional<Material> materialFromName(std::string_view name) {
  for (std::size_t i = 0; i < kMaterialNames.size(); ++i) {
    const auto candidate = kMaterialNames[i];
    if (candidate.size() != name.size()) continue;
    bool same = true;
    for (std::size_t c = 0; c < name.size() && same; ++c) {
      same = std::toupper(static_cast<unsigned char>(name[c])) == candidate[c];
    }
    if (same) return materialFromIndex(int(i));
  }
  return std::nullopt;
}

}  // namespace impulse::wire
