#include "scene/IndexChecks.h"

#include <algorithm>

namespace ivshadow {

IndexRuns IndexRuns::of(const SoMFInt32& indices) {
  IndexRuns result;
  long length = 0;
  const auto endRun = [&] {
    if (result.shortest < 0 || length < result.shortest) {
      result.shortest = length;
      result.shortestAt = result.runs;
    }
    result.longest = std::max(result.longest, length);
    ++result.runs;
    result.segments += std::max(length - 1, 0L);
    result.triangles += std::max(length - 2, 0L);
    length = 0;
  };
  for (int i = 0; i < indices.getNum(); ++i) {
    if (indices[i] == -1) {
      endRun();
    } else {
      ++length;
      ++result.vertices;
    }
  }
  if (length > 0) endRun();
  return result;
}

bool indexGiven(const SoMFInt32& indices) {
  return indices.getNum() > 0 && indices[0] >= 0;
}

std::string shortRun(const IndexRuns& runs, long shortest, const char* run) {
  if (runs.runs == 0 || runs.shortest >= shortest) return {};
  return std::string(run) + " " + std::to_string(runs.shortestAt) + " of coordIndex has " +
         std::to_string(runs.shortest) + " vertices; a " + run + " needs at least " +
         std::to_string(shortest);
}

namespace {
std::string entries(long count) {
  return std::to_string(count) + (count == 1 ? " entry" : " entries");
}

std::string outside(const char* name, long at, long index, long count, const char* what) {
  return std::string(name) + "[" + std::to_string(at) + "] " + std::to_string(index) +
         " is outside the " + std::to_string(count) + " " + what;
}
}  // namespace

std::string indicesInside(const SoMFInt32& indices, const char* name, long count,
                          const char* what) {
  for (int i = 0; i < indices.getNum(); ++i)
    if (indices[i] != -1 && (indices[i] < 0 || indices[i] >= count))
      return outside(name, i, indices[i], count, what);
  return {};
}

std::string indicesPerVertex(const SoMFInt32& coordIndex, const SoMFInt32& indices,
                             const char* name, long count, const char* what) {
  for (int i = 0; i < coordIndex.getNum(); ++i) {
    if (coordIndex[i] < 0) continue;
    if (i >= indices.getNum())
      return std::string(name) + " holds " + entries(indices.getNum()) +
             "; coordIndex reads one at each of its " + std::to_string(coordIndex.getNum());
    if (indices[i] < 0 || indices[i] >= count) return outside(name, i, indices[i], count, what);
  }
  return {};
}

std::string indicesPerUnit(const SoMFInt32& indices, const char* name, long units, const char* unit,
                           long count, const char* what) {
  if (indices.getNum() < units)
    return std::string(name) + " holds " + entries(indices.getNum()) + "; one is read per " + unit +
           ", " + std::to_string(units) + " in all";
  for (long i = 0; i < units; ++i)
    if (indices[int(i)] < 0 || indices[int(i)] >= count)
      return outside(name, i, indices[int(i)], count, what);
  return {};
}

std::string valuesPerUnit(const char* what, const char* binding, const char* unit, long units,
                          long count) {
  if (count >= units) return {};
  return std::string(binding) + " reads one of the " + what + " per " + unit + ", " +
         std::to_string(units) + " in all; there are " + std::to_string(count);
}

}  // namespace ivshadow
