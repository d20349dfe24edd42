// Catmull-Clark and linear subdivision as document actions (see subdivision_actions.h).
#include "ui/subdivision_actions.h"

#include <new>
#include <string>
#include <utility>

#include "core/linear_subdivision.h"

namespace meshedit {
namespace {

// Made when the program starts, so apply_operation takes them without an allocation that could fail.
const std::string kCatmullClarkLabel = "Catmull-Clark subdivision";
const std::string kLinearLabel = "Linear subdivision";
const std::string kCatmullClarkPhaseLabels[] = {
    "",
    "Catmull-Clark 1/3: compute face, edge and vertex points",
    "Catmull-Clark 2/3: split every face into quads (nothing moves yet)",
    "Catmull-Clark 3/3: move every vertex to its point",
};

bool stepper_current(const MeshDocument& doc, const CatmullClarkStepper& stepper) {
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

const std::string& next_catmull_clark_phase_label(const MeshDocument& doc, const CatmullClarkStepper& stepper) {
  return kCatmullClarkPhaseLabels[stepper.next_phase > 1 && stepper_current(doc, stepper) ? stepper.next_phase : 1];
}

Check catmull_clark_step(MeshDocument& doc, Selection& selection, CatmullClarkStepper& stepper) {
  const bool restarting = stepper.next_phase > 1 && !stepper_current(doc, stepper);
  const int stale_phase = stepper.next_phase - 1;
  const int phase = restarting ? 1 : stepper.next_phase;
  const std::string& label = kCatmullClarkPhaseLabels[phase];
  auto restarted = [&] {
    return restarting ? "the mesh changed after Catmull-Clark phase " + std::to_string(stale_phase) +
                            "; starting again. "
                      : std::string();
  };
  Check check;
  if (phase == 1) {
    OpResult<CatmullClarkState> computed;
    try {
      computed = catmull_clark_compute_points(doc.mesh);
    } catch (const std::bad_alloc&) {
      set_memory_ran_out_message(doc, Severity::Error);
      return Check::no(kMemoryRanOut);
    }
    if (restarting) stepper = CatmullClarkStepper{};
    if (!computed) {
      set_message_noexcept(doc, Severity::Warning, [&] { return restarted() + label + ": " + computed.check.reason; });
      return std::move(computed.check);
    }
    stepper.state = std::move(computed.value);
    set_message_noexcept(doc, Severity::Info, [&] {
      return restarted() + label + ": " + std::to_string(doc.mesh.num_faces()) + " face points, " +
             std::to_string(doc.mesh.num_edges()) + " edge points, " + std::to_string(doc.mesh.num_vertices()) +
             " vertex points; nothing moved yet";
    });
  } else {
    const CatmullClarkState& state = stepper.state;
    check = apply_operation(doc, label, [&](HalfedgeMesh& mesh) {
      if (phase == 2) catmull_clark_refine(mesh, state);
      if (phase == 3) catmull_clark_commit_positions(mesh, state);
      return Check::yes();
    });
    if (phase == 2) keep_vertices_only(selection, doc.mesh);
    if (!check) return check;
  }
  stepper.next_phase = phase == 3 ? 1 : phase + 1;
  stepper.generation = doc.generation;
  stepper.version = doc.mesh.version();
  if (phase == 3) stepper.state = CatmullClarkState{};
  return check;
}

}  // namespace meshedit
