// apply_edit, replay and the text of recorded edits (see edit_log.h for the contracts).
//
// Invariant kept here: every check (element allocated, value kind, creation id, operation accepted) happens
// before the first write, so a refused edit leaves the mesh untouched, version included.
#include "core/edit_log.h"

#include <algorithm>
#include <string_view>

#include "core/catmull_clark.h"
#include "core/linear_subdivision.h"
#include "core/loop_subdivision.h"
#include "core/mesh_error.h"
#include "core/mesh_ops.h"
#include "core/translation.h"
#include "core/triangulate.h"
#include "core/value_format.h"

namespace meshedit {
namespace {

bool is_position(const RecordedEdit& edit) { return edit.what == EditKind::Set && edit.field == "position"; }

std::string show(const RecordedEdit& edit, const EditValue& value) {
  return is_position(edit) ? format_position(value.position) : format_id(value.element);
}

// An operation's name as describe() shows it: the core's edits and the mesh replacements in the text language, the
// subdivisions by their function names (loop_subdivide, triangulate, ...), as scripts call them.
const char* operation_text(const std::string& operation) {
  for (const char* word : {"flip", "split", "collapse", "restore", "undo", "redo", "subdivision phase"}) {
    if (operation == word) return tr(word);
  }
  return operation.c_str();
}

[[noreturn]] void refuse(const RecordedEdit& edit, const std::string& why) {
  throw MeshError("cannot apply '" + describe(edit) + "': " + why, edit.element);
}

void check_allocated(const HalfedgeMesh& mesh, const RecordedEdit& edit) {
  const ElementKind kind = edit.element.kind;
  if (!edit.element.valid() || edit.element.index >= mesh.capacity(kind)) {
    refuse(edit, "the mesh has no " + std::string(kind_name(kind)) + " with that id (it has " +
                     std::to_string(mesh.capacity(kind)) + ")");
  }
}

// The value of a pointer field must be null or an id of the field's kind (a face field takes boundary loops).
void check_value_kind(const RecordedEdit& edit, ElementKind wanted) {
  const ElementRef v = edit.value.element;
  if (!v.valid()) return;
  const bool face_slot = wanted == ElementKind::Face && v.kind == ElementKind::Boundary;
  if (v.kind != wanted && !face_slot) refuse(edit, "the value must be a " + std::string(kind_name(wanted)));
}

void apply_set(HalfedgeMesh& mesh, const RecordedEdit& edit) {
  check_allocated(mesh, edit);
  const std::string_view field = edit.field;
  const ElementRef target = edit.element;
  const uint32_t value = edit.value.element.valid() ? edit.value.element.index : kInvalidIndex;
  if (target.kind == ElementKind::Halfedge) {
    const HalfedgeId h(target.index);
    if (field == "next" || field == "twin") {
      check_value_kind(edit, ElementKind::Halfedge);
      return field == "next" ? mesh.set_next(h, HalfedgeId(value)) : mesh.set_twin(h, HalfedgeId(value));
    }
    if (field == "vertex") {
      check_value_kind(edit, ElementKind::Vertex);
      return mesh.set_vertex(h, VertexId(value));
    }
    if (field == "edge") {
      check_value_kind(edit, ElementKind::Edge);
      return mesh.set_edge(h, EdgeId(value));
    }
    if (field == "face") {
      check_value_kind(edit, ElementKind::Face);
      return mesh.set_face(h, edit.value.element.valid() ? edit.value.element.face_id() : FaceId());
    }
  } else if (field == "halfedge") {
    check_value_kind(edit, ElementKind::Halfedge);
    if (target.kind == ElementKind::Vertex) return mesh.set_halfedge(VertexId(target.index), HalfedgeId(value));
    if (target.kind == ElementKind::Edge) return mesh.set_halfedge(EdgeId(target.index), HalfedgeId(value));
    return mesh.set_halfedge(target.face_id(), HalfedgeId(value));
  } else if (field == "position" && target.kind == ElementKind::Vertex) {
    return mesh.set_position(VertexId(target.index), edit.value.position);
  }
  refuse(edit, std::string(kind_name(target.kind)) + "s have no field '" + edit.field + "'");
}

void apply_create(HalfedgeMesh& mesh, const RecordedEdit& edit) {
  const ElementKind kind = edit.element.kind;
  if (edit.element.index != mesh.capacity(kind)) {
    refuse(edit, "the mesh's next " + std::string(kind_name(kind)) + " id is " +
                     format_id(ElementRef(kind, mesh.capacity(kind))));
  }
  switch (kind) {
    case ElementKind::Vertex: mesh.new_vertex(edit.value.position); break;
    case ElementKind::Halfedge: mesh.new_halfedge(); break;
    case ElementKind::Edge: mesh.new_edge(); break;
    case ElementKind::Face: mesh.new_face(); break;
    case ElementKind::Boundary: mesh.new_boundary(); break;
  }
}

void apply_delete(HalfedgeMesh& mesh, const RecordedEdit& edit) {
  check_allocated(mesh, edit);
  const ElementRef r = edit.element;
  switch (r.kind) {
    case ElementKind::Vertex: return mesh.delete_element(VertexId(r.index));
    case ElementKind::Halfedge: return mesh.delete_element(HalfedgeId(r.index));
    case ElementKind::Edge: return mesh.delete_element(EdgeId(r.index));
    case ElementKind::Face:
    case ElementKind::Boundary: return mesh.delete_element(r.face_id());
  }
}

void apply_operation(HalfedgeMesh& mesh, const RecordedEdit& edit) {
  const std::string_view op = edit.field;
  if (op == "restore" || op == "undo" || op == "redo" || op == "subdivision phase") {
    if (!edit.state) refuse(edit, "the recording holds no mesh state to restore");
    const uint64_t seen = mesh.version();
    mesh = *edit.state;
    mesh.bump_version_above(seen);
    return;
  }
  Check check;
  if (op == "loop_subdivide") {
    check = loop_subdivide(mesh);
  } else if (op == "catmull_clark") {
    check = catmull_clark_subdivide(mesh);
  } else if (op == "linear_subdivide") {
    check = linear_subdivide(mesh);
  } else if (op == "triangulate") {
    check = triangulate_mesh(mesh).check;
  } else if (op == "flip" || op == "split" || op == "collapse") {
    if (edit.element.kind != ElementKind::Edge) refuse(edit, "the element must be an edge");
    const EdgeId e(edit.element.index);
    check = op == "flip" ? flip(mesh, e).check : op == "split" ? split(mesh, e).check : collapse(mesh, e).check;
  } else {
    refuse(edit, "unknown operation");
  }
  if (!check.ok) refuse(edit, check.reason);
}

}  // namespace

const char* edit_kind_name(EditKind kind) {
  switch (kind) {
    case EditKind::Set: return "set";
    case EditKind::Create: return "new";
    case EditKind::Delete: return "delete";
    case EditKind::Operation: return "operation";
  }
  return "edit";
}

std::string format_edit_before(const RecordedEdit& edit) {
  switch (edit.what) {
    case EditKind::Set: return show(edit, edit.before);
    case EditKind::Create: return "-";
    case EditKind::Delete: return "alive";
    case EditKind::Operation: return "-";
  }
  return "-";
}

std::string format_edit_after(const RecordedEdit& edit) {
  switch (edit.what) {
    case EditKind::Set: return show(edit, edit.value);
    case EditKind::Create: return "alive";
    case EditKind::Delete: return "dead";
    case EditKind::Operation: return format_id(edit.value.element);
  }
  return "-";
}

std::string describe(const RecordedEdit& edit) {
  const std::string id = format_id(edit.element);
  switch (edit.what) {
    case EditKind::Set: {
      return tr_format("{element}.{field} = {value} (was {before})", {{"element", id},
                                                                      {"field", edit.field},
                                                                      {"value", format_edit_after(edit)},
                                                                      {"before", format_edit_before(edit)}});
    }
    case EditKind::Create:
      if (edit.element.kind == ElementKind::Vertex) {
        return tr_format("new {element} at {position}",
                         {{"element", id}, {"position", format_position(edit.value.position)}});
      }
      return tr_format("new {element}", {{"element", id}});
    case EditKind::Delete: return tr_format("delete {element}", {{"element", id}});
    case EditKind::Operation: {  // "split e3 -> v9": the same order in every language
      std::string text = operation_text(edit.field);
      if (edit.element.valid()) text += " " + id;
      if (edit.value.element.valid() && edit.value.element != edit.element)
        text += " -> " + format_id(edit.value.element);
      return text;
    }
  }
  return id;
}

void apply_edit(HalfedgeMesh& mesh, const RecordedEdit& edit) {
  switch (edit.what) {
    case EditKind::Set: return apply_set(mesh, edit);
    case EditKind::Create: return apply_create(mesh, edit);
    case EditKind::Delete: return apply_delete(mesh, edit);
    case EditKind::Operation: return apply_operation(mesh, edit);
  }
}

HalfedgeMesh replay(const HalfedgeMesh& before, std::span<const RecordedEdit> edits, size_t count) {
  HalfedgeMesh mesh = before;
  const size_t n = std::min(count, edits.size());
  for (size_t i = 0; i < n; ++i) apply_edit(mesh, edits[i]);
  return mesh;
}

}  // namespace meshedit
