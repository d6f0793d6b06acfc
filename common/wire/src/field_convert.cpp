// Fields on the wire (docs/protocol.md, "Fields"). AddField and FieldDescriptor
// carry the same oneof of kinds under the same names, so one template per
// direction serves both. Here numbers are checked to be finite and fit a
// float; their ranges are the engine's to judge (makeField).

#include "impulse/wire/field_convert.h"

#include <cmath>
#include <type_traits>
#include <variant>

#include "wire_reader.h"

namespace impulse::wire {

namespace {

void fill(const GravitationDef& d, v1::Gravitation* out) { out->set_constant(d.constant); }

void fill(const FluidDef& d, v1::FluidRegion* out) {
  for (const Vec2& p : d.polygon) toWire(p, out->add_polygon());
  out->set_density(d.density);
  out->set_linear_drag(d.linearDrag);
  out->set_angular_drag(d.angularDrag);
  toWire(d.current, out->mutable_current());
}

void fill(const FanDef& d, v1::Fan* out) {
  toWire(d.position, out->mutable_position());
  toWire(d.direction, out->mutable_direction());
  out->set_speed(d.speed);
  out->set_range(d.range);
  out->set_spread(d.spread);
}

template <class Message>
void kindToWire(const FieldDef& def, Message* out) {
  std::visit(
      [&](const auto& d) {
        using Def = std::decay_t<decltype(d)>;
        if constexpr (std::is_same_v<Def, GravitationDef>) fill(d, out->mutable_gravitation());
        if constexpr (std::is_same_v<Def, FluidDef>) fill(d, out->mutable_fluid());
        if constexpr (std::is_same_v<Def, FanDef>) fill(d, out->mutable_fan());
      },
      def);
}

FieldDef read(Reader& r, const v1::Gravitation& m) {
  // G stays a double: the engine sums pulls in double.
  if (!std::isfinite(m.constant())) r.keep(std::string(r.prefix()) + "constant is not a finite number");
  return GravitationDef{m.constant()};
}

FieldDef read(Reader& r, const v1::FluidRegion& m) {
  FluidDef d;
  for (const v1::Vec2& p : m.polygon()) d.polygon.push_back(r.vec(p, "polygon"));
  d.density = r.real(m.density(), "density");
  d.linearDrag = r.real(m.linear_drag(), "linear_drag");
  d.angularDrag = r.real(m.angular_drag(), "angular_drag");
  d.current = r.vec(m.current(), "current");
  return d;
}

FieldDef read(Reader& r, const v1::Fan& m) {
  FanDef d;
  d.position = r.vec(m.position(), "position");
  d.direction = r.vec(m.direction(), "direction");
  d.speed = r.real(m.speed(), "speed");
  d.range = r.real(m.range(), "range");
  d.spread = r.real(m.spread(), "spread");
  return d;
}

template <class Kind>
Decoded<FieldDef> readKind(const Reader& parent, std::string_view name, const Kind& kind) {
  Reader r = parent.kind(name);
  FieldDef def = read(r, kind);
  if (!r.error().empty()) return Decoded<FieldDef>::failure(r.error());
  return Decoded<FieldDef>::success(std::move(def));
}

template <class Message>
Decoded<FieldDef> kindFromWire(const Message& m, const Reader& r) {
  switch (m.kind_case()) {
    case Message::kGravitation: return readKind(r, "gravitation", m.gravitation());
    case Message::kFluid: return readKind(r, "fluid", m.fluid());
    case Message::kFan: return readKind(r, "fan", m.fan());
    case Message::KIND_NOT_SET: break;
  }
  return Decoded<FieldDef>::failure(std::string(r.prefix()) + "kind is missing (gravitation, fluid or fan)");
}

}  // namespace

void toWire(const FieldDef& def, v1::AddField* out) { kindToWire(def, out); }

void toWire(FieldId id, const FieldDef& def, v1::FieldDescriptor* out) {
  out->set_id(id.value);
  kindToWire(def, out);
}

Decoded<FieldDef> fieldDefFromWire(const v1::AddField& command) {
  return kindFromWire(command, Reader("add_field."));
}

std::optional<FieldDef> fieldFromWire(const v1::FieldDescriptor& field) {
  Decoded<FieldDef> decoded = kindFromWire(field, Reader("field."));
  return decoded.value;
}

std::string_view fieldKindName(const FieldDef& def) {
  constexpr std::string_view kNames[] = {"gravitation", "fluid", "fan"};
  return kNames[def.index()];
}

}  // namespace impulse::wire
