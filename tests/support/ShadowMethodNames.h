#pragma once

#include "ivshadow/ShadowMethod.h"

#include <ostream>
#include <string_view>

namespace ivshadow {

// Tests may compare a light's statistics with the method's name, as `ivshadow render --stats`
// writes it (EXPECT_EQ(stats.lights[0].method, "RAYS")); the name table decides.
inline bool operator==(ShadowMethod method, std::string_view name) {
  return name == shadowMethodName(method);
}

// GoogleTest prints a method by its name.
inline void PrintTo(ShadowMethod method, std::ostream* out) {
  *out << shadowMethodName(method);
}

}  // namespace ivshadow
