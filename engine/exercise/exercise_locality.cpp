// The bound on the elements a flip_edge or split_edge touches, and the message when a run passes it (see
// exercise_locality.h for the bound and why).
#include "exercise/exercise_locality.h"

#include <set>
#include <vector>

#include "core/history.h"
#include "core/value_format.h"

namespace meshedit {
namespace {

// The vertices of the faces on either side of `e` (boundary loops left out: a loop may run around the whole mesh).
std::set<uint32_t> corners_at(const HalfedgeMesh& mesh, EdgeId e) {
  std::set<uint32_t> corners;
  const HalfedgeId h0 = mesh.halfedge(e);
  if (!mesh.alive(h0)) return corners;
  for (const HalfedgeId side : {h0, mesh.twin(h0)}) {
    if (!mesh.alive(side) || mesh.face(side).is_boundary()) continue;
    mesh.for_each_face_halfedge(mesh.face(side), [&](HalfedgeId h) { corners.insert(mesh.vertex(h).index); });
  }
  return corners;
}

// "changes 12 fields of 8 elements", "creates 12 elements and changes 9 fields of 7 elements it had", "changes
// nothing": what the reference did to the input, counted from its mesh (a field is one changed value of m:diff).
std::string reference_changes(const HalfedgeMesh& before, const HalfedgeMesh& after) {
  const std::vector<FieldChange> changes = diff(before, after);
  std::set<ElementRef> created, changed;
  size_t fields = 0;
  for (const FieldChange& c : changes) {
    if (!before.alive(c.element)) {
      created.insert(c.element);
      continue;
    }
    changed.insert(c.element);
    ++fields;
  }
  if (created.empty() && changed.empty()) return "changes nothing";
  const std::string rewritten =
      "changes " + plural(fields, "field", "fields") + " of " + plural(changed.size(), "element", "elements");
  if (created.empty()) return rewritten;
  return "creates " + plural(created.size(), "element", "elements") + " and " + rewritten + " it had";
}

}  // namespace

bool has_locality_bound(Exercise exercise) { return exercise == Exercise::FlipEdge || exercise == Exercise::SplitEdge; }

size_t locality_bound(const ExerciseInput& input) {
  size_t degrees = 0;
  if (input.mesh && input.element.kind == ElementKind::Edge) {
    for (const uint32_t v : corners_at(*input.mesh, EdgeId(input.element.index))) {
      degrees += input.mesh->degree(VertexId(v));
    }
  }
  return kLocalElements + kPerCornerDegree * degrees;
}

std::string locality_failure(Exercise exercise, const ExerciseInput& input, const ExerciseOutcome& mine,
                             const ExerciseOutcome& reference) {
  if (!has_locality_bound(exercise) || !mine.ran || !mine.touched || !input.mesh) return "";
  const HalfedgeMesh& before = *input.mesh;
  if (before.num_faces() < kMinFaces) return "";
  const TouchCount& touched = *mine.touched;
  if (touched.elements <= locality_bound(input)) return "";

  const bool flip = exercise == Exercise::FlipEdge;
  const std::string function = flip ? "flip_edge" : "split_edge";
  const std::string mesh_size = "a mesh of " + std::to_string(before.num_faces()) + " faces";
  std::string message;
  if (!touched.whole_mesh_call.empty()) {
    message = "your " + function + " touched all " + std::to_string(touched.elements) + " elements of " + mesh_size +
              ": " + touched.whole_mesh_call + " reads every one";
  } else {
    message = "your " + function + " touched " + std::to_string(touched.elements) + " elements of " + mesh_size +
              " (it wrote " + std::to_string(touched.written) + " of them and only read the rest)";
  }
  message += std::string("; a ") + (flip ? "flip" : "split") + " changes a fixed handful (the reference ";
  message += reference.mesh ? reference_changes(before, *reference.mesh) : "changes nothing";
  message += "), whatever the mesh's size: walk from e.halfedge instead of ";
  message += touched.whole_mesh_call.empty() ? "looping over the mesh" : "reading the whole mesh";
  return message;
}

}  // namespace meshedit
