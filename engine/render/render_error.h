// RenderError: what the renderer throws when it cannot do its job (no EGL display, no OpenGL 3.3 core,
// a shader that is missing or does not compile, a mesh too large for the GPU's limits). The message is
// complete and meant for people: it names the file, the paths tried or the driver's log.
// Nothing in engine/render calls exit() or abort(); callers catch this (the CLI turns it into one line).
#pragma once

#include <stdexcept>
#include <string>

namespace meshedit {

class RenderError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace meshedit
