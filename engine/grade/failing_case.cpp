// The input of a failed mesh check as a case the window can open (see failing_case.h).
#include "grade/failing_case.h"

#include <unordered_map>
#include <vector>

#include "core/mesh_build.h"
#include "core/mesh_error.h"
#include "io/obj_io.h"

namespace meshedit {

std::optional<FailingCase> failing_case_of(Exercise exercise, const ExerciseInput& input) {
  if (!is_mesh_exercise(exercise) || !input.mesh) return std::nullopt;
  const HalfedgeMesh& mesh = *input.mesh;
  FailingCase out;
  out.exercise = exercise_info(exercise).function;
  out.input = input.describe(exercise);
  try {
    out.mesh_obj = format_obj(to_polygon_mesh(mesh), "case.obj");
  } catch (const MeshError&) {
    return std::nullopt;
  }
  std::unordered_map<uint32_t, size_t> obj_index;  // vertex id -> 0-based OBJ index
  for (const VertexId v : mesh.vertices()) obj_index.emplace(v.index, obj_index.size());
  const auto corner = [&](VertexId v) { return obj_index.at(v.index); };
  const ElementRef element = input.element;
  if (!element.valid() || !mesh.alive(element)) return out;
  switch (element.kind) {
    case ElementKind::Vertex:
      out.element = "vertex";
      out.corners = {corner(VertexId(element.index))};
      break;
    case ElementKind::Edge:
    case ElementKind::Halfedge: {
      const HalfedgeId h =
          element.kind == ElementKind::Edge ? mesh.halfedge(EdgeId(element.index)) : HalfedgeId(element.index);
      out.element = element.kind == ElementKind::Edge ? "edge" : "halfedge";
      out.corners = {corner(mesh.vertex(h)), corner(mesh.vertex(mesh.twin(h)))};
      break;
    }
    case ElementKind::Face: {
      out.element = "face";
      mesh.for_each_face_halfedge(element.face_id(),
                                  [&](HalfedgeId h) { out.corners.push_back(corner(mesh.vertex(h))); });
      break;
    }
    default: break;  // a boundary loop: the whole mesh
  }
  return out;
}

HalfedgeMesh case_mesh(const FailingCase& failing_case) {
  return build_halfedge_mesh(parse_obj(failing_case.mesh_obj, "the test's input"));
}

ElementRef case_element(const HalfedgeMesh& mesh, const FailingCase& failing_case) {
  const std::vector<size_t>& corners = failing_case.corners;
  const auto vertex = [&](size_t i) { return VertexId(static_cast<uint32_t>(corners[i])); };
  for (size_t corner : corners) {
    if (corner >= mesh.vertex_capacity() || !mesh.alive(VertexId(static_cast<uint32_t>(corner)))) return {};
  }
  if (failing_case.element == "vertex" && corners.size() == 1) return vertex(0);
  if (corners.size() < 2) return {};
  // The halfedge from the first corner to the second.
  HalfedgeId from_first;
  mesh.for_each_outgoing(vertex(0), [&](HalfedgeId h) {
    if (!from_first.valid() && mesh.vertex(mesh.twin(h)) == vertex(1)) from_first = h;
  });
  if (!from_first.valid()) return {};
  if (failing_case.element == "halfedge" && corners.size() == 2) return from_first;
  if (failing_case.element == "edge" && corners.size() == 2) return mesh.edge(from_first);
  if (failing_case.element != "face") return {};
  std::vector<size_t> around;
  mesh.for_each_face_halfedge(mesh.face(from_first), [&](HalfedgeId h) { around.push_back(mesh.vertex(h).index); });
  if (around != corners || mesh.face(from_first).is_boundary()) return {};
  return mesh.face(from_first);
}

}  // namespace meshedit
