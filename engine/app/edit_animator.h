// EditAnimator: plays the document's flips, splits and collapses, and their undo and redo, in the mesh view for
// kEditAnimationSeconds (render/edit_animation.h), so a student sees the edge turn, the new vertex appear or the two
// ends meet. It follows the document's last change: a new change whose label names one of those operations
// (document/edge_edit_label.h) and that was recorded as a patch starts its animation, an undo's backward; any other
// change stops the one playing.
//
// Invariants:
// - Off until set_enabled(true) (tests, headless pictures and scripted runs leave it off): while off it starts nothing,
//   and turning it off stops the animation playing. Changes made while off are never played later.
// - A change is played at most once, by the follow() that first sees it (by `doc.last.serial`); the first follow()
//   only notes the change it sees.
// - Time moves only by advance(seconds), by at most kMaxStepSeconds a call, so one slow frame cannot skip the motion.
//   playing() is true from the follow() that starts an animation until advance() has moved it kEditAnimationSeconds;
//   overlay() draws it at that time, and is empty when nothing plays.
// - An animation belongs to the mesh state it was made for: once the mesh is another (version or generation), follow()
//   stops it.
#pragma once

#include <cstdint>
#include <optional>

#include "document/mesh_document.h"
#include "render/edit_animation.h"

namespace meshedit {

class EditAnimator {
 public:
  // The longest step one advance() takes, in seconds.
  static constexpr double kMaxStepSeconds = 0.05;

  void set_enabled(bool enabled);
  bool enabled() const { return enabled_; }

  // Reads the document's last change (call each frame before drawing, after the frame's actions).
  void follow(const MeshDocument& doc);
  void advance(double seconds);

  bool playing() const { return animation_.has_value(); }
  // How far the animation playing has come, in [0, 1]; 0 when none plays.
  double time() const { return playing() ? elapsed_ / kEditAnimationSeconds : 0.0; }
  const std::optional<EditAnimation>& animation() const { return animation_; }
  Overlay overlay(const EditAnimationLook& look) const;

 private:
  bool enabled_ = false;
  std::optional<uint64_t> seen_serial_;
  std::optional<EditAnimation> animation_;
  double elapsed_ = 0.0;
  uint64_t generation_ = 0, version_ = 0;  // the mesh state the animation was made for
};

}  // namespace meshedit
