#pragma once

#include <cstddef>

#include <string>
#include <vector>

namespace ivshadow {

// The longest variant name (sweep names included): it names the output files.
constexpr std::size_t kMaxVariantName = 200;

// One scripted variant of a scene: a name and the field assignments it makes.
struct Variant {
  struct Assignment {
    std::string text;  // NAME.field=VALUE, as `ivshadow render --set` takes it
    int line = 0;      // where the variants file says it
  };
  std::string name;
  int line = 0;  // the line that starts the variant
  std::vector<Assignment> assignments;
};

// Reads a variants file (docs/VARIANTS.md):
//   # comment
//   variant NAME                       a variant; the assignment lines below belong to it
//     NODE.field = VALUE               VALUE in Inventor field syntax, to the end of the line
//   sweep NAME NODE.field = V1 | V2    one variant per value, named NAME-V (sanitised)
//   sweep NAME NODE.field = A .. B step S   numbers from A to B
//   sweep NAME A.f = 1 | 2 * B.g = 0 .. 1 step 0.5   crossed: one variant per combination,
//                                      named NAME-V1-V2 (at most 10000)
//     NODE.field = VALUE               ...and assignments shared by all the sweep's variants
// Throws InputError naming `path` and the line for a line it cannot read, a duplicate
// variant name or an empty file. Whether a node, field or value exists is for the scene to
// say (each variant is rendered separately).
std::vector<Variant> readVariantsFile(const std::string& path);
std::vector<Variant> parseVariants(const std::string& text, const std::string& path);

}  // namespace ivshadow
