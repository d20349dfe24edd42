// MeshError: the exception the core throws when input cannot become a mesh, or a mesh cannot be used
// for what was asked (building from non-manifold polygons, exporting a broken mesh). Its message is
// complete and meant for people: it names the faces, vertices or edges involved.
#pragma once

#include <stdexcept>
#include <string>

#include "core/ids.h"

namespace meshedit {

class MeshError : public std::runtime_error {
 public:
  explicit MeshError(const std::string& message, ElementRef element = {})
      : std::runtime_error(message), element_(element) {}
  // The element to select in the UI, when there is one.
  ElementRef element() const { return element_; }

 private:
  ElementRef element_;
};

}  // namespace meshedit
