#pragma once
// The front cannot start: no particle the scene draws fits in its container. The scene's own
// mistake (a box smaller than its particles, a size law on a dimension that makes them huge),
// so the command line reports it as bad input, at the scene's particles.
#include <stdexcept>

namespace fp {

struct ContainerTooSmall : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace fp
