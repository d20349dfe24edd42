// The command table's mesh edits (see mesh_edits.h).
#include "document/mesh_edits.h"

#include "document/document_actions.h"

namespace meshedit {
namespace {

const SubdivisionStepper& stepper(SubdivisionScheme scheme, const MeshEditState& state) {
  return scheme == SubdivisionScheme::CatmullClark ? state.catmull_clark : state.linear;
}

}  // namespace

bool is_mesh_edit(CommandId id) {
  switch (id) {
    case CommandId::Flip:
    case CommandId::Split:
    case CommandId::Collapse:
    case CommandId::Triangulate:
    case CommandId::Loop:
    case CommandId::LoopPhase:
    case CommandId::CatmullClark:
    case CommandId::CatmullClarkPhase:
    case CommandId::Linear:
    case CommandId::LinearPhase: return true;
    default: return false;
  }
}

Check run_mesh_edit(CommandId id, MeshDocument& doc, Selection& selection, MeshEditState& state) {
  switch (id) {
    case CommandId::Flip: return flip_selected(doc, selection);
    case CommandId::Split: return split_selected(doc, selection);
    case CommandId::Collapse: return collapse_selected(doc, selection);
    case CommandId::Triangulate: return triangulate_all(doc, selection);
    case CommandId::Loop: return loop_subdivide_all(doc, selection, state.loop_weights);
    case CommandId::LoopPhase: return loop_subdivide_step(doc, selection, state.loop_weights);
    case CommandId::CatmullClark: return catmull_clark_all(doc, selection);
    case CommandId::CatmullClarkPhase: return subdivision_step(doc, selection, state.catmull_clark);
    case CommandId::Linear: return linear_subdivide_all(doc, selection);
    case CommandId::LinearPhase: return subdivision_step(doc, selection, state.linear);
    default: return Check::no("not a mesh edit");
  }
}

CommandId subdivide_command(SubdivisionScheme scheme, bool one_phase) {
  switch (scheme) {
    case SubdivisionScheme::Loop: return one_phase ? CommandId::LoopPhase : CommandId::Loop;
    case SubdivisionScheme::CatmullClark: return one_phase ? CommandId::CatmullClarkPhase : CommandId::CatmullClark;
    case SubdivisionScheme::Linear: break;
  }
  return one_phase ? CommandId::LinearPhase : CommandId::Linear;
}

const std::string& next_phase_label(SubdivisionScheme scheme, const MeshDocument& doc, const MeshEditState& state) {
  if (scheme == SubdivisionScheme::Loop) return next_loop_phase_label(doc);
  return next_phase_label(doc, stepper(scheme, state));
}

std::optional<int> stale_phase(SubdivisionScheme scheme, const MeshDocument& doc, const MeshEditState& state) {
  if (scheme == SubdivisionScheme::Loop) {
    const LoopStepper& loop = doc.loop;
    const bool current = loop.generation == doc.generation && loop.version == doc.mesh.version();
    if (loop.next_phase > 1 && !current) return loop.next_phase - 1;
    return std::nullopt;
  }
  const SubdivisionStepper& s = stepper(scheme, state);
  const bool current = s.generation == doc.generation && s.version == doc.mesh.version();
  if (s.phases.computed() && !current) return s.phases.next_phase() - 1;
  return std::nullopt;
}

}  // namespace meshedit
