// Key and button actions on a MeshDocument (see document_actions.h for the contracts).
#include "ui/document_actions.h"

#include "core/mesh_ops.h"
#include "core/parallel_for.h"

namespace meshedit {
namespace {

const char* const kLoopPhaseLabels[] = {
    "",
    "Loop 1/4: compute new positions",
    "Loop 2/4: split every original edge",
    "Loop 3/4: flip new edges joining an old and a new vertex",
    "Loop 4/4: move every vertex to its new position",
};

bool loop_state_current(const MeshDocument& doc) {
  return doc.loop.generation == doc.generation && doc.loop.version == doc.mesh.version();
}

// Runs a local operation on the selected edge and reports the outcome on doc.message.
template <class Op>
auto edit_selected_edge(MeshDocument& doc, Selection& selection, const char* verb, Op op) {
  using Result = decltype(op(doc.mesh, EdgeId()));
  const OpResult<EdgeId> edge = edge_for_operation(doc.mesh, selection.selected);
  if (!edge) {
    set_message(doc, Severity::Warning, std::string(verb) + ": " + edge.check.reason);
    return Result{edge.check, {}};
  }
  const EdgeId e = edge.value;
  Result result =
      apply_operation(doc, std::string(verb) + " " + format_id(e), [&](HalfedgeMesh& mesh) { return op(mesh, e); });
  keep_if_alive(selection, doc.mesh);
  return result;
}

}  // namespace

OpResult<EdgeId> edge_for_operation(const HalfedgeMesh& mesh, ElementRef selected) {
  OpResult<EdgeId> result;
  if (!selected.valid()) {
    result.check = Check::no("select an edge first");
    return result;
  }
  if (selected.kind == ElementKind::Edge) {
    if (const std::string problem = reference_problem(mesh, selected); !problem.empty()) {
      result.check = Check::no(problem);
      return result;
    }
    result.value = EdgeId(selected.index);
    return result;
  }
  if (selected.kind == ElementKind::Halfedge) {
    const OpResult<ElementRef> edge = navigate(mesh, selected, NavStep::Edge);
    if (!edge) {
      result.check = edge.check;
      return result;
    }
    result.value = EdgeId(edge.value.index);
    return result;
  }
  result.check = Check::no(format_id(selected) + " is a " + kind_name(selected.kind) +
                           "; select an edge (or one of its halfedges) first");
  return result;
}

bool navigate_selection(MeshDocument& doc, Selection& selection, NavStep step) {
  const OpResult<ElementRef> target = navigate(doc.mesh, selection.selected, step);
  if (!target) {
    set_message(doc, Severity::Warning, std::string(1, nav_key(step)) + " (" + nav_field(step) + "): " +
                                            target.check.reason);
    return false;
  }
  selection.selected = target.value;
  set_message(doc, Severity::Info, std::string(1, nav_key(step)) + ": selected " + format_id(target.value));
  return true;
}

bool select_element(MeshDocument& doc, Selection& selection, ElementRef element) {
  if (!in_range(doc.mesh, element)) {
    set_message(doc, Severity::Warning, "cannot select: " + reference_problem(doc.mesh, element));
    return false;
  }
  selection.selected = element;
  return true;
}

Check flip_selected(MeshDocument& doc, Selection& selection) {
  return edit_selected_edge(doc, selection, "flip", [](HalfedgeMesh& m, EdgeId e) { return flip(m, e); }).check;
}

Check split_selected(MeshDocument& doc, Selection& selection) {
  const OpResult<VertexId> result =
      edit_selected_edge(doc, selection, "split", [](HalfedgeMesh& m, EdgeId e) { return split(m, e); });
  if (result) doc.message.text += "; new vertex " + format_id(result.value);
  return result.check;
}

Check collapse_selected(MeshDocument& doc, Selection& selection) {
  const OpResult<VertexId> result =
      edit_selected_edge(doc, selection, "collapse", [](HalfedgeMesh& m, EdgeId e) { return collapse(m, e); });
  if (result) {
    selection.selected = result.value;
    doc.message.text += "; " + format_id(result.value) + " remains";
  }
  return result.check;
}

Check loop_subdivide_all(MeshDocument& doc, Selection& selection, LoopWeights weights) {
  const Check check = apply_operation(doc, "Loop subdivision", [&](HalfedgeMesh& mesh) {
    return loop_subdivide(mesh, weights, 1, hardware_threads());  // the same mesh on any thread count
  });
  keep_if_alive(selection, doc.mesh);
  if (check) doc.loop = LoopStepper{};
  return check;
}

std::string next_loop_phase_label(const MeshDocument& doc) {
  const int phase = doc.loop.next_phase > 1 && loop_state_current(doc) ? doc.loop.next_phase : 1;
  return kLoopPhaseLabels[phase];
}

Check loop_subdivide_step(MeshDocument& doc, Selection& selection, LoopWeights weights) {
  std::string restarted;
  if (doc.loop.next_phase > 1 && !loop_state_current(doc)) {
    restarted = "the mesh changed after Loop phase " + std::to_string(doc.loop.next_phase - 1) + "; starting again. ";
    doc.loop = LoopStepper{};
  }
  const int phase = doc.loop.next_phase;
  const std::string label = kLoopPhaseLabels[phase];
  Check check;
  if (phase == 1) {
    OpResult<LoopState> state = loop_compute_positions(doc.mesh, weights);
    if (!state) {
      set_message(doc, Severity::Warning, restarted + label + ": " + state.check.reason);
      return state.check;
    }
    doc.loop.state = std::move(state.value);
    set_message(doc, Severity::Info,
                restarted + label + ": positions for " + std::to_string(doc.mesh.num_vertices()) + " vertices and " +
                    std::to_string(doc.loop.state.original_edges.size()) + " edge points; nothing moved yet");
  } else {
    LoopState& state = doc.loop.state;
    check = apply_operation(doc, label, [&](HalfedgeMesh& mesh) {
      if (phase == 2) loop_split_edges(mesh, state);
      if (phase == 3) loop_flip_edges(mesh, state);
      if (phase == 4) loop_commit_positions(mesh, state);
      return Check::yes();
    });
    keep_if_alive(selection, doc.mesh);
    if (!check) return check;
    if (!restarted.empty()) doc.message.text.insert(0, restarted);
  }
  doc.loop.next_phase = phase == 4 ? 1 : phase + 1;
  doc.loop.generation = doc.generation;
  doc.loop.version = doc.mesh.version();
  if (phase == 4) doc.loop.state = LoopState{};
  return check;
}

bool undo_edit(MeshDocument& doc, Selection& selection) {
  const bool done = undo(doc);
  keep_if_alive(selection, doc.mesh);
  return done;
}

bool redo_edit(MeshDocument& doc, Selection& selection) {
  const bool done = redo(doc);
  keep_if_alive(selection, doc.mesh);
  return done;
}

}  // namespace meshedit
