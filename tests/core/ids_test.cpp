// The one id formatter and its parser.
#include <gtest/gtest.h>

#include "core/ids.h"

namespace meshedit {
namespace {

TEST(Ids, FormatsEveryKind) {
  EXPECT_EQ(format_id(VertexId(12)), "v12");
  EXPECT_EQ(format_id(HalfedgeId(37)), "h37");
  EXPECT_EQ(format_id(EdgeId(5)), "e5");
  EXPECT_EQ(format_id(FaceId::face(3)), "f3");
  EXPECT_EQ(format_id(FaceId::boundary(0)), "b0");
  EXPECT_EQ(format_id(HalfedgeId()), "-");
  EXPECT_EQ(format_id(FaceId()), "-");
}

TEST(Ids, BoundaryBitIsPartOfTheId) {
  const FaceId b = FaceId::boundary(7), f = FaceId::face(7);
  EXPECT_TRUE(b.is_boundary());
  EXPECT_FALSE(f.is_boundary());
  EXPECT_EQ(b.slot(), 7u);
  EXPECT_NE(b, f);
  EXPECT_EQ(ElementRef(b).kind, ElementKind::Boundary);
  EXPECT_EQ(ElementRef(b).face_id(), b);
  EXPECT_FALSE(FaceId().is_boundary());
}

TEST(Ids, ParsesWhatItFormats) {
  for (ElementRef r : {ElementRef(VertexId(0)), ElementRef(HalfedgeId(4000000)), ElementRef(EdgeId(9)),
                       ElementRef(FaceId::face(1)), ElementRef(FaceId::boundary(2))}) {
    EXPECT_EQ(parse_element(format_id(r)), r) << format_id(r);
  }
  for (const char* bad : {"", "v", "x3", "h-1", "h1x", "v4294967295", "b2147483648", " v1"}) {
    EXPECT_FALSE(parse_element(bad).has_value()) << bad;
  }
}

}  // namespace
}  // namespace meshedit
