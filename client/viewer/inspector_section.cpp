#include <algorithm>
#include <array>
#include <cinttypes>
#include <cstdio>
#include <numbers>
#include <vector>

#include "body_metrics.h"
#include "impulse/client/commands.h"
#include "impulse/client/number_format.h"
#include "impulse/wire/convert.h"
#include "side_panel.h"

namespace impulse::viewer {

namespace {

using client::formatNumber;

std::string vec(const Vec2d& v, int decimals) {
  std::string text = "(";
  text += formatNumber(v.x(), decimals);
  text += ", ";
  text += formatNumber(v.y(), decimals);
  return text += ")";
}

std::string vec(const v1::Vec2& v, int decimals) { return vec(Vec2d(v.x(), v.y()), decimals); }

std::string yesNo(bool value) { return value ? "yes" : "no"; }

// The body's shapes, decoded; the error of the first that cannot be.
struct BodyShapes {
  std::vector<Shape> shapes;
  std::string error;
};

BodyShapes shapesOf(const v1::BodyDescriptor& d) {
  BodyShapes out;
  for (int i = 0; i <= d.extra_shapes_size(); ++i) {
    const auto decoded = wire::shapeFromWire(i == 0 ? d.shape() : d.extra_shapes(i - 1));
    if (!decoded.ok()) return {{}, "unreadable: " + decoded.error};
    out.shapes.push_back(*decoded.value);
  }
  return out;
}

void row(const char* name, const std::string& value) {
  ImGui::TableNextRow();
  ImGui::TableNextColumn();
  ImGui::TextDisabled("%s", name);
  ImGui::TableNextColumn();
  ImGui::TextWrapped("%s", value.c_str());
}

// One row for a single shape; for several, a summary and then the first
// few one row each (a chain's fifty segments would push the rest away).
void drawShapeRows(const v1::BodyDescriptor& d) {
  constexpr std::size_t kListed = 6;
  const BodyShapes body = shapesOf(d);
  if (!body.error.empty()) return row("shape", body.error);
  if (body.shapes.size() == 1) return row("shape", describeShape(body.shapes.front()));
  row("shapes", describeShapes(body.shapes));
  for (std::size_t i = 0; i < std::min(body.shapes.size(), kListed); ++i) {
    row(("  " + std::to_string(i + 1)).c_str(), describeShape(body.shapes[i]));
  }
  if (body.shapes.size() > kListed) row("", "and " + std::to_string(body.shapes.size() - kListed) + " more");
}

std::string hex(std::uint64_t bits) {
  char text[24];
  std::snprintf(text, sizeof text, "0x%" PRIX64, bits);
  return text;
}

std::string describeFilter(const CollisionFilter& filter) {
  return "category " + hex(filter.categoryBits) + ", mask " + hex(filter.maskBits) + ", group " +
         std::to_string(filter.groupIndex);
}

// The flags that are on, in words; "none" when none is.
std::string describeFlags(const ShapeInteraction& flags) {
  std::string text;
  const auto add = [&](bool on, const char* name) {
    if (!on) return;
    if (!text.empty()) text += ", ";
    text += name;
  };
  add(flags.isSensor, "sensor");
  add(flags.enableSensorEvents, "sensor events");
  add(flags.enableContactEvents, "contact events");
  add(flags.enableHitEvents, "hit events");
  return text.empty() ? "none" : text;
}

// The ids events and queries name the shapes by, the first few of a long list.
std::string describeShapeIds(const v1::BodyDescriptor& d) {
  constexpr int kListed = 6;
  std::string text;
  for (int i = 0; i < std::min(d.shape_ids_size(), kListed); ++i) {
    if (i > 0) text += ", ";
    text += std::to_string(d.shape_ids(i));
  }
  if (d.shape_ids_size() > kListed) text += ", ... (" + std::to_string(d.shape_ids_size()) + ")";
  return text;
}

// The body's position from (0, 0): the reply's is from the room's origin.
Vec2d absolutePosition(const v1::BodyInfo& info, const Vec2d& origin) {
  return origin + Vec2d(info.state().position().x(), info.state().position().y());
}

void drawBodyTable(const v1::BodyInfo& info, const Vec2d& origin) {
  const auto& d = info.descriptor();
  const auto& s = info.state();
  const auto material = wire::materialFromWire(d.material()).value_or(Material::Solid);
  const double degrees = s.angle() * 180 / std::numbers::pi;
  if (!ImGui::BeginTable("body", 2, ImGuiTableFlags_SizingStretchProp)) return;
  row("id", std::to_string(d.id()));
  drawShapeRows(d);
  row("material", materialLabel(material));
  row("type", d.is_static() ? "static" : d.is_kinematic() ? "kinematic" : "dynamic");
  row("awake", yesNo(s.awake()));
  row("gravity", d.ignore_gravity() ? "ignored" : "felt");
  row("position", vec(absolutePosition(info, origin), 3) + " m");
  row("angle", formatNumber(degrees, 1) + " deg (" + formatNumber(s.angle(), 3) + " rad)");
  row("velocity", vec(s.velocity(), 3) + " m/s");
  row("angular vel.", formatNumber(s.angular_velocity(), 3) + " rad/s");
  row("mass", formatNumber(info.mass(), 3) + " kg");
  row("inertia", formatNumber(info.inertia(), 4) + " kg m2");
  row("area", formatNumber(info.area(), 4) + " m2");
  row("restitution", formatNumber(info.restitution(), 3));
  row("friction", "static " + formatNumber(info.static_friction(), 3) + ", dynamic " +
                      formatNumber(info.dynamic_friction(), 3));
  row("density", formatNumber(info.density(), 3) + " kg/m2");
  row("damping", "linear " + formatNumber(info.linear_damping(), 3) + ", angular " +
                     formatNumber(info.angular_damping(), 3) + " 1/s");
  row("gravity scale", formatNumber(info.gravity_scale(), 3));
  ImGui::EndTable();
}

// Three of the body's figures in one row of fields, `current` unless a
// person is typing in them (the server's figures, five a second, would
// overwrite the typing). Clicking a field selects its text, so typing
// replaces it. True when Enter was pressed: `edit.values` are then sent.
// Doubles: a position 83 km from (0, 0) keeps its millimetres.
bool editFields(const char* id, FieldsEdit& edit, std::uint32_t body, const std::array<double, 3>& current) {
  if (edit.body != body || !edit.editing) edit = {body, {current[0], current[1], current[2]}, false};
  ImGui::SetNextItemWidth(-FLT_MIN);
  const bool entered =
      ImGui::InputScalarN(id, ImGuiDataType_Double, edit.values, 3, nullptr, nullptr, "%.3f",
                          ImGuiInputTextFlags_EnterReturnsTrue | ImGuiInputTextFlags_AutoSelectAll);
  edit.editing = ImGui::IsItemActive();
  return entered;
}

// Position (from (0, 0)) and angle: Enter moves the body there at once
// (SetTransform). The command goes out in the mirror's frame, from the
// room's origin, as every command of the viewer does: the link adds it back.
void drawPoseEditor(const v1::BodyInfo& info, const Vec2d& origin, const PanelActions& actions,
                    PanelState& state) {
  const std::uint32_t id = info.descriptor().id();
  const Vec2d position = absolutePosition(info, origin);
  const double degrees = info.state().angle() * 180 / std::numbers::pi;
  ImGui::TextDisabled("set x, y (m), angle (deg); Enter moves it:");
  if (editFields("##pose", state.poseEdit, id, {position.x(), position.y(), degrees})) {
    const FieldsEdit& edit = state.poseEdit;
    const Vec2d target = Vec2d(edit.values[0], edit.values[1]) - origin;
    actions.send(client::setTransform(id, {target.x(), target.y()}, edit.values[2] * std::numbers::pi / 180),
                 "move");
  }
  if (ImGui::IsItemVisible()) state.poseFields = lastItemRect();
}

// Velocity and angular velocity: Enter sends them (SetVelocity), Stop
// sends zeros.
void drawVelocityEditor(const v1::BodyInfo& info, const PanelActions& actions, PanelState& state) {
  const std::uint32_t id = info.descriptor().id();
  const auto& s = info.state();
  const auto send = [&](double vx, double vy, double angular) {
    actions.send(client::setVelocity(id, {vx, vy}, angular), "velocity");
  };
  ImGui::TextDisabled("set vx, vy (m/s), angular (rad/s); Enter sends:");
  if (editFields("##velocity", state.velocityEdit, id,
                 {s.velocity().x(), s.velocity().y(), s.angular_velocity()})) {
    const FieldsEdit& edit = state.velocityEdit;
    send(edit.values[0], edit.values[1], edit.values[2]);
  }
  if (ImGui::Button("Stop")) send(0, 0, 0);
  if (ImGui::IsItemVisible()) state.stopButton = lastItemRect();
}

// The material (SetMaterial: the body's mass follows) and the type
// (SetBodyType), each a click away.
void drawMaterialAndType(const v1::BodyInfo& info, const PanelActions& actions, PanelState& state) {
  const auto& d = info.descriptor();
  const std::uint32_t id = d.id();
  const Material material = wire::materialFromWire(d.material()).value_or(Material::Solid);
  ImGui::SetNextItemWidth(ImGui::CalcTextSize("RUBBER").x + ImGui::GetFrameHeight() * 2);
  if (ImGui::BeginCombo("material##edit", materialLabel(material).c_str())) {
    for (int index = 0; index < kMaterialCount; ++index) {
      const Material choice = *materialFromIndex(index);
      if (ImGui::Selectable(materialLabel(choice).c_str(), choice == material) && choice != material) {
        actions.send(client::setMaterial(id, choice), "material");
      }
    }
    ImGui::EndCombo();
  }
  constexpr std::array<std::pair<BodyType, const char*>, 3> kTypes{
      {{BodyType::Static, "static"}, {BodyType::Kinematic, "kinematic"}, {BodyType::Dynamic, "dynamic"}}};
  const BodyType current = d.is_static() ? BodyType::Static : d.is_kinematic() ? BodyType::Kinematic : BodyType::Dynamic;
  for (std::size_t i = 0; i < kTypes.size(); ++i) {
    const auto [type, label] = kTypes[i];
    if (i > 0) sameLineIfFits(ImGui::CalcTextSize(label).x + ImGui::GetFrameHeight() * 1.5f);
    if (ImGui::RadioButton(label, type == current) && type != current) {
      actions.send(client::setBodyType(id, type), "body type");
    }
    if (ImGui::IsItemVisible()) state.typeButtons[i] = lastItemRect();
  }
}

// The shapes' ids, filter and flags, then the flags as check boxes: a click
// sends the body's flags with that one changed (SetShapeFlags, every shape
// of the body). Last in the inspector: set less often than the rest.
void drawFilterAndFlags(const v1::BodyInfo& info, const PanelActions& actions, PanelState& state) {
  const auto& d = info.descriptor();
  const std::uint32_t id = d.id();
  // A body made over the wire gives every shape the first one's flags.
  const ShapeInteraction current = wire::shapeFlagsFromWire(d.shape_flags());
  if (ImGui::BeginTable("filter", 2, ImGuiTableFlags_SizingStretchProp)) {
    row("shape ids", describeShapeIds(d));
    row("filter", describeFilter(current.filter));
    row("flags", describeFlags(current));
    ImGui::EndTable();
  }
  const std::array<std::pair<const char*, bool ShapeInteraction::*>, 4> kFlags{{
      {"sensor", &ShapeInteraction::isSensor},
      {"sensor events", &ShapeInteraction::enableSensorEvents},
      {"contact events", &ShapeInteraction::enableContactEvents},
      {"hit events", &ShapeInteraction::enableHitEvents},
  }};
  ImGui::TextDisabled("shape flags; a click sets them:");
  for (std::size_t i = 0; i < kFlags.size(); ++i) {
    const auto [label, member] = kFlags[i];
    ShapeInteraction wanted = current;
    if (i > 0) sameLineIfFits(ImGui::CalcTextSize(label).x + ImGui::GetFrameHeight() * 1.5f);
    if (ImGui::Checkbox(label, &(wanted.*member))) actions.send(client::setShapeFlags(id, wanted), "shape flags");
    if (ImGui::IsItemVisible()) state.flagBoxes[i] = lastItemRect();
  }
}

}  // namespace

void drawInspectorSection(const Controls& controls, const PanelInput& input,
                          const PanelActions& actions, PanelState& state) {
  if (!controls.selectedBody()) {
    ImGui::TextDisabled("click a body to select it");
    return;
  }
  if (input.inspected == nullptr) {
    ImGui::Text("body %u: waiting for the server...", *controls.selectedBody());
    return;
  }
  drawBodyTable(*input.inspected, input.origin);
  drawPoseEditor(*input.inspected, input.origin, actions, state);
  if (!input.inspected->descriptor().is_static()) drawVelocityEditor(*input.inspected, actions, state);
  drawMaterialAndType(*input.inspected, actions, state);
  ImGui::TextDisabled("arrows push it, Delete removes it");
  drawFilterAndFlags(*input.inspected, actions, state);
}

}  // namespace impulse::viewer
