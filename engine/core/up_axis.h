// UpAxis: the world axis that points up on screen when a mesh is shown. Files disagree on it (glTF and most
// .obj exports are Y-up, Blender and the course's files are Z-up, COLLADA says which in <up_axis>), so it is
// a property of what is shown, carried from the file to the camera (render/camera.h), and never changes the
// mesh's positions.
//
// Each axis comes with COLLADA's frame for it (COLLADA 1.4.1 spec, <up_axis>), which fixes what the front
// view shows: the axis pointing right and the one pointing towards the viewer.
//   X up: right -Y, towards the viewer +Z
//   Y up: right +X, towards the viewer +Z
//   Z up: right +X, towards the viewer -Y
// Every frame is right-handed: right x up = towards the viewer.
#pragma once

#include <string_view>

namespace meshedit {

enum class UpAxis { X, Y, Z };

// "X up", "Y up", "Z up": what the window's menu and status bar call it.
constexpr std::string_view up_axis_name(UpAxis axis) {
  switch (axis) {
    case UpAxis::X: return "X up";
    case UpAxis::Y: return "Y up";
    case UpAxis::Z: return "Z up";
  }
  return "Z up";
}

}  // namespace meshedit
