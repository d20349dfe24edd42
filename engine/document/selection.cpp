// Navigation and selection upkeep (see selection.h). Every read of a stored field is preceded by in_range().
#include "document/selection.h"

#include <optional>

#include "core/ids.h"

namespace meshedit {

char nav_key(NavStep step) {
  switch (step) {
    case NavStep::Next: return 'N';
    case NavStep::Twin: return 'T';
    case NavStep::Vertex: return 'V';
    case NavStep::Edge: return 'E';
    case NavStep::Face: return 'F';
    case NavStep::Halfedge: return 'H';
  }
  return '?';
}

const char* nav_field(NavStep step) {
  switch (step) {
    case NavStep::Next: return "next";
    case NavStep::Twin: return "twin";
    case NavStep::Vertex: return "vertex";
    case NavStep::Edge: return "edge";
    case NavStep::Face: return "face";
    case NavStep::Halfedge: return "halfedge";
  }
  return "?";
}

ElementRef live_element(const HalfedgeMesh& mesh, std::string_view id) {
  const std::optional<ElementRef> parsed = parse_element(id);
  return parsed && reference_state(mesh, *parsed) == RefState::Live ? *parsed : ElementRef{};
}

bool in_range(const HalfedgeMesh& mesh, ElementRef ref) { return ref.valid() && ref.index < mesh.capacity(ref.kind); }

RefState reference_state(const HalfedgeMesh& mesh, ElementRef ref) {
  if (!ref.valid()) return RefState::Null;
  if (!in_range(mesh, ref)) return RefState::OutOfRange;
  return mesh.alive(ref) ? RefState::Live : RefState::Dead;
}

namespace {
std::string plural_kind(ElementKind kind) {
  if (kind == ElementKind::Vertex) return "vertices";
  if (kind == ElementKind::Boundary) return "boundary loops";
  return std::string(kind_name(kind)) + "s";
}

// "does not exist (halfedges h0..h47)".
std::string missing_text(const HalfedgeMesh& mesh, ElementRef ref) {
  const uint32_t n = mesh.capacity(ref.kind);
  if (n == 0) return "does not exist (there are no " + plural_kind(ref.kind) + ")";
  return "does not exist (" + plural_kind(ref.kind) + " " + format_id(ElementRef(ref.kind, 0)) + ".." +
         format_id(ElementRef(ref.kind, n - 1)) + ")";
}

}  // namespace

std::string reference_problem(const HalfedgeMesh& mesh, ElementRef ref) {
  switch (reference_state(mesh, ref)) {
    case RefState::Live: return {};
    case RefState::Null: return "- is no " + std::string(kind_name(ref.kind)) + " (a null pointer)";
    case RefState::Dead: return format_id(ref) + " is dead";
    case RefState::OutOfRange: return format_id(ref) + " " + missing_text(mesh, ref);
  }
  return {};
}

namespace {

// The stored halfedge field of a vertex, edge, face or boundary loop (in range: checked by the caller).
HalfedgeId element_halfedge(const HalfedgeMesh& mesh, ElementRef ref) {
  switch (ref.kind) {
    case ElementKind::Vertex: return mesh.halfedge(VertexId(ref.index));
    case ElementKind::Edge: return mesh.halfedge(EdgeId(ref.index));
    case ElementKind::Face:
    case ElementKind::Boundary: return mesh.halfedge(ref.face_id());
    case ElementKind::Halfedge: return HalfedgeId(ref.index);
  }
  return {};
}

// "h12.next is h40, which is dead" (or "... which does not exist (...)", "h12.next is - (a null pointer)").
std::string broken_pointer(const HalfedgeMesh& mesh, const std::string& path, ElementRef target) {
  switch (reference_state(mesh, target)) {
    case RefState::Live: return {};
    case RefState::Null: return path + " is - (a null pointer)";
    case RefState::Dead: return path + " is " + format_id(target) + ", which is dead";
    case RefState::OutOfRange: return path + " is " + format_id(target) + ", which " + missing_text(mesh, target);
  }
  return {};
}

}  // namespace

OpResult<ElementRef> navigate(const HalfedgeMesh& mesh, ElementRef from, NavStep step) {
  OpResult<ElementRef> result;
  const auto refuse = [&](std::string why) {
    result.check = Check::no(std::move(why));
    result.value = ElementRef();
    return result;
  };
  if (!from.valid()) return refuse("nothing is selected");
  if (reference_state(mesh, from) != RefState::Live) return refuse(reference_problem(mesh, from));

  HalfedgeId h;
  std::string path;
  if (from.kind == ElementKind::Halfedge) {
    if (step == NavStep::Halfedge)
      return refuse(format_id(from) + " is already a halfedge; H goes from a vertex, edge or face to its halfedge");
    h = HalfedgeId(from.index);
    path = format_id(h);
  } else {
    h = element_halfedge(mesh, from);
    path = format_id(from) + ".halfedge";
    if (const std::string broken = broken_pointer(mesh, path, h); !broken.empty()) return refuse(broken);
    if (step == NavStep::Halfedge) {
      result.value = h;
      return result;
    }
    path = format_id(h);  // the walk continues from the element's halfedge
  }

  ElementRef target;
  switch (step) {
    case NavStep::Next: target = mesh.next(h); break;
    case NavStep::Twin: target = mesh.twin(h); break;
    case NavStep::Vertex: target = mesh.vertex(h); break;
    case NavStep::Edge: target = mesh.edge(h); break;
    case NavStep::Face: target = mesh.face(h); break;
    case NavStep::Halfedge: break;  // handled above
  }
  const std::string field_path = path + "." + nav_field(step);
  const std::string broken = broken_pointer(mesh, field_path, target);
  if (!broken.empty()) {
    if (from.kind == ElementKind::Halfedge) return refuse(broken);
    return refuse(format_id(from) + ".halfedge is " + format_id(h) + "; " + broken);
  }
  result.value = target;
  return result;
}

bool keep_if_alive(Selection& selection, const HalfedgeMesh& mesh) {
  if (selection.hovered.valid() && !mesh.alive(selection.hovered)) selection.hovered = ElementRef();
  if (selection.selected.valid() && !mesh.alive(selection.selected)) {
    selection.selected = ElementRef();
    return true;
  }
  return false;
}

}  // namespace meshedit
