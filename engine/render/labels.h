// Id labels (`v3`, `e5`, `f2`, `h12`) placed on screen next to their elements, for the app to draw with
// ImGui when the mesh is small enough to read them. Pure: no GL, unit-tested.
//
// Anchors: a vertex at its position, an edge at its midpoint, a face at its centre (the corners'
// average), a halfedge at the middle of its arrow (mesh_geometry.h), so twins' labels sit on their own
// sides. A label is kept when its anchor is in front of the eye, inside the viewport, and its element
// faces the camera: a face (or a halfedge's face) whose normal points towards the eye, an edge or a
// vertex with such a face around it (or a vertex whose fan cannot be walked: a broken mesh still gets
// its labels). Occlusion by other parts of the mesh is not tested. Order: vertices, edges, faces,
// halfedges, each in id order; at most `max_labels` (the rest would be unreadable anyway).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "core/halfedge_mesh.h"
#include "render/camera.h"

namespace meshedit {

struct ScreenLabel {
  ElementRef element;
  glm::dvec2 pixel{0.0};  // top-left origin
  std::string text;       // format_id(element)
};

struct LabelOptions {
  bool vertices = true;
  bool edges = true;
  bool faces = true;
  bool halfedges = false;
  size_t max_labels = 2000;
};

// Where the element's label goes in world space; nullopt for dead or unwalkable elements.
std::optional<glm::dvec3> label_anchor(const HalfedgeMesh& mesh, ElementRef element);
std::vector<ScreenLabel> visible_labels(const HalfedgeMesh& mesh, const OrbitCamera& camera, Viewport viewport,
                                        const LabelOptions& options = {});

}  // namespace meshedit
