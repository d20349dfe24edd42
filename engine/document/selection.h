// Selection and pointer navigation: the course viewers' N/T/V/E/F/H keys as pure functions.
//
// Invariants:
// - Nothing here reads a mesh array through an id before checking that the id is in range, so a selection
//   or a pointer that a script or a bug left dangling is reported, never followed.
// - Navigation never lands on a dead or missing element: it refuses with a sentence that names the pointer
//   ("h12.next is h40, which is dead") and the caller keeps the old selection.
// - An element's selection survives an edit exactly when the element does (ids are never reused, so a live
//   id after an edit is the same element).
#pragma once

#include <string>
#include <string_view>

#include "core/check.h"
#include "core/halfedge_mesh.h"

namespace meshedit {

// What the user has clicked (selected) and what is under the cursor (hovered). An invalid ElementRef means
// none. The app sets `hovered` from picking each frame; panels set it while a link or row is under the mouse.
struct Selection {
  ElementRef selected;
  ElementRef hovered;
};

// The keys students know from the course viewers.
enum class NavStep { Next, Twin, Vertex, Edge, Face, Halfedge };
char nav_key(NavStep step);           // 'N', 'T', 'V', 'E', 'F', 'H'
const char* nav_field(NavStep step);  // "next", "twin", "vertex", "edge", "face", "halfedge"

// Whether a reference can be followed.
enum class RefState { Live, Dead, OutOfRange, Null };
RefState reference_state(const HalfedgeMesh& mesh, ElementRef ref);
// The element `id` names ("e7", as format_id writes it) when it is a live element of `mesh`; invalid otherwise.
ElementRef live_element(const HalfedgeMesh& mesh, std::string_view id);
// True when the slot exists (live or dead), i.e. its stored fields may be read.
bool in_range(const HalfedgeMesh& mesh, ElementRef ref);
// "h40 is dead", "h999 does not exist (halfedges h0..h47)", "- is no halfedge (a null pointer)"; "" when live.
std::string reference_problem(const HalfedgeMesh& mesh, ElementRef ref);

// One step from `from`:
// - from a halfedge h: N h.next, T h.twin, V h.vertex, E h.edge, F h.face (a face or a boundary loop);
//   H is refused (h is already a halfedge).
// - from a vertex, edge, face or boundary loop x: H selects x.halfedge; the other keys first go to
//   x.halfedge and then follow that field (as the course viewer does: N on a face gives its second halfedge).
// Refused (value invalid, reason set) when `from` is none, missing or dead, or when any pointer on the way
// is null, out of range or dead.
OpResult<ElementRef> navigate(const HalfedgeMesh& mesh, ElementRef from, NavStep step);

// Clears `selected` and `hovered` where their element is no longer alive (after an edit, an undo, or
// opening another mesh). Returns true when `selected` was cleared.
bool keep_if_alive(Selection& selection, const HalfedgeMesh& mesh);

}  // namespace meshedit
