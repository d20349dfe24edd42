// Catmull-Clark and linear subdivision as document actions (see subdivision_actions.h).
#include "ui/subdivision_actions.h"

#include <string>

#include "core/catmull_clark.h"
#include "core/linear_subdivision.h"

namespace meshedit {
namespace {

// Made when the program starts, so apply_operation takes them without an allocation that could fail.
const std::string kCatmullClarkLabel = "Catmull-Clark subdivision";
const std::string kLinearLabel = "Linear subdivision";

Check subdivide_all(MeshDocument& doc, Selection& selection, const std::string& label,
                    Check (*subdivide)(HalfedgeMesh&, int)) {
  Check check = apply_operation(doc, label, [&](HalfedgeMesh& mesh) { return subdivide(mesh, 1); });
  if (check) {
    // The refined mesh reuses edge and face ids for new elements: only an original vertex is still itself.
    if (selection.selected.kind != ElementKind::Vertex) selection.selected = ElementRef();
    if (selection.hovered.kind != ElementKind::Vertex) selection.hovered = ElementRef();
    keep_if_alive(selection, doc.mesh);
    doc.loop = LoopStepper{};
  }
  return check;
}

}  // namespace

Check catmull_clark_all(MeshDocument& doc, Selection& selection) {
  return subdivide_all(doc, selection, kCatmullClarkLabel, catmull_clark_subdivide);
}

Check linear_subdivide_all(MeshDocument& doc, Selection& selection) {
  return subdivide_all(doc, selection, kLinearLabel, linear_subdivide);
}

}  // namespace meshedit
