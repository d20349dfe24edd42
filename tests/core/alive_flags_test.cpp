// AliveFlags (alive_flags.h): the flags agree with a plain vector<bool> model under random pushes, kills, revivals,
// growth and shrinking; they hold no bytes until something dies; equality is by value. And through HalfedgeMesh: a
// built or subdivided mesh spends no byte on liveness, and a deletion still reads as dead afterwards.
#include "core/alive_flags.h"

#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "core/halfedge_mesh.h"
#include "core/loop_subdivision.h"
#include "core/mesh_build.h"
#include "core/primitives.h"

namespace meshedit {
namespace {

void expect_matches(const AliveFlags& flags, const std::vector<bool>& model) {
  ASSERT_EQ(flags.size(), model.size());
  for (size_t i = 0; i < model.size(); ++i) ASSERT_EQ(flags[i], model[i]) << "slot " << i;
}

TEST(AliveFlags, HoldNoBytesUntilSomethingDies) {
  AliveFlags flags;
  flags.resize(100000, true);
  flags.push_back(true);
  flags.set(7, true);
  EXPECT_EQ(flags.memory_bytes(), 0u);
  EXPECT_TRUE(flags[100000]);

  flags.set(64, false);
  EXPECT_FALSE(flags[64]);
  EXPECT_TRUE(flags[63]);
  EXPECT_TRUE(flags[65]);
  EXPECT_GE(flags.memory_bytes(), 100001u / 8);
}

TEST(AliveFlags, NewSlotsTakeTheGivenStateAndShrinkingForgetsDeadBits) {
  AliveFlags flags;
  flags.resize(70, false);  // set_slots: new slots are dead
  for (size_t i = 0; i < 70; ++i) EXPECT_FALSE(flags[i]);
  flags.resize(130, true);
  EXPECT_FALSE(flags[69]);
  EXPECT_TRUE(flags[70]);
  EXPECT_TRUE(flags[129]);

  flags.resize(65, true);  // drops slots 65..129, including dead 65..69
  flags.resize(128, true);
  EXPECT_FALSE(flags[64]);
  for (size_t i = 65; i < 128; ++i) EXPECT_TRUE(flags[i]) << "slot " << i << " came back dead";
}

TEST(AliveFlags, EqualityIsByValue) {
  AliveFlags never_died, revived;
  never_died.resize(200, true);
  revived.resize(200, true);
  revived.set(150, false);
  EXPECT_FALSE(never_died == revived);
  revived.set(150, true);
  EXPECT_TRUE(never_died == revived);
  EXPECT_TRUE(revived == never_died);

  AliveFlags shorter;
  shorter.resize(199, true);
  EXPECT_FALSE(shorter == never_died);
}

TEST(AliveFlags, AMovedFromInstanceIsEmpty) {
  AliveFlags flags;
  flags.resize(300, true);
  flags.set(3, false);
  AliveFlags taken = std::move(flags);
  EXPECT_EQ(flags.size(), 0u);  // NOLINT(bugprone-use-after-move): the state after a move is specified
  EXPECT_EQ(flags.memory_bytes(), 0u);
  EXPECT_EQ(taken.size(), 300u);
  EXPECT_FALSE(taken[3]);
  AliveFlags assigned;
  assigned = std::move(taken);
  EXPECT_EQ(taken.size(), 0u);  // NOLINT(bugprone-use-after-move)
  EXPECT_FALSE(assigned[3]);
  EXPECT_TRUE(assigned[4]);
}

TEST(AliveFlags, AgreeWithAPlainModelUnderRandomUse) {
  std::mt19937 rng(12345);
  AliveFlags flags;
  std::vector<bool> model;
  for (int step = 0; step < 20000; ++step) {
    const int op = static_cast<int>(rng() % 10);
    if (op < 3) {
      const bool alive = rng() % 4 != 0;
      flags.push_back(alive);
      model.push_back(alive);
    } else if (op < 7 && !model.empty()) {
      const size_t i = rng() % model.size();
      const bool alive = rng() % 2 == 0;
      flags.set(i, alive);
      model[i] = alive;
    } else if (op == 7) {
      const size_t n = rng() % 300;
      const bool alive = rng() % 2 == 0;
      flags.resize(n, alive);
      model.resize(n, alive);
    } else if (op == 8 && step % 500 == 0) {
      const size_t n = rng() % 200;
      flags.assign(n, true);
      model.assign(n, true);
    } else {
      AliveFlags copy = flags;
      ASSERT_TRUE(copy == flags);
    }
    expect_matches(flags, model);
  }
}

TEST(AliveFlags, ABuiltAndSubdividedMeshSpendsNothingOnLiveness) {
  HalfedgeMesh mesh = build_halfedge_mesh(make_torus(24, 16));
  ASSERT_TRUE(loop_subdivide(mesh, LoopWeights::Course, 1).ok);
  const size_t pointers_and_positions = mesh.halfedge_capacity() * sizeof(HalfedgeRecord) +
                                        mesh.vertex_capacity() * (4 + sizeof(glm::dvec3)) + mesh.edge_capacity() * 4 +
                                        mesh.face_capacity() * 4 + mesh.boundary_capacity() * 4;
  const size_t rows = mesh.num_faces() * sizeof(TriangleRow);  // what Loop leaves for whole-mesh passes
  EXPECT_EQ(mesh.memory_bytes(), pointers_and_positions + rows);

  const FaceId f = FaceId::face(5);
  const HalfedgeId h = mesh.halfedge(f);
  mesh.delete_element(f);
  EXPECT_FALSE(mesh.alive(f));
  EXPECT_TRUE(mesh.alive(FaceId::face(4)));
  EXPECT_TRUE(mesh.alive(h));
  EXPECT_EQ(mesh.num_faces(), size_t(mesh.face_capacity()) - 1);
  EXPECT_GT(mesh.memory_bytes(), pointers_and_positions);
  size_t visited = 0;
  for (FaceId g : mesh.faces()) {
    EXPECT_NE(g, f);
    ++visited;
  }
  EXPECT_EQ(visited, mesh.num_faces());
}

}  // namespace
}  // namespace meshedit
