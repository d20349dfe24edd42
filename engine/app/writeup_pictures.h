// draw_writeup_pictures: the PNG bytes of every picture of a write-up (writeup/writeup.h), drawn by the window's own
// renderers: a mesh by MeshRenderer as the mesh view draws it (flat or Phong, the wireframe, the marked edges in the
// "changed" colour, a patch's control net by OverlayRenderer), a curve by the curve view's canvas
// (ui/curve_editor.h's draw_curve_picture) through Dear ImGui's OpenGL backend.
//
// Invariants:
// - Needs a current OpenGL context (`meshedit writeup`'s OffscreenContext, or the window's between two frames) and no
//   current ImGui frame: it makes an ImGui context of its own and leaves the caller's current when it returns.
// - The pictures of one figure share one camera, fitted to all of their meshes, so before and after line up; a flat
//   mesh is seen from above, anything else from the write-up's camera.
// - A picture that cannot be drawn (no mesh, a renderer refusal) keeps its empty `png`, and the return value says
//   why; the rest are drawn.
// - The same write-up gives the same bytes on the same machine (no clock, no state kept between calls).
#pragma once

#include <string>

#include "writeup/writeup.h"

namespace meshedit {

inline constexpr int kWriteupPictureWidth = 480, kWriteupPictureHeight = 360;

// Fills every picture's png; "" when all were drawn, else one sentence on the first that was not.
std::string draw_writeup_pictures(Writeup& writeup);

}  // namespace meshedit
