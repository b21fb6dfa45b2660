#pragma once

#include "scene/InputError.h"

#include <exception>
#include <iostream>

namespace ivshadow {

// Runs a command body and turns what it throws into the CLI's exit statuses: bad input
// (InputError, whose message already names the file and line) exits 2, anything else 1.
template <typename Body>
int withExitStatus(Body body) {
  try {
    return body();
  } catch (const InputError& error) {
    std::cerr << error.what() << '\n';
    return 2;
  } catch (const std::exception& error) {
    std::cerr << "ivshadow: error: " << error.what() << '\n';
    return 1;
  }
}

}  // namespace ivshadow
