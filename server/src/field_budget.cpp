#include "impulse/server/field_budget.h"

#include <variant>

namespace impulse::server {

namespace {

const char* kindName(const FieldDef& def) {
  if (std::holds_alternative<GravitationDef>(def)) return "a gravitation field";
  if (std::holds_alternative<FanDef>(def)) return "a fan";
  return "a fluid region";
}

std::string overBudget(std::uint64_t cost, const FieldLimits& limits) {
  return std::to_string(cost) + " body interactions per step, over the room's budget of " +
         std::to_string(limits.maxCost) + " (--max-field-cost)";
}

std::string tooManyFields(std::uint64_t fields, const FieldLimits& limits) {
  return std::to_string(fields) + " force fields, over the room's limit of " +
         std::to_string(limits.maxFields) + " (--max-fields)";
}

}  // namespace

std::uint64_t fieldCost(const FieldDef& def, std::uint64_t bodies) {
  if (std::holds_alternative<GravitationDef>(def)) return bodies * (bodies - (bodies > 0)) / 2;
  return bodies;
}

std::uint64_t fieldsCost(const World& world, std::uint64_t bodies) {
  std::uint64_t cost = 0;
  for (const FieldId id : world.fieldIds()) {
    // A field of a kind the wire cannot describe costs like a gravitation field.
    const auto def = describeField(*world.field(id));
    cost += fieldCost(def ? *def : FieldDef{GravitationDef{}}, bodies);
  }
  return cost;
}

std::string fieldRefusal(const World& world, const FieldDef& def, const FieldLimits& limits) {
  const auto fields = std::uint64_t(world.fieldCount()) + 1;
  if (fields > std::uint64_t(limits.maxFields)) return tooManyFields(fields, limits);
  const auto bodies = std::uint64_t(world.bodyCount());
  const std::uint64_t cost = fieldsCost(world, bodies) + fieldCost(def, bodies);
  if (cost <= limits.maxCost) return {};
  return std::string(kindName(def)) + " over " + std::to_string(bodies) +
         " bodies brings the room's fields to " + overBudget(cost, limits) +
         ": fewer bodies or fewer fields";
}

std::string bodyRefusal(const World& world, const FieldLimits& limits) {
  if (world.fieldCount() == 0) return {};
  const auto bodies = std::uint64_t(world.bodyCount()) + 1;
  const std::uint64_t cost = fieldsCost(world, bodies);
  if (cost <= limits.maxCost) return {};
  return "with " + std::to_string(bodies) + " bodies the room's force fields would cost " +
         overBudget(cost, limits) + ": remove a field first";
}

std::string worldRefusal(const World& world, const FieldLimits& limits) {
  const auto fields = std::uint64_t(world.fieldCount());
  if (fields > std::uint64_t(limits.maxFields)) return tooManyFields(fields, limits);
  const std::uint64_t cost = fieldsCost(world, std::uint64_t(world.bodyCount()));
  if (cost <= limits.maxCost) return {};
  return "its force fields over " + std::to_string(world.bodyCount()) + " bodies cost " +
         overBudget(cost, limits);
}

}  // namespace impulse::server
