// The bound on the elements a flip_edge or split_edge touches, and the message when a run passes it (see
// exercise_locality.h for the bound and why).
#include "exercise/exercise_locality.h"

#include <set>
#include <vector>

#include "core/history.h"
#include "core/translation.h"
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

// "3 fields", "1 element": a count with its noun, in the window's language.
std::string counted(size_t n, const char* one, const char* many) {
  return tr_format(n == 1 ? one : many, {{"count", std::to_string(n)}});
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
  if (created.empty() && changed.empty()) return tr("changes nothing");
  const MessageParts parts = {{"fields", counted(fields, "{count} field", "{count} fields")},
                              {"elements", counted(changed.size(), "{count} element", "{count} elements")},
                              {"created", counted(created.size(), "{count} element", "{count} elements")}};
  if (created.empty()) return tr_format("changes {fields} of {elements}", parts);
  return tr_format("creates {created} and changes {fields} of {elements} it had", parts);
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
  const MessageParts parts = {
      {"function", flip ? "flip_edge" : "split_edge"},
      {"count", std::to_string(touched.elements)},
      {"faces", std::to_string(before.num_faces())},
      {"call", touched.whole_mesh_call},
      {"written", std::to_string(touched.written)},
      {"changes", reference.mesh ? reference_changes(before, *reference.mesh) : std::string(tr("changes nothing"))}};
  if (!touched.whole_mesh_call.empty()) {
    return flip ? tr_format(
                      "your {function} touched all {count} elements of a mesh of {faces} faces: {call} reads "
                      "every one; a flip changes a fixed handful (the reference {changes}), whatever the "
                      "mesh's size: walk from e.halfedge instead of reading the whole mesh",
                      parts)
                : tr_format(
                      "your {function} touched all {count} elements of a mesh of {faces} faces: {call} reads "
                      "every one; a split changes a fixed handful (the reference {changes}), whatever the "
                      "mesh's size: walk from e.halfedge instead of reading the whole mesh",
                      parts);
  }
  return flip ? tr_format(
                    "your {function} touched {count} elements of a mesh of {faces} faces (it wrote {written} "
                    "of them and only read the rest); a flip changes a fixed handful (the reference {changes}), "
                    "whatever the mesh's size: walk from e.halfedge instead of looping over the mesh",
                    parts)
              : tr_format(
                    "your {function} touched {count} elements of a mesh of {faces} faces (it wrote {written} "
                    "of them and only read the rest); a split changes a fixed handful (the reference "
                    "{changes}), whatever the mesh's size: walk from e.halfedge instead of looping over the mesh",
                    parts);
}

}  // namespace meshedit
