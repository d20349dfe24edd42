// The sums a vertex normal may be made of, and the one a given normal is (see normal_recipes.h).
#include "exercise/internal/normal_recipes.h"

#include <algorithm>
#include <array>
#include <cmath>

#include <glm/geometric.hpp>

#include "core/normals.h"

namespace meshedit {
namespace {

// Recipes that leave out one face and turn another inwards number (faces)^2: only for fans up to this size.
constexpr size_t kMostFacesForPairs = 64;

// One face (or boundary loop) around v, as a student's code meets it at the outgoing halfedge h.
struct FanFace {
  FaceId face;
  glm::dvec3 vector{0.0};   // a real face's vector area; a loop's cross product (p1 - p0):cross(p2 - p0) at v
  glm::dvec3 polygon{0.0};  // the face's or loop's polygon vector area (2 x face_area x face_normal)
  double angle = 0.0;       // the angle at v between p1 - p0 and p2 - p0
};

struct Fan {
  std::vector<FanFace> faces;  // the real ones
  std::vector<FanFace> loops;  // the boundary loops v is on
};

glm::dvec3 unit_or_zero(const glm::dvec3& n) {
  const double length = glm::length(n);
  return length > 0.0 && std::isfinite(length) ? n / length : glm::dvec3(0.0);
}

double angle_between(const glm::dvec3& a, const glm::dvec3& b) {
  return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b));
}

std::optional<Fan> read_fan(const HalfedgeMesh& mesh, VertexId v) {
  Fan fan;
  bool ok = true;
  const bool closed = mesh.for_each_outgoing(v, [&](HalfedgeId h) {
    const FaceId f = mesh.face(h);
    const HalfedgeId h1 = mesh.next(h);
    const HalfedgeId h2 = mesh.alive(h1) ? mesh.next(h1) : HalfedgeId();
    if (!ok || !mesh.alive(f) || !mesh.alive(h2) || !mesh.alive(mesh.vertex(h1)) || !mesh.alive(mesh.vertex(h2))) {
      ok = false;
      return;
    }
    const glm::dvec3 p0 = mesh.position(v);
    const glm::dvec3 e1 = mesh.position(mesh.vertex(h1)) - p0, e2 = mesh.position(mesh.vertex(h2)) - p0;
    FanFace face{f, glm::cross(e1, e2), 2.0 * face_area(mesh, f) * face_normal(mesh, f), angle_between(e1, e2)};
    if (f.is_boundary()) {
      fan.loops.push_back(face);
    } else {
      face.vector = face.polygon;
      fan.faces.push_back(face);
    }
  });
  if (!closed || !ok || fan.faces.empty()) return std::nullopt;
  return fan;
}

glm::dvec3 term(const FanFace& face, FaceWeight weight, bool polygon) {
  const glm::dvec3& vector = polygon ? face.polygon : face.vector;
  switch (weight) {
    case FaceWeight::Area: return vector;
    case FaceWeight::UnitNormal: return unit_or_zero(vector);
    case FaceWeight::Angle: return face.angle * unit_or_zero(vector);
  }
  return vector;
}

// The recipes with one weight: every choice of faces, then of orientation.
void add_recipes_weighted(const Fan& fan, FaceWeight weight, std::vector<NormalRecipe>& out) {
  const size_t k = fan.faces.size();
  std::vector<glm::dvec3> terms;
  glm::dvec3 total(0.0);
  for (const FanFace& f : fan.faces) total += terms.emplace_back(term(f, weight, false));
  NormalRecipe base;
  base.weight = weight;
  base.face_count = k;
  // Each orientation of a sum over the real faces `left_out` aside (invalid: none), with `extra` added.
  const auto add_oriented = [&](NormalRecipe recipe, const glm::dvec3& sum, size_t left_out, bool pairs) {
    recipe.sum = sum;
    out.push_back(recipe);
    recipe.orientation = Orientation::Inward;
    recipe.sum = -sum;
    out.push_back(recipe);
    if (!pairs) return;
    recipe.orientation = Orientation::OneFaceInward;
    for (size_t j = 0; j < k; ++j) {
      if (j == left_out) continue;
      recipe.inward_face = fan.faces[j].face;
      recipe.sum = sum - 2.0 * terms[j];
      out.push_back(recipe);
    }
  };
  add_oriented(base, total, k, k >= 2);
  for (size_t polygon = 0; polygon < (weight == FaceWeight::Area ? 2 : 1) && !fan.loops.empty(); ++polygon) {
    NormalRecipe recipe = base;
    recipe.faces = FacesCounted::WithBoundaryLoop;
    recipe.face = fan.loops.front().face;
    recipe.loop_polygon = polygon == 1;
    glm::dvec3 sum = total;
    for (const FanFace& loop : fan.loops) sum += term(loop, weight, polygon == 1);
    add_oriented(recipe, sum, k, true);
  }
  for (size_t i = 0; i < k && k >= 2; ++i) {
    NormalRecipe recipe = base;
    recipe.faces = FacesCounted::AllButOne;
    recipe.face = fan.faces[i].face;
    add_oriented(recipe, total - terms[i], i, k - 1 >= 2 && k <= kMostFacesForPairs);
  }
  // One face alone has the same direction whatever its weight. With two faces, one alone is the other left out,
  // named so above.
  for (size_t i = 0; i < k && k >= 2 && weight == FaceWeight::Area; ++i) {
    NormalRecipe recipe = base;
    recipe.faces = FacesCounted::OneOnly;
    recipe.face = fan.faces[i].face;
    add_oriented(recipe, terms[i], i, false);
  }
}

