#include "cli/VariantShard.h"

#include "scene/InputError.h"

#include <regex>

namespace ivshadow {

VariantShard VariantShard::parse(const std::string& text) {
  static const std::regex form("([0-9]{1,6})/([0-9]{1,6})");
  std::smatch match;
  VariantShard shard;
  if (std::regex_match(text, match, form)) {
    shard.index = std::stoi(match[1]);
    shard.count = std::stoi(match[2]);
    if (shard.count >= 1 && shard.index < shard.count) return shard;
  }
  throw InputError("--shard " + text +
                   ": error: expected K/N with whole numbers 0 <= K < N, e.g. 0/4 for the first "
                   "of four shards");
}

}  // namespace ivshadow
