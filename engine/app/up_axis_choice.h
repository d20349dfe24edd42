// The window's up axis: the file's (io/file_up_axis.h) unless View > Up axis chooses one, and the status bar's words
// for it.
//
// Invariants:
// - What the window shows that no file gave it (the start cube, a lesson's mesh, a mesh shown by name) is Z-up, as
//   core's primitives are: `file` is nullopt for it.
// - The choice belongs to what is shown: opening a file or a lesson goes back to FromFile (editor_files.cpp,
//   lesson_room.cpp), so a lesson's mesh is Z-up even after a file before it was turned by hand.
// - The words are static text and nothing here allocates or throws, so the window switches its up axis in the steps
//   of showing a file that cannot fail.
#pragma once

#include <optional>
#include <string_view>

#include "core/up_axis.h"
#include "io/file_up_axis.h"

namespace meshedit {

enum class UpAxisChoice { FromFile, Y, Z };

// The axis the camera uses.
UpAxis chosen_up_axis(UpAxisChoice choice, const std::optional<FileUpAxis>& file) noexcept;
// The status bar's text: "Y up (from the file)", "Z up (course file)", "Z up" (no file), "Y up (View menu)".
std::string_view up_axis_status(UpAxisChoice choice, const std::optional<FileUpAxis>& file) noexcept;
// Its tooltip: where the axis came from, and how to change it.
std::string_view up_axis_status_tooltip(UpAxisChoice choice, const std::optional<FileUpAxis>& file) noexcept;

}  // namespace meshedit
