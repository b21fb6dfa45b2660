#pragma once

#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <vector>

namespace ivshadow {

// What one variant's render left: DIR/manifests/NAME.json, written atomically when the render
// ends (docs/VARIANTS.md). A rerun skips a variant whose manifest says "ok" for the same input
// hash and whose picture exists; any other variant is rendered again. Shards on different
// machines share nothing but these files, so variants-merge builds the reports from them.
struct VariantManifest {
  std::string variant;
  std::vector<std::string> assignments;  // NAME.field=VALUE, as the render got them
  std::string size;                      // WIDTHxHEIGHT
  int frames = 0;
  std::string hash;  // VariantsPlan::make hashes the render's inputs
  // A variant no shard has reported (in a merge only; never written to a file).
  static constexpr int kPending = -2;

  int exitCode = -1;     // the render's exit status; -1 when it was killed by a signal
  std::string error;     // the variant's error line, naming the variants file's line
  nlohmann::json stats;  // the render's --stats, as `ivshadow render` wrote them
  double seconds = 0.0;  // wall time of the render process
  std::string host;      // where it ran, to find a node's logs

  bool ok() const { return exitCode == 0; }

  static std::string path(const std::string& outputDir, const std::string& variant);
  // The manifest, or nothing when there is none. Throws InputError naming the file and what
  // is wrong when it is empty, cut short, not JSON, of another variant or has a field of the
  // wrong type (a sweep that renders takes such a variant as not rendered: SweepState).
  static std::optional<VariantManifest> read(const std::string& outputDir,
                                             const std::string& variant);
  void write(const std::string& outputDir) const;
};

}  // namespace ivshadow
