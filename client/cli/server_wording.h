#pragma once
// The server names what it refuses by the protocol's fields
// ("spawn_circle.center.x is not a finite number"); a script's author wrote
// "circle X Y R". This rewrites the field names of a server error into the
// script's words ("circle X is not a finite number") and the fixed-point
// numbers some messages carry ("-25.000000") as people write them ("-25").

#include <string>
#include <string_view>

namespace impulse::cli {

std::string scriptWording(std::string_view serverError);

}  // namespace impulse::cli
