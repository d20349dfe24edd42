// ViewRoom and the up axis: View > Up axis's choice and what the camera and the status bar show of it (see
// app/up_axis_choice.h for the rule, view_showing.cpp and lesson_room.cpp for where a file or a lesson sets it).
#include "app/document_room.h"
#include "app/view_room.h"
#include "render/mesh_geometry.h"

namespace meshedit {

bool ViewRoom::apply_up_axis() noexcept {
  status_bar_.up_axis = up_axis_status(up_axis_choice_, file_up_axis_);
  status_bar_.up_axis_why = up_axis_status_tooltip(up_axis_choice_, file_up_axis_);
  const UpAxis up = chosen_up_axis(up_axis_choice_, file_up_axis_);
  if (camera_.up_axis() == up) return false;
  camera_.set_up_axis(up);
  return true;
}

void ViewRoom::follow_lesson_up_axis() noexcept {
  up_axis_choice_ = UpAxisChoice::FromFile;
  if (apply_up_axis()) fit_camera();
}

void ViewRoom::choose_up_axis(UpAxisChoice choice) {
  up_axis_choice_ = choice;
  apply_up_axis();
  if (mode_ == ViewMode::Patches && patches_.tessellation.mesh) {
    fit_camera(mesh_bounds(*patches_.tessellation.mesh));
  } else {
    fit_camera(mesh_bounds(document_.doc().mesh));
  }
}

}  // namespace meshedit
