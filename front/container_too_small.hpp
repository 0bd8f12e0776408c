#pragma once
// The front cannot start: no particle the scene draws fits in its container. The scene's own
// mistake (a box smaller than its particles, a size law on a dimension that makes them huge),
// so the command line reports it as bad input, at the scene's particles, and Python raises
// ValueError (an invalid_argument).
#include <stdexcept>

namespace fp {

struct ContainerTooSmall : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

}  // namespace fp
