// The window's up axis from the file's and View > Up axis's choice, and the status bar's words for each case.
#include "app/up_axis_choice.h"

#include <gtest/gtest.h>

namespace meshedit {
namespace {

const FileUpAxis kObj{UpAxis::Y, UpAxisSource::Format};
const FileUpAxis kTaggedX{UpAxis::X, UpAxisSource::FileTag};
const FileUpAxis kCourseDae{UpAxis::Z, UpAxisSource::CourseExporter};
const FileUpAxis kLessonY{UpAxis::Y, UpAxisSource::Lesson};

TEST(UpAxisChoice, FromTheFileIsTheFilesAndZWithoutOne) {
  EXPECT_EQ(chosen_up_axis(UpAxisChoice::FromFile, kObj), UpAxis::Y);
  EXPECT_EQ(chosen_up_axis(UpAxisChoice::FromFile, kTaggedX), UpAxis::X);
  EXPECT_EQ(chosen_up_axis(UpAxisChoice::FromFile, kCourseDae), UpAxis::Z);
  EXPECT_EQ(chosen_up_axis(UpAxisChoice::FromFile, std::nullopt), UpAxis::Z);
}

TEST(UpAxisChoice, AChoiceOverridesTheFile) {
  for (const std::optional<FileUpAxis>& file :
       {std::optional<FileUpAxis>(kObj), std::optional<FileUpAxis>(kTaggedX), std::optional<FileUpAxis>()}) {
    EXPECT_EQ(chosen_up_axis(UpAxisChoice::Y, file), UpAxis::Y);
    EXPECT_EQ(chosen_up_axis(UpAxisChoice::Z, file), UpAxis::Z);
  }
}

TEST(UpAxisChoice, TheStatusBarSaysTheAxisAndWhereItCameFrom) {
  EXPECT_EQ(up_axis_status(UpAxisChoice::FromFile, kObj), "Y up (from the file)");
  EXPECT_EQ(up_axis_status(UpAxisChoice::FromFile, kTaggedX), "X up (from the file)");
  EXPECT_EQ(up_axis_status(UpAxisChoice::FromFile, kCourseDae), "Z up (course file)");
  EXPECT_EQ(up_axis_status(UpAxisChoice::FromFile, kLessonY), "Y up (the lesson's)");
  EXPECT_EQ(up_axis_status(UpAxisChoice::FromFile, std::nullopt), "Z up");
  EXPECT_EQ(up_axis_status(UpAxisChoice::Z, kObj), "Z up (View menu)");
  EXPECT_EQ(up_axis_status(UpAxisChoice::Y, std::nullopt), "Y up (View menu)");
}

TEST(UpAxisChoice, TheTooltipSaysWhy) {
  EXPECT_NE(up_axis_status_tooltip(UpAxisChoice::FromFile, kObj).find("format's convention"), std::string_view::npos);
  EXPECT_NE(up_axis_status_tooltip(UpAxisChoice::FromFile, kTaggedX).find("<up_axis>"), std::string_view::npos);
  EXPECT_NE(up_axis_status_tooltip(UpAxisChoice::FromFile, kCourseDae).find("course file"), std::string_view::npos);
  EXPECT_NE(up_axis_status_tooltip(UpAxisChoice::FromFile, kLessonY).find("lesson"), std::string_view::npos);
  EXPECT_NE(up_axis_status_tooltip(UpAxisChoice::FromFile, std::nullopt).find("MeshEdit makes"),
            std::string_view::npos);
  EXPECT_NE(up_axis_status_tooltip(UpAxisChoice::Y, kObj).find("View > Up axis"), std::string_view::npos);
}

}  // namespace
}  // namespace meshedit
