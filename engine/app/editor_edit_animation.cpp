// EditorApp and the animation of edits: whether they play (the policy and View > Animate edits) and drawing the one
// playing over the mesh view, in the view's "changed" colour and highlight sizes, on top of the mesh after the edit.
// The timing and which changes play are app/edit_animator.h's; the pictures are render/edit_animation.h's.
#include "app/editor_app.h"

namespace meshedit {

bool EditorApp::edits_animate() const {
  switch (edit_animation_policy_) {
    case EditAnimationPolicy::Never: return false;
    case EditAnimationPolicy::AsSettingSays: return settings_.animate_edits;
    case EditAnimationPolicy::Always: return true;
  }
  return false;
}

void EditorApp::draw_edit_animation() {
  if (!edit_animator_.playing()) return;
  const RenderStyle& style = mesh_renderer_->style();
  const EditAnimationLook look{style.changed, style.highlight_width + 1.0f, style.highlight_vertex_size};
  overlay_renderer_->draw(camera_, viewport(), edit_animator_.overlay(look));
}

}  // namespace meshedit
