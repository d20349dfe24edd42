// What a vertex normal is made of: the sums a student's vertex_normal may add over the faces around a vertex, and
// the one a given normal is. The course's recipe is every real face around v, each weighted by its area (its cross
// product), outwards, the sum normalised; a recipe here changes one or two of those choices (which faces are
// counted, with which weights, which way round). normal_diagnosis.h turns the recipe found into words.
//
//   const std::vector<NormalRecipe> recipes = normal_recipes(mesh, v);  // the course's first
//   const std::optional<NormalMatch> match = match_normal(mesh, v, yours, reference);
//   match->recipe.faces == FacesCounted::AllButOne, match->recipe.face == FaceId(3), match->normalised
//
// Invariants:
// - The faces around v are read in for_each_outgoing order (bounded walks); a fan that does not close, or meets a
//   dead element, gives no recipes. A real face's area term is its vector area (2 x face_area x face_normal, the
//   reference's term); a boundary loop's is the cross product (p1 - p0):cross(p2 - p0) at v that a student's code
//   takes there, and, as a second recipe, the loop polygon's vector area.
// - normal_recipes lists the course's recipe first, then those with one choice changed, then those with two, each
//   group in the order the mistakes are likely; match_normal keeps the first that matches, so the fewest changes win,
//   and the first other one as likely that differs in which choice it changes (`also`).
// - A recipe matches when its direction and yours agree within kSameDirection (unit vectors, so it is relative); its
//   length does not matter (`normalised` says whether yours has length 1). A recipe whose direction is the
//   reference's explains nothing (only a missing normalisation can), and neither does a zero sum.
// - Without an exact match, the nearest recipe by angle is kept only when it is convincingly close: within
//   kNearAngle radians and at most a tenth of the angle between yours and the reference (NormalMatch::near).
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include <glm/vec3.hpp>

#include "core/halfedge_mesh.h"

namespace meshedit {

enum class FaceWeight { Area, UnitNormal, Angle };  // a face's cross product, its unit normal, or that x its angle at v
enum class FacesCounted { All, AllButOne, OneOnly, WithBoundaryLoop };
enum class Orientation { Outward, Inward, OneFaceInward };  // Inward: every cross product taken the wrong way round

struct NormalRecipe {
  FaceWeight weight = FaceWeight::Area;
  FacesCounted faces = FacesCounted::All;
  Orientation orientation = Orientation::Outward;
  FaceId face;                // AllButOne: the face left out; OneOnly: the face counted; WithBoundaryLoop: the loop
  FaceId inward_face;         // OneFaceInward: the face whose cross product is the wrong way round
  bool loop_polygon = false;  // WithBoundaryLoop: the loop's term is the loop polygon's vector area
  size_t face_count = 0;      // the real faces around v
  glm::dvec3 sum{0.0};        // the recipe's sum, before normalising

  // How many of the three choices (faces, weights, orientation) differ from the course's.
  size_t changes() const;
};

struct NormalMatch {
  NormalRecipe recipe;
  bool normalised = true;  // yours has length 1 (within kSameDirection)
  bool near = false;       // not within kSameDirection: the nearest recipe, `angle` radians from yours
  double angle = 0.0;
  // Another recipe with as many changes that matches too, of another kind (a regular mesh can make a face left out
  // and angle weights agree): a message names both, so neither misleads.
  std::optional<NormalRecipe> also;
};

inline constexpr double kSameDirection = 1e-6;
inline constexpr double kNearAngle = 1e-2;

// Every recipe at v, the course's first; empty when v's fan cannot be read.
std::vector<NormalRecipe> normal_recipes(const HalfedgeMesh& mesh, VertexId v);

// The recipe `yours` is (the course's, when only its length is wrong), or nullopt: no recipe explains it, yours is
// zero or not finite, or it is the reference's.
std::optional<NormalMatch> match_normal(const HalfedgeMesh& mesh, VertexId v, const glm::dvec3& yours,
                                        const glm::dvec3& reference);

}  // namespace meshedit
