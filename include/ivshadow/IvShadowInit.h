#pragma once

#include "ivshadow/Export.h"

namespace ivshadow {

// Initialises Coin (SoInteraction::init: the database, node kits, selection nodes, draggers
// and manipulators, as SoQt::init does) if needed and registers every node class of the plugin with
// Coin's type system. Safe to call more than once; call it after SoQt::init in GUI programs.
IVSHADOW_API void init();

// The plugin's version, "MAJOR.MINOR.PATCH".
IVSHADOW_API const char* version();

}  // namespace ivshadow
