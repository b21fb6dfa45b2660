#pragma once

#include <cstddef>
#include <string>

namespace ivshadow {

// `--shard K/N`: the variants whose index in the variants file is K modulo N (0 <= K < N).
// The index depends on the file alone, so every machine computes the same partition, and
// taking every N-th variant spreads a sweep whose variants grow costlier along the file (a
// layers or resolution sweep) evenly over the shards.
struct VariantShard {
  int index = 0;
  int count = 1;

  // Throws InputError naming --shard for anything but two whole numbers K/N with 0 <= K < N.
  static VariantShard parse(const std::string& text);
  bool contains(std::size_t variantIndex) const {
    return int(variantIndex % std::size_t(count)) == index;
  }
};

}  // namespace ivshadow
