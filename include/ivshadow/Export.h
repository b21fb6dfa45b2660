#pragma once

// The library is built with hidden visibility (-fvisibility=hidden): only what is marked here
// is exported from libivshadow.so, the library Coin loads.
//
// IVSHADOW_API marks the public API, the headers installed under include/ivshadow/: the node
// classes (whose initClass Coin's loader calls by name), init() and the statistics.
//
// IVSHADOW_INTERNAL marks the few internal classes and functions that the project's own
// tools (the headless renderer, the reference renderer, the CLI, the viewer, the tests) call
// in the library. They are not part of the public API: their headers are not installed and
// may change in any release. Spelling them apart keeps that boundary visible in the code.
#if defined(__GNUC__)
#define IVSHADOW_API __attribute__((visibility("default")))
#define IVSHADOW_INTERNAL __attribute__((visibility("default")))
#else
#define IVSHADOW_API
#define IVSHADOW_INTERNAL
#endif
