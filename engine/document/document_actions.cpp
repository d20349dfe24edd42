// Key and button actions on a MeshDocument (see document_actions.h for the contracts).
//
// Out of memory: what an action allocates itself before the edit (the edge's refusal sentence, the edit's label, Loop
// phase 1's state) is made before the document changes, and a std::bad_alloc there ends the action with nothing done
// (Error, kMemoryRanOut); the edit runs through apply_operation, undo or redo, which never throw it; every message
// is set with set_message_noexcept or append_to_message, which fall back to kMemoryRanOut; the bookkeeping that
// follows a kept change (the selection, the Loop stepper) allocates nothing. edge_for_operation, asked outside the
// actions too (the exercise session), turns its search's std::bad_alloc into a refusal with kMemoryRanOut.
#include "document/document_actions.h"

#include <new>

#include "core/mesh_ops.h"
#include "core/parallel_for.h"
#include "core/translation.h"
#include "core/triangulate.h"
#include "document/edge_edit_label.h"

namespace meshedit {
namespace {

// The edits' labels as strings made when the program starts: apply_operation takes them without a copy that could run
// out of memory (each is longer than std::string's inline buffer). English in every language (the history keeps them;
// the status line shows them translated).
const std::string kLoopSubdivisionLabel = "Loop subdivision";
const std::string kTriangulateLabel = "Triangulate every face";
const std::string kLoopPhaseLabels[] = {
    "",
    "Loop 1/4: compute new positions",
    "Loop 2/4: split every original edge",
    "Loop 3/4: flip new edges joining an old and a new vertex",
    "Loop 4/4: move every vertex to its new position",
};

bool loop_state_current(const MeshDocument& doc) {
  return doc.loop.generation == doc.generation && doc.loop.version == doc.mesh.version();
}

// What an action that ran out of memory before doing anything says and returns (no allocation: the reason fits
// std::string's inline buffer).
Check memory_ran_out_before_acting(MeshDocument& doc) {
  set_memory_ran_out_message(doc, Severity::Error);
  return Check::no(kMemoryRanOut);
}

// Appends `make_text()` to the message; when that runs out of memory the message becomes kMemoryRanOut (its
// severity kept, at least a Warning). Never throws.
template <class MakeText>
void append_to_message(MeshDocument& doc, MakeText&& make_text) noexcept {
  try {
    doc.message.text += make_text();
  } catch (const std::bad_alloc&) {
    set_memory_ran_out_message(doc, doc.message.severity, doc.message.element);
  }
}

// edge_for_operation without its guard: std::bad_alloc (building a refusal's sentence) escapes.
OpResult<EdgeId> find_edge(const HalfedgeMesh& mesh, ElementRef selected) {
  OpResult<EdgeId> result;
  if (!selected.valid()) {
    result.check = Check::no(tr("select an edge first"));
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
  const char* not_an_edge = "{element} is a {kind}; select an edge (or one of its halfedges) first";
  if (selected.kind == ElementKind::Vertex) {
    not_an_edge = "{element} is a vertex; select an edge (or one of its halfedges) first";
  } else if (selected.kind == ElementKind::Face) {
    not_an_edge = "{element} is a face; select an edge (or one of its halfedges) first";
  } else if (selected.kind == ElementKind::Boundary) {
    not_an_edge = "{element} is a boundary; select an edge (or one of its halfedges) first";
  }
  result.check =
      Check::no(tr_format(not_an_edge, {{"element", format_id(selected)}, {"kind", kind_name(selected.kind)}}));
  return result;
}

// Runs a local operation on the selected edge and reports the outcome on doc.message.
template <class Op>
auto edit_selected_edge(MeshDocument& doc, Selection& selection, EdgeOperation operation, Op op) {
  using Result = decltype(op(doc.mesh, EdgeId()));
  const char* refused = operation == EdgeOperation::Flip    ? "flip: {reason}"
                        : operation == EdgeOperation::Split ? "split: {reason}"
                                                            : "collapse: {reason}";
  Result result{};
  OpResult<EdgeId> edge;
  std::string label;
  try {
    edge = find_edge(doc.mesh, selection.selected);
    if (edge) label = edge_edit_label(operation, edge.value);  // "flip e5": the window reads it back to animate
  } catch (const std::bad_alloc&) {
    result.check = memory_ran_out_before_acting(doc);
    return result;
  }
  if (!edge) {
    set_message_noexcept(doc, Severity::Warning, [&] { return tr_format(refused, {{"reason", edge.check.reason}}); });
    result.check = std::move(edge.check);
    return result;
  }
  const EdgeId e = edge.value;
  result = apply_operation(doc, label, [&](HalfedgeMesh& mesh) { return op(mesh, e); });
  keep_if_alive(selection, doc.mesh);
  return result;
}

}  // namespace

OpResult<EdgeId> edge_for_operation(const HalfedgeMesh& mesh, ElementRef selected) {
  try {
    return find_edge(mesh, selected);
  } catch (const std::bad_alloc&) {
    return {Check::no(kMemoryRanOut), EdgeId()};  // the reason fits std::string's inline buffer: no allocation
  }
}

bool navigate_selection(MeshDocument& doc, Selection& selection, NavStep step) {
  OpResult<ElementRef> target;
  try {
    target = navigate(doc.mesh, selection.selected, step);
  } catch (const std::bad_alloc&) {
    memory_ran_out_before_acting(doc);
    return false;
  }
  if (!target) {
    set_message_noexcept(doc, Severity::Warning, [&] {
      return std::string(1, nav_key(step)) + " (" + nav_field(step) + "): " + target.check.reason;
    });
    return false;
  }
  selection.selected = target.value;
  set_message_noexcept(doc, Severity::Info, [&] {
    return tr_format("{key}: selected {element}",
                     {{"key", std::string(1, nav_key(step))}, {"element", format_id(target.value)}});
  });
  return true;
}

bool select_element(MeshDocument& doc, Selection& selection, ElementRef element) {
  if (!in_range(doc.mesh, element)) {
    set_message_noexcept(doc, Severity::Warning, [&] {
      return tr_format("cannot select: {why}", {{"why", reference_problem(doc.mesh, element)}});
    });
    return false;
  }
  selection.selected = element;
  return true;
}

Check flip_selected(MeshDocument& doc, Selection& selection) {
  const auto flip_edge = [](HalfedgeMesh& m, EdgeId e) { return flip(m, e); };
  return edit_selected_edge(doc, selection, EdgeOperation::Flip, flip_edge).check;
}

Check split_selected(MeshDocument& doc, Selection& selection) {
  const auto split_edge = [](HalfedgeMesh& m, EdgeId e) { return split(m, e); };
  OpResult<VertexId> result = edit_selected_edge(doc, selection, EdgeOperation::Split, split_edge);
  if (result) {
    append_to_message(doc, [&] { return tr_format("; new vertex {vertex}", {{"vertex", format_id(result.value)}}); });
  }
  return std::move(result.check);
}

Check collapse_selected(MeshDocument& doc, Selection& selection) {
  const auto collapse_edge = [](HalfedgeMesh& m, EdgeId e) { return collapse(m, e); };
  OpResult<VertexId> result = edit_selected_edge(doc, selection, EdgeOperation::Collapse, collapse_edge);
  if (result) {
    selection.selected = result.value;
    append_to_message(doc, [&] { return tr_format("; {vertex} remains", {{"vertex", format_id(result.value)}}); });
  }
  return std::move(result.check);
}

Check loop_subdivide_all(MeshDocument& doc, Selection& selection, LoopWeights weights) {
  Check check = apply_operation(doc, kLoopSubdivisionLabel, [&](HalfedgeMesh& mesh) {
    return loop_subdivide(mesh, weights, 1, hardware_threads());  // the same mesh on any thread count
  });
  keep_if_alive(selection, doc.mesh);
  if (check) doc.loop = LoopStepper{};
  return check;
}

Check triangulate_all(MeshDocument& doc, Selection& selection) {
  TriangulationReport report;
  Check check = apply_operation(doc, kTriangulateLabel, [&](HalfedgeMesh& mesh) {
    OpResult<TriangulationReport> done = triangulate_mesh(mesh);
    report = done.value;
    return std::move(done.check);
  });
  if (!check) return check;
  selection = Selection{};  // the mesh was rebuilt: an id now names another element
  doc.loop = LoopStepper{};
  append_to_message(doc, [&] {
    if (report.polygons_split == 0) return std::string(tr("; every face was already a triangle"));
    return tr_format(
        "; {faces} faces split into {triangles} triangles",
        {{"faces", std::to_string(report.polygons_split)}, {"triangles", std::to_string(report.triangles_made)}});
  });
  return check;
}

const std::string& next_loop_phase_label(const MeshDocument& doc) {
  const int phase = doc.loop.next_phase > 1 && loop_state_current(doc) ? doc.loop.next_phase : 1;
  return kLoopPhaseLabels[phase];
}

Check loop_subdivide_step(MeshDocument& doc, Selection& selection, LoopWeights weights) {
  // The mesh changed since the last phase: this press starts again at phase 1 (doc.loop is reset once phase 1 has
  // run, so a press that runs out of memory leaves the stepper as it was).
  const bool restarting = doc.loop.next_phase > 1 && !loop_state_current(doc);
  const int stale_phase = doc.loop.next_phase - 1;
  const int phase = restarting ? 1 : doc.loop.next_phase;
  const std::string& label = kLoopPhaseLabels[phase];
  auto restarted = [&] {
    return restarting ? tr_format("the mesh changed after {scheme} phase {phase}; starting again. ",
                                  {{"scheme", "Loop"}, {"phase", std::to_string(stale_phase)}})
                      : std::string();
  };
  Check check;
  if (phase == 1) {
    OpResult<LoopState> state;
    try {
      state = loop_compute_positions(doc.mesh, weights);
    } catch (const std::bad_alloc&) {
      return memory_ran_out_before_acting(doc);
    }
    if (restarting) doc.loop = LoopStepper{};
    if (!state) {
      set_message_noexcept(doc, Severity::Warning, [&] {
        return restarted() + tr_format("{change}: {reason}", {{"change", tr(label)}, {"reason", state.check.reason}});
      });
      return std::move(state.check);
    }
    doc.loop.state = std::move(state.value);
    set_message_noexcept(doc, Severity::Info, [&] {
      return restarted() + tr_format(
                               "{change}: positions for {vertices} vertices and {points} edge points; nothing "
                               "moved yet",
                               {{"change", tr(label)},
                                {"vertices", std::to_string(doc.mesh.num_vertices())},
                                {"points", std::to_string(doc.loop.state.original_edges.size())}});
    });
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
