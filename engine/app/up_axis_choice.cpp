// The window's up axis and its words (see up_axis_choice.h).
#include "app/up_axis_choice.h"

namespace meshedit {

UpAxis chosen_up_axis(UpAxisChoice choice, const std::optional<FileUpAxis>& file) noexcept {
  switch (choice) {
    case UpAxisChoice::Y: return UpAxis::Y;
    case UpAxisChoice::Z: return UpAxis::Z;
    case UpAxisChoice::FromFile: break;
  }
  return file ? file->up_axis : UpAxis::Z;
}

std::string_view up_axis_status(UpAxisChoice choice, const std::optional<FileUpAxis>& file) noexcept {
  switch (choice) {
    case UpAxisChoice::Y: return "Y up (View menu)";
    case UpAxisChoice::Z: return "Z up (View menu)";
    case UpAxisChoice::FromFile: break;
  }
  if (!file) return "Z up";
  if (file->source == UpAxisSource::CourseExporter) return "Z up (course file)";
  // By axis, in UpAxis order: what the file says, or what the lesson says of the file it read.
  static_assert(int(UpAxis::X) == 0 && int(UpAxis::Y) == 1 && int(UpAxis::Z) == 2);
  constexpr std::string_view kFromTheFile[] = {"X up (from the file)", "Y up (from the file)", "Z up (from the file)"};
  constexpr std::string_view kTheLessons[] = {"X up (the lesson's)", "Y up (the lesson's)", "Z up (the lesson's)"};
  return (file->source == UpAxisSource::Lesson ? kTheLessons : kFromTheFile)[int(file->up_axis)];
}

std::string_view up_axis_status_tooltip(UpAxisChoice choice, const std::optional<FileUpAxis>& file) noexcept {
  if (choice != UpAxisChoice::FromFile) return "Chosen in View > Up axis (\"From the file\" goes back to the file's)";
  if (!file) return "Every mesh MeshEdit makes is Z-up (View > Up axis changes it)";
  switch (file->source) {
    case UpAxisSource::Format: return "The format's convention (View > Up axis changes it)";
    case UpAxisSource::FileTag: return "What the file's <up_axis> says (View > Up axis changes it)";
    case UpAxisSource::CourseExporter:
      return "A CS184 course file: Z-up, although its exporter tagged it Y_UP (View > Up axis changes it)";
    case UpAxisSource::Lesson: return "The lesson shows this mesh as its file is meant (View > Up axis changes it)";
  }
  return "View > Up axis changes it";
}

}  // namespace meshedit
