// markdown_to_plain and the words LessonWait uses for the panel and the headless transcript.
#include <gtest/gtest.h>

#include "lesson/lesson_events.h"
#include "lesson/lesson_text.h"

namespace meshedit {
namespace {

TEST(LessonText, MarkdownBecomesPlainText) {
  EXPECT_EQ(markdown_to_plain("# Flip\n\nPress **F** to *flip* `e7`."), "Flip\n\nPress F to flip e7.");
  EXPECT_EQ(markdown_to_plain("### Deep heading"), "Deep heading");
  EXPECT_EQ(markdown_to_plain("#hashtag stays"), "#hashtag stays");
  EXPECT_EQ(markdown_to_plain("- one\n* two\n  - nested **bold**"), "- one\n- two\n  - nested bold");
  EXPECT_EQ(markdown_to_plain("see [the notes](docs/notes.md) now"), "see the notes (docs/notes.md) now");
  // Code keeps its text verbatim: stars and underscores inside it survive.
  EXPECT_EQ(markdown_to_plain("`a * b` and `current_mesh()`"), "a * b and current_mesh()");
  EXPECT_EQ(markdown_to_plain("line\r\nnext"), "line\nnext");
  EXPECT_EQ(markdown_to_plain("unclosed `tick"), "unclosed `tick");
  EXPECT_EQ(markdown_to_plain(""), "");
}

TEST(LessonEvents, WaitsMatchOnlyTheirEvent) {
  LessonWait key;
  key.kind = LessonWait::Kind::Key;
  key.name = "shift+L";
  EXPECT_TRUE(key.matches(LessonEvent::key("Shift+l")));
  EXPECT_FALSE(key.matches(LessonEvent::key("L")));
  EXPECT_FALSE(key.matches(LessonEvent::button("shift+L")));

  LessonWait any_click;
  any_click.kind = LessonWait::Kind::Click;
  EXPECT_TRUE(any_click.matches(LessonEvent::click(ElementRef(FaceId::boundary(0)))));
  EXPECT_FALSE(any_click.matches(LessonEvent::click(ElementRef())));  // a click on nothing
  EXPECT_FALSE(any_click.matches(LessonEvent::selection(ElementRef(VertexId(0)))));
  EXPECT_EQ(any_click.describe(), "a click on an element");

  LessonWait edge;
  edge.kind = LessonWait::Kind::Selection;
  edge.element_kind = ElementKind::Edge;
  EXPECT_TRUE(edge.selection_matches(ElementRef(EdgeId(9))));
  EXPECT_FALSE(edge.selection_matches(ElementRef(HalfedgeId(9))));
  EXPECT_EQ(edge.describe(), "the selection of an edge");

  LessonWait animation;
  animation.kind = LessonWait::Kind::Animation;
  animation.seconds = 2.5;
  EXPECT_EQ(animation.describe(), "an animation (2.5 s)");
  EXPECT_FALSE(animation.selection_matches(ElementRef(VertexId(0))));
  EXPECT_EQ(LessonWait().describe(), "");
}

}  // namespace
}  // namespace meshedit
