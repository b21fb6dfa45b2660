#pragma once

#include "scene_input/VariantsFile.h"

#include <string>
#include <vector>

namespace ivshadow {

// The whole sweep as every shard sees it: the base scene, the variants in the file's order,
// the render settings and, per variant, the hash of its inputs. Each run writes it to
// DIR/manifests/plan.json (the same content from every shard, atomically), so variants-merge
// and --status know the variants no shard has reported yet and which manifests are stale.
struct VariantsPlan {
  std::string base;
  std::string variantsFile;
  std::string size;
  int frames = 0;
  std::vector<Variant> variants;
  std::vector<std::string> hashes;  // inputHash of each variant, in the same order

  // Hashes the base scene file's bytes with every variant's name and assignments and the size
  // and frames (FNV-1a, 64 bits, hex): a change to any of them makes a manifest stale.
  static VariantsPlan make(const std::string& base, const std::string& variantsFile,
                           const std::string& size, int frames, std::vector<Variant> variants);
  static std::string path(const std::string& outputDir);
  // Throws InputError naming the plan's path when DIR holds no readable plan.
  static VariantsPlan read(const std::string& outputDir);
  void write(const std::string& outputDir) const;
};

}  // namespace ivshadow
