// One highlighted element over the mesh view, as the overlay renderer draws it: a vertex as a large point, an edge as
// a thick line, a halfedge as its arrow, a face (or boundary loop) as its outline. The lesson's highlights and the
// repaired spots are drawn through this one path.
//
// Invariant: an element that is dead or has no drawable shape (a face whose cycle does not close) adds nothing.
#pragma once

#include <glm/vec4.hpp>

#include "core/halfedge_mesh.h"
#include "render/overlay_renderer.h"

namespace meshedit {

void add_highlight(Overlay& overlay, const HalfedgeMesh& mesh, ElementRef element, const glm::vec4& rgba);

}  // namespace meshedit
