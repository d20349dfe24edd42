// The status bar along the bottom of the window: V/E/F/H counts, Euler characteristic, validation state (green
// "valid", or red with the first broken invariant and a button that selects its element), the message line,
// a standing note from the view (what it dropped to keep frames fast), the view's up axis, undo/redo hints and the
// frame time.
//
// Invariants:
// - validate() runs through the document's cache: at most once per mesh state. Meshes with more halfedges than
//   StatusBarState::auto_validate_max_halfedges are validated only when the user presses "validate", unless the
//   cache can answer without a whole-mesh pass (cached_validation_if_cheap: a vouched mesh, or a local edit of a
//   state it found valid that its patch shows kept it valid), so edits on a big mesh stay validated once it has
//   been; an edit that breaks it waits for the button (the report needs a walk of the whole mesh).
// - Counts and the Euler characteristic come from the mesh's live counters: O(1) per frame.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

#include "document/mesh_document.h"
#include "document/selection.h"
#include "ui/element_link.h"

namespace meshedit {

struct StatusBarState {
  size_t auto_validate_max_halfedges = 4000000;  // ~1.3M triangles: a whole-mesh validate() past it costs frames
  UiProbe* probe = nullptr;                      // tests: where the buttons were drawn
  bool mesh_shown = true;  // the mesh view is on screen: counts, validation and undo (else the message line only)
  bool view_is_3d = true;  // the up axis means something (not in the curve view)
  std::string note;        // a standing remark from the view ("frame 62 ms: multisampling off"); "" for none
  // The view's up axis ("Y up (from the file)") and where it came from, for its tooltip: NUL-terminated English
  // literals the app fills (app/up_axis_choice.h), shown in the window's language; "" shows nothing.
  std::string_view up_axis;
  std::string_view up_axis_why;
};

// Draws the bar as a borderless window across the bottom of the main viewport. Returns its height in pixels,
// so the app can keep the mesh view above it. Its "select" buttons change selection.selected.
float draw_status_bar(MeshDocument& doc, Selection& selection, StatusBarState& state, float frame_ms);

}  // namespace meshedit
