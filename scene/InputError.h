#pragma once

#include <stdexcept>
#include <string>

namespace ivshadow {

// Bad input from the user: a scene file, a field assignment, a command-line value. The
// message names the file, line or field and what was expected; callers exit with status 2.
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace ivshadow
