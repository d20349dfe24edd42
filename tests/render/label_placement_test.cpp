// Label placement (render/label_placement.h): no overlaps, boxes inside the bounds and off their anchors, priority
// order, ties by request order, the candidates' order, dropping when there is no room.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include <glm/common.hpp>

#include "render/label_placement.h"

namespace meshedit {
namespace {

const LabelRect kWindow{{0.0, 0.0}, {1280.0, 800.0}};

LabelRequest request(uint32_t vertex, glm::dvec2 anchor, glm::dvec2 direction, int priority = 0,
                     glm::dvec2 text_size = {14.0, 13.0}) {
  return {VertexId(vertex), "v" + std::to_string(vertex), LabelSource::Id, anchor, direction, text_size, priority};
}

std::vector<LabelRequest> random_requests(std::mt19937& random, size_t count, const LabelRect& area) {
  std::uniform_real_distribution<double> x(area.min.x, area.max.x), y(area.min.y, area.max.y);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::uniform_int_distribution<int> chars(1, 4), priority(0, 3), centred(0, 4);
  std::vector<LabelRequest> requests;
  for (size_t i = 0; i < count; ++i) {
    const glm::dvec2 direction = centred(random) == 0 ? glm::dvec2(0.0) : glm::dvec2(unit(random), unit(random));
    requests.push_back(
        request(uint32_t(i), {x(random), y(random)}, direction, priority(random), {7.0 * chars(random), 13.0}));
  }
  return requests;
}

void expect_disjoint_and_inside(const LabelPlacement& placement, const LabelRect& bounds, double spacing) {
  for (size_t i = 0; i < placement.placed.size(); ++i) {
    const LabelRect& a = placement.placed[i].rect;
    EXPECT_TRUE(a.inside(bounds)) << i;
    for (size_t j = i + 1; j < placement.placed.size(); ++j) {
      const LabelRect& b = placement.placed[j].rect;
      const LabelRect grown{b.min - glm::dvec2(spacing * 0.999), b.max + glm::dvec2(spacing * 0.999)};
      ASSERT_FALSE(a.overlaps(grown)) << placement.placed[i].text << " and " << placement.placed[j].text;
    }
  }
}

TEST(LabelPlacement, RandomLabelsNeverOverlapStayInsideAndKeepOffTheirAnchors) {
  std::mt19937 random(7);
  const LabelPlacementOptions options;
  for (int round = 0; round < 20; ++round) {
    // Crowded: 400 labels in a 300 x 200 corner of the window, so many are dropped.
    const LabelRect crowd{{20.0, 30.0}, {320.0, 230.0}};
    const std::vector<LabelRequest> requests = random_requests(random, 400, crowd);
    const LabelPlacement placement = place_labels(requests, kWindow, options);
    EXPECT_EQ(placement.placed.size() + placement.dropped, requests.size());
    EXPECT_GT(placement.dropped, 0u);
    EXPECT_GT(placement.placed.size(), 50u);
    expect_disjoint_and_inside(placement, kWindow, options.spacing);
    for (const PlacedLabel& label : placement.placed) {
      const LabelRequest& asked = requests[label.request];
      EXPECT_EQ(label.text, asked.text);
      EXPECT_EQ(label.element, asked.element);
      EXPECT_DOUBLE_EQ(label.rect.width(), asked.text_size.x + 2.0 * options.padding.x);
      EXPECT_DOUBLE_EQ(label.rect.height(), asked.text_size.y + 2.0 * options.padding.y);
      EXPECT_EQ(label.text_min, label.rect.min + options.padding);
      if (asked.direction != glm::dvec2(0.0)) {
        EXPECT_FALSE(label.rect.contains(asked.anchor)) << label.text;
      }
    }
  }
}

TEST(LabelPlacement, AHigherPriorityIsNeverDroppedOrMovedForALowerOne) {
  std::mt19937 random(11);
  for (int round = 0; round < 10; ++round) {
    const std::vector<LabelRequest> requests = random_requests(random, 300, {{0.0, 0.0}, {250.0, 180.0}});
    const LabelPlacement all = place_labels(requests, kWindow);
    // What the labels of priority >= p get does not depend on the labels below p.
    for (int p = 1; p <= 3; ++p) {
      std::vector<LabelRequest> high;
      std::vector<size_t> index_in_all;
      for (size_t i = 0; i < requests.size(); ++i) {
        if (requests[i].priority >= p) {
          high.push_back(requests[i]);
          index_in_all.push_back(i);
        }
      }
      const LabelPlacement alone = place_labels(high, kWindow);
      std::vector<PlacedLabel> from_all;
      for (const PlacedLabel& l : all.placed) {
        if (requests[l.request].priority >= p) from_all.push_back(l);
      }
      ASSERT_EQ(from_all.size(), alone.placed.size()) << p;
      for (size_t i = 0; i < alone.placed.size(); ++i) {
        EXPECT_EQ(from_all[i].request, index_in_all[alone.placed[i].request]);
        EXPECT_EQ(from_all[i].rect.min, alone.placed[i].rect.min);
      }
    }
    // Placement order: priorities never rise along the placed list.
    for (size_t i = 1; i < all.placed.size(); ++i) {
      EXPECT_GE(requests[all.placed[i - 1].request].priority, requests[all.placed[i].request].priority);
    }
  }
}

TEST(LabelPlacement, TheFirstFreeCandidateWinsInPriorityThenRequestOrder) {
  // Three labels on one anchor, preferring the right: the lesson's (priority 3, asked last) takes the right; the
  // first of the two others the first free candidate after it (the right slid down by one box: the +-45 degree
  // ones overlap the first), the second the next one (slid up).
  const glm::dvec2 anchor(400.0, 300.0);
  const std::vector<LabelRequest> requests = {request(1, anchor, {1.0, 0.0}, 0), request(2, anchor, {1.0, 0.0}, 0),
                                              request(3, anchor, {1.0, 0.0}, 3)};
  const LabelPlacement placement = place_labels(requests, kWindow);
  ASSERT_EQ(placement.placed.size(), 3u);
  EXPECT_EQ(placement.dropped, 0u);
  EXPECT_EQ(placement.placed[0].request, 2u);
  EXPECT_EQ(placement.placed[1].request, 0u);
  EXPECT_EQ(placement.placed[2].request, 1u);
  // Right of the anchor, centred vertically, `gap` pixels away.
  const LabelPlacementOptions options;
  const LabelRect& right = placement.placed[0].rect;
  EXPECT_DOUBLE_EQ(right.min.x, anchor.x + options.gap);
  EXPECT_NEAR(right.centre().y, anchor.y, 0.5);  // boxes start on whole pixels
  // The second: right below the first (y grows down), `gap` pixels apart; the third right above it.
  EXPECT_EQ(placement.placed[1].rect.min.x, right.min.x);
  EXPECT_EQ(placement.placed[1].rect.min.y, right.max.y + options.gap);
  EXPECT_EQ(placement.placed[2].rect.min.x, right.min.x);
  EXPECT_EQ(placement.placed[2].rect.max.y, right.min.y - options.gap);
  // The same input gives the same output.
  const LabelPlacement again = place_labels(requests, kWindow);
  ASSERT_EQ(again.placed.size(), 3u);
  for (size_t i = 0; i < 3; ++i) EXPECT_EQ(again.placed[i].rect.min, placement.placed[i].rect.min);
}

TEST(LabelPlacement, AFaceLabelIsCentredOnItsAnchorWhenFree) {
  const LabelPlacement placement = place_labels(std::vector{request(0, {100.0, 100.0}, {0.0, 0.0})}, kWindow);
  ASSERT_EQ(placement.placed.size(), 1u);
  EXPECT_NEAR(placement.placed[0].rect.centre().x, 100.0, 0.5);  // boxes start on whole pixels
  EXPECT_NEAR(placement.placed[0].rect.centre().y, 100.0, 0.5);
  EXPECT_EQ(placement.placed[0].rect.min, glm::floor(placement.placed[0].rect.min));
}

TEST(LabelPlacement, ALabelAtTheEdgeOfTheViewTurnsInsideIt) {
  // At the right edge, preferring the right: the box goes where it fits (not past the edge), off the anchor.
  const LabelRect view{{100.0, 50.0}, {500.0, 350.0}};
  const glm::dvec2 anchor(498.0, 200.0);
  const LabelPlacement placement = place_labels(std::vector{request(0, anchor, {1.0, 0.0})}, view);
  ASSERT_EQ(placement.placed.size(), 1u);
  EXPECT_TRUE(placement.placed[0].rect.inside(view));
  EXPECT_FALSE(placement.placed[0].rect.contains(anchor));
  EXPECT_LT(placement.placed[0].rect.max.x, anchor.x);
}

TEST(LabelPlacement, NoBoxCrossesItsLabelsKeepClearSegment) {
  // An edge from (300, 300) to (500, 300) with its label asked for straight across it (upwards), then another
  // label taking that place: the edge's label slides along the edge, above it, never onto the line.
  const glm::dvec2 mid(400.0, 300.0);
  LabelRequest edge = request(0, mid, {0.0, -1.0});
  edge.keep_clear = LabelSegment{{300.0, 300.0}, {500.0, 300.0}};
  const LabelRequest blocker = request(1, mid + glm::dvec2(0.0, -20.0), {0.0, 0.0}, 1, {60.0, 30.0});
  const LabelPlacement placement = place_labels(std::vector{edge, blocker}, kWindow);
  ASSERT_EQ(placement.placed.size(), 2u);
  const LabelRect& box = placement.placed[1].rect;
  EXPECT_EQ(placement.placed[1].request, 0u);
  EXPECT_LE(box.max.y, 300.0 - LabelPlacementOptions{}.gap);
  EXPECT_FALSE(box.overlaps(placement.placed[0].rect));
  // A view with room for the centred box only: it is placed, unless the segment crosses it.
  const LabelRect tight{{630.0, 392.0}, {650.0, 408.0}};
  LabelRequest face = request(2, {640.0, 400.0}, {0.0, 0.0});
  EXPECT_EQ(place_labels(std::vector{face}, tight).placed.size(), 1u);
  face.keep_clear = LabelSegment{{600.0, 390.0}, {700.0, 410.0}};
  EXPECT_EQ(place_labels(std::vector{face}, tight).dropped, 1u);
  face.keep_clear = LabelSegment{{600.0, 390.0}, {625.0, 410.0}};  // stops short of the box
  EXPECT_EQ(place_labels(std::vector{face}, tight).placed.size(), 1u);
}

TEST(LabelPlacement, LabelsThatFitNowhereAreDroppedAndCounted) {
  // A view just big enough for one box around the anchor: the first label takes it, the other two are dropped.
  const LabelRect view{{0.0, 0.0}, {30.0, 20.0}};
  const std::vector<LabelRequest> requests = {
      request(0, {15.0, 10.0}, {0.0, 0.0}), request(1, {15.0, 10.0}, {0.0, 0.0}), request(2, {15.0, 10.0}, {1.0, 0.0})};
  const LabelPlacement placement = place_labels(requests, view);
  ASSERT_EQ(placement.placed.size(), 1u);
  EXPECT_EQ(placement.placed[0].element, ElementRef(VertexId(0)));
  EXPECT_EQ(placement.dropped, 2u);
  // A non-finite anchor is dropped too, and an empty view drops everything.
  EXPECT_EQ(place_labels(std::vector{request(0, {NAN, 1.0}, {0.0, 0.0})}, kWindow).dropped, 1u);
  EXPECT_EQ(place_labels(requests, LabelRect{}).dropped, 3u);
}

TEST(LabelPlacement, AThousandLabelsArePlacedQuickly) {
  std::mt19937 random(3);
  const std::vector<LabelRequest> requests = random_requests(random, 1000, kWindow);
  const auto start = std::chrono::steady_clock::now();
  const LabelPlacement placement = place_labels(requests, kWindow);
  const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  expect_disjoint_and_inside(placement, kWindow, LabelPlacementOptions{}.spacing);
  EXPECT_EQ(placement.placed.size() + placement.dropped, 1000u);
  EXPECT_LT(ms, 100.0);  // a few milliseconds on one core; generous for sanitizer builds
}

}  // namespace
}  // namespace meshedit
