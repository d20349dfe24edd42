// The window's Catmull-Clark and linear subdivision actions (Subdivide menu), beside Loop's in document_actions.h.
//
// Invariants, as for every document action: each is one undoable step through apply_operation, labelled
// "Catmull-Clark subdivision" or "Linear subdivision"; a refusal changes nothing but the message (a Warning with the
// core's reason); the selection keeps what survives (original vertices keep their ids; every original edge and face
// is replaced, so they are deselected); the Loop stepper is reset, since its next phase would start again anyway.
// No action throws std::bad_alloc (the labels are made when the program starts; apply_operation catches the rest).
#pragma once

#include "core/check.h"
#include "ui/mesh_document.h"
#include "ui/selection.h"

namespace meshedit {

Check catmull_clark_all(MeshDocument& doc, Selection& selection);
Check linear_subdivide_all(MeshDocument& doc, Selection& selection);

}  // namespace meshedit
