#pragma once

#include <Inventor/fields/SoMFInt32.h>

#include <string>

namespace ivshadow {

// One index array as Inventor's indexed shapes read it: runs (faces, polylines or strips)
// ended by -1, the last one possibly without.
struct IndexRuns {
  long runs = 0;         // faces, polylines or strips, empty ones included
  long vertices = 0;     // entries other than -1
  long segments = 0;     // sum over runs of (length - 1): line segments
  long triangles = 0;    // sum over runs of (length - 2): a strip's triangles
  long shortest = -1;    // the shortest run's length (-1: no run)
  long longest = -1;     // the longest run's length (-1: no run)
  long shortestAt = -1;  // its number

  static IndexRuns of(const SoMFInt32& indices);
};

// Whether an index field is given as Coin reads it: not empty and not starting with -1 (Coin
// then reads coordIndex, or the values in order, in its place).
bool indexGiven(const SoMFInt32& indices);

// A run of `runs` shorter than `shortest` indices: "RUN N of coordIndex has K vertices; a RUN
// needs at least SHORTEST", or empty.
std::string shortRun(const IndexRuns& runs, long shortest, const char* run);

// Each entry of `indices` other than -1 inside 0..count-1, or what is not: "NAME[I] V is
// outside the COUNT WHAT".
std::string indicesInside(const SoMFInt32& indices, const char* name, long count, const char* what);

// `indices` read in step with `coordIndex` (one entry per vertex, -1 where coordIndex ends a
// run): an entry for every vertex, each inside 0..count-1.
std::string indicesPerVertex(const SoMFInt32& coordIndex, const SoMFInt32& indices,
                             const char* name, long count, const char* what);

// `indices` read one entry per `unit` (face, polyline, strip, segment or triangle): at least
// `units` entries, the first `units` inside 0..count-1.
std::string indicesPerUnit(const SoMFInt32& indices, const char* name, long units, const char* unit,
                           long count, const char* what);

// `count` values of WHAT read one per UNIT: "BINDING reads one of the WHAT per UNIT, N in all;
// there are COUNT", or empty when count >= units.
std::string valuesPerUnit(const char* what, const char* binding, const char* unit, long units,
                          long count);

}  // namespace ivshadow