// Whether two recipes change the same choices (faces, weights, orientation), whatever faces they name.
bool same_choices(const NormalRecipe& a, const NormalRecipe& b) {
  return a.weight == b.weight && a.faces == b.faces && a.orientation == b.orientation;
}

}  // namespace

size_t NormalRecipe::changes() const {
  return (weight != FaceWeight::Area ? 1 : 0) + (faces != FacesCounted::All ? 1 : 0) +
         (orientation != Orientation::Outward ? 1 : 0);
}

std::vector<NormalRecipe> normal_recipes(const HalfedgeMesh& mesh, VertexId v) {
  const std::optional<Fan> fan = read_fan(mesh, v);
  if (!fan) return {};
  std::vector<NormalRecipe> out;
  for (FaceWeight weight : {FaceWeight::Area, FaceWeight::UnitNormal, FaceWeight::Angle}) {
    add_recipes_weighted(*fan, weight, out);
  }
  std::erase_if(out, [](const NormalRecipe& r) { return r.changes() > 2; });
  std::stable_sort(out.begin(), out.end(),
                   [](const NormalRecipe& a, const NormalRecipe& b) { return a.changes() < b.changes(); });
  return out;
}

std::optional<NormalMatch> match_normal(const HalfedgeMesh& mesh, VertexId v, const glm::dvec3& yours,
                                        const glm::dvec3& reference) {
  const double length = glm::length(yours);
  if (!(length > 0.0) || !std::isfinite(length)) return std::nullopt;
  const std::vector<NormalRecipe> recipes = normal_recipes(mesh, v);
  if (recipes.empty()) return std::nullopt;
  const glm::dvec3 direction = yours / length;
  const glm::dvec3 reference_direction = unit_or_zero(reference);
  const bool normalised = std::abs(length - 1.0) <= kSameDirection;
  const auto same = [](const glm::dvec3& a, const glm::dvec3& b) { return glm::distance(a, b) <= kSameDirection; };
  if (same(direction, reference_direction)) {
    if (normalised) return std::nullopt;
    return NormalMatch{recipes.front(), false, false, 0.0, std::nullopt};
  }
  std::optional<NormalMatch> found, nearest;
  for (const NormalRecipe& recipe : recipes) {
    const glm::dvec3 recipe_direction = unit_or_zero(recipe.sum);
    if (recipe_direction == glm::dvec3(0.0) || same(recipe_direction, reference_direction)) continue;
    if (same(direction, recipe_direction)) {
      if (!found) {
        found = NormalMatch{recipe, normalised, false, 0.0, std::nullopt};
      } else if (recipe.changes() > found->recipe.changes()) {
        break;
      } else if (!found->also && !same_choices(recipe, found->recipe)) {
        found->also = recipe;
      }
      continue;
    }
    const double angle = angle_between(direction, recipe_direction);
    if (!nearest || angle < nearest->angle) nearest = NormalMatch{recipe, normalised, true, angle, std::nullopt};
  }
  if (found) return found;
  const double off = angle_between(direction, reference_direction);
  if (nearest && nearest->angle <= kNearAngle && nearest->angle <= 0.1 * off) return nearest;
  return std::nullopt;
}

}  // namespace meshedit
