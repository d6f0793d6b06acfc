#pragma once
/// Fields between the engine's FieldDef and the wire's AddField and
/// FieldDescriptor (docs/protocol.md, "Fields").

#include <optional>
#include <string_view>

#include "impulse.pb.h"
#include "impulse/field_kinds.h"
#include "impulse/wire/convert.h"

namespace impulse::wire {

void toWire(const FieldDef& def, v1::AddField* out);
void toWire(FieldId id, const FieldDef& def, v1::FieldDescriptor* out);
/// Every number finite and fitting a float, errors naming the field
/// ("add_field.fan.speed is not a finite number"); ranges are the engine's.
Decoded<FieldDef> fieldDefFromWire(const v1::AddField& command);
/// Fields come from the server: nothing for a descriptor without a kind.
std::optional<FieldDef> fieldFromWire(const v1::FieldDescriptor& field);
/// "gravitation", "fluid" or "fan".
std::string_view fieldKindName(const FieldDef& def);

}  // namespace impulse::wire
