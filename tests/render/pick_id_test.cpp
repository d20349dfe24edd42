// Pick id encoding and the choice of one element near the cursor (render/pick_id.h).
#include <vector>

#include <gtest/gtest.h>

#include "render/pick_id.h"

namespace meshedit {
namespace {

TEST(PickId, RoundTripsEveryPickableKind) {
  for (ElementKind kind : {ElementKind::Vertex, ElementKind::Halfedge, ElementKind::Edge, ElementKind::Face}) {
    for (uint32_t index : {0u, 1u, 12345u, 3000000u, kPickIndexMask}) {
      const ElementRef element(kind, index);
      const uint32_t id = encode_pick_id(element);
      EXPECT_NE(id, 0u);
      EXPECT_EQ(decode_pick_id(id), element) << format_id(element);
    }
  }
}

TEST(PickId, KindsHaveDistinctBitsAndTheDocumentedPriority) {
  EXPECT_EQ(pick_kind_bits(ElementKind::Face), 1u << 29);
  EXPECT_EQ(pick_kind_bits(ElementKind::Edge), 2u << 29);
  EXPECT_EQ(pick_kind_bits(ElementKind::Halfedge), 3u << 29);
  EXPECT_EQ(pick_kind_bits(ElementKind::Vertex), 4u << 29);
  EXPECT_EQ(encode_pick_id(ElementRef(ElementKind::Edge, 7)), (2u << 29) | 7u);
}

TEST(PickId, WhatCannotBePickedEncodesAsBackground) {
  EXPECT_EQ(encode_pick_id(ElementRef()), 0u);
  EXPECT_EQ(encode_pick_id(ElementRef(ElementKind::Boundary, 0)), 0u);
  EXPECT_EQ(encode_pick_id(ElementRef(ElementKind::Face, kPickIndexMask + 1)), 0u);
  EXPECT_FALSE(decode_pick_id(0).valid());
  for (uint32_t code : {5u, 6u, 7u}) EXPECT_FALSE(decode_pick_id((code << 29) | 3u).valid());
  EXPECT_FALSE(decode_pick_id(5u).valid());  // index bits with no kind
}

// A 5x5 window of the given ids, the cursor in the middle.
struct Window {
  std::vector<uint32_t> ids = std::vector<uint32_t>(25, 0);
  void set(int x, int y, ElementRef e) { ids[size_t(y * 5 + x)] = encode_pick_id(e); }
  ElementRef choose() const { return choose_pick(ids, 5, 5, 2, 2); }
};

TEST(ChoosePick, BackgroundEverywhereIsNothing) {
  Window w;
  EXPECT_FALSE(w.choose().valid());
}

TEST(ChoosePick, SmallTargetsBeatTheFaceUnderTheCursor) {
  Window w;
  for (int y = 0; y < 5; ++y) {
    for (int x = 0; x < 5; ++x) w.set(x, y, ElementRef(ElementKind::Face, 3));
  }
  EXPECT_EQ(w.choose(), ElementRef(ElementKind::Face, 3));
  w.set(0, 4, ElementRef(ElementKind::Edge, 9));
  EXPECT_EQ(w.choose(), ElementRef(ElementKind::Edge, 9));
  w.set(4, 4, ElementRef(ElementKind::Halfedge, 11));
  EXPECT_EQ(w.choose(), ElementRef(ElementKind::Halfedge, 11));
  w.set(4, 0, ElementRef(ElementKind::Vertex, 2));
  EXPECT_EQ(w.choose(), ElementRef(ElementKind::Vertex, 2));
}

TEST(ChoosePick, AmongOneKindTheNearestPixelWins) {
  Window w;
  w.set(0, 0, ElementRef(ElementKind::Edge, 1));
  w.set(3, 2, ElementRef(ElementKind::Edge, 2));
  w.set(2, 4, ElementRef(ElementKind::Edge, 3));
  EXPECT_EQ(w.choose(), ElementRef(ElementKind::Edge, 2));
  // Ties go to the first in row order.
  w.set(2, 1, ElementRef(ElementKind::Edge, 4));
  EXPECT_EQ(w.choose(), ElementRef(ElementKind::Edge, 4));
}

TEST(ChoosePick, EachKindCountsOnlyWithinItsRadius) {
  // A 13x13 window (radius 6 around the centre), as pick() reads it.
  std::vector<uint32_t> ids(169, 0);
  auto set = [&](int x, int y, ElementRef e) { ids[size_t(y * 13 + x)] = encode_pick_id(e); };
  set(6 + kPickRadius + 1, 6, ElementRef(ElementKind::Edge, 1));  // just too far for an edge
  EXPECT_FALSE(choose_pick(ids, 13, 13, 6, 6).valid());
  set(6, 6 - kPickRadius, ElementRef(ElementKind::Edge, 2));  // exactly at the radius
  EXPECT_EQ(choose_pick(ids, 13, 13, 6, 6), ElementRef(ElementKind::Edge, 2));
  set(6 + 4, 6 + 4, ElementRef(ElementKind::Vertex, 3));  // 5.7 pixels away: a vertex still counts
  EXPECT_EQ(choose_pick(ids, 13, 13, 6, 6), ElementRef(ElementKind::Vertex, 3));
  set(6 + 4, 6 + 4, ElementRef());                  // encodes as background
  set(12, 12, ElementRef(ElementKind::Vertex, 4));  // in the window's corner, 8.5 pixels: too far
  EXPECT_EQ(choose_pick(ids, 13, 13, 6, 6), ElementRef(ElementKind::Edge, 2));
}

TEST(ChoosePick, AShortBufferIsReadOnlyAsFarAsItGoes) {
  const std::vector<uint32_t> ids = {encode_pick_id(ElementRef(ElementKind::Face, 1))};
  EXPECT_EQ(choose_pick(ids, 3, 3, 1, 1), ElementRef(ElementKind::Face, 1));
}

}  // namespace
}  // namespace meshedit
