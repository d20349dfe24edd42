// Catmull-Clark and linear subdivision as document actions (see subdivision_actions.h).
#include "document/subdivision_actions.h"

#include <new>
#include <string>
#include <utility>

#include "core/catmull_clark.h"
#include "core/linear_subdivision.h"
#include "core/translation.h"

namespace meshedit {
namespace {

// Made when the program starts, so apply_operation takes them without an allocation that could fail. English in every
// language (the history keeps them; the status line shows them translated).
const std::string kCatmullClarkLabel = "Catmull-Clark subdivision";
const std::string kLinearLabel = "Linear subdivision";
bool stepper_current(const MeshDocument& doc, const SubdivisionStepper& stepper) {
  return stepper.generation == doc.generation && stepper.version == doc.mesh.version();
}

// Original edges and faces do not survive a refinement; original vertices keep their ids.
void keep_vertices_only(Selection& selection, const HalfedgeMesh& mesh) {
  if (selection.selected.kind != ElementKind::Vertex) selection.selected = ElementRef();
  if (selection.hovered.kind != ElementKind::Vertex) selection.hovered = ElementRef();
  keep_if_alive(selection, mesh);
}

Check subdivide_all(MeshDocument& doc, Selection& selection, const std::string& label,
                    Check (*subdivide)(HalfedgeMesh&, int)) {
  Check check = apply_operation(doc, label, [&](HalfedgeMesh& mesh) { return subdivide(mesh, 1); });
  if (check) {
    keep_vertices_only(selection, doc.mesh);
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

const std::string& next_phase_label(const MeshDocument& doc, const SubdivisionStepper& stepper) {
  const SubdivisionPhases& phases = stepper.phases;
  return phase_label(phases.scheme(), phases.computed() && stepper_current(doc, stepper) ? phases.next_phase() : 1);
}

Check subdivision_step(MeshDocument& doc, Selection& selection, SubdivisionStepper& stepper) {
  SubdivisionPhases& phases = stepper.phases;
  const bool restarting = phases.computed() && !stepper_current(doc, stepper);
  const int stale_phase = phases.next_phase() - 1;
  const int phase = restarting ? 1 : phases.next_phase();
  const std::string& label = phase_label(phases.scheme(), phase);
  auto restarted = [&] {
    return restarting ? tr_format("the mesh changed after {scheme} phase {phase}; starting again. ",
                                  {{"scheme", scheme_title(phases.scheme())}, {"phase", std::to_string(stale_phase)}})
                      : std::string();
  };
  Check check;
  if (phase == 1) {
    // Phase 1 reads the mesh and allocates its points before anything changes: memory running out there does nothing.
    SubdivisionPhases computed(phases.scheme());
    try {
      check = computed.run_next(doc.mesh);
    } catch (const std::bad_alloc&) {
      set_memory_ran_out_message(doc, Severity::Error);
      return Check::no(kMemoryRanOut);
    }
    phases = std::move(computed);
    if (!check) {
      set_message_noexcept(doc, Severity::Warning, [&] {
        return restarted() + tr_format("{change}: {reason}", {{"change", tr(label)}, {"reason", check.reason}});
      });
      return check;
    }
    set_message_noexcept(doc, Severity::Info, [&] {
      return restarted() + tr_format("{change}: {summary}; nothing moved yet",
                                     {{"change", tr(label)}, {"summary", phases.computed_summary()}});
    });
  } else {
    check = apply_operation(doc, label, [&](HalfedgeMesh& mesh) { return phases.run_next(mesh); });
    if (phase == 2) keep_vertices_only(selection, doc.mesh);  // every scheme refines in phase 2
    if (!check) return check;
  }
  stepper.generation = doc.generation;
  stepper.version = doc.mesh.version();
  return check;
}

}  // namespace meshedit
