// A wrong vertex normal in words, from the recipe it is made of (see normal_diagnosis.h).
#include "exercise/internal/normal_diagnosis.h"

#include <cmath>
#include <numbers>
#include <optional>
#include <vector>

#include <glm/geometric.hpp>

#include "core/translation.h"
#include "core/value_format.h"
#include "exercise/internal/normal_recipes.h"

namespace meshedit {
namespace {

constexpr double kSameNormal = 1e-9;

// What the words need besides the recipe.
struct Said {
  std::string yours, reference, vertex;  // "(0.1, 0.2, 0.97)", "(0, 0, 1)", "v0"
  double length = 1.0;                   // of yours
};

// A recipe with one choice changed, in its own words.
std::string one_change(const NormalRecipe& r, const Said& s) {
  const MessageParts parts = {{"yours", s.yours},          {"reference", s.reference},
                              {"vertex", s.vertex},        {"count", std::to_string(r.face_count)},
                              {"face", format_id(r.face)}, {"inward", format_id(r.inward_face)}};
  if (r.weight == FaceWeight::UnitNormal) {
    return tr_format(
        "your normal {yours} is the average of the faces' unit normals; the reference {reference} "
        "weights each face by its area: add the cross products themselves, then normalise",
        parts);
  }
  if (r.weight == FaceWeight::Angle) {
    return tr_format(
        "your normal {yours} weights each face by its angle at {vertex} (an angle-weighted normal); the "
        "reference {reference} weights each face by its area: add the cross products themselves, then "
        "normalise",
        parts);
  }
  if (r.orientation == Orientation::Inward) {
    return tr_format(
        "your normal {yours} points inwards (the reference's is {reference}): take the cross product of "
        "the edges in the face's order, (p1 - p0):cross(p2 - p0)",
        parts);
  }
  if (r.orientation == Orientation::OneFaceInward) {
    return tr_format(
        "your normal {yours} takes {inward}'s cross product the wrong way round, pointing inwards (the "
        "reference's is {reference}): take every face's in the face's order, (p1 - p0):cross(p2 - p0) "
        "with p0 = h.vertex.position, p1 = h.next.vertex.position and p2 = h.next.next.vertex.position",
        parts);
  }
  const bool both = r.face_count == 2;
  switch (r.faces) {
    case FacesCounted::WithBoundaryLoop:
      return tr_format(
          "your normal {yours} counts the boundary loop as a face ({face}); the reference {reference} "
          "adds only the {count} real faces around {vertex}: skip faces with f:is_boundary()",
          parts);
    case FacesCounted::AllButOne:
      return both ? tr_format(
                        "your normal {yours} leaves out {face}, one of the {count} faces around {vertex}; the "
                        "reference {reference} adds the cross products of both: walk h = h.twin.next until h is "
                        "back at v.halfedge and count the face of every h (a loop that tests before adding, or "
                        "stops one step early, misses one)",
                        parts)
                  : tr_format(
                        "your normal {yours} leaves out {face}, one of the {count} faces around {vertex}; the "
                        "reference {reference} adds the cross products of all {count}: walk h = h.twin.next "
                        "until h is back at v.halfedge and count the face of every h (a loop that tests before "
                        "adding, or stops one step early, misses one)",
                        parts);
    case FacesCounted::OneOnly:
      return both ? tr_format(
                        "your normal {yours} is the normal of {face} alone, one of the {count} faces around "
                        "{vertex}; the reference {reference} adds the cross products of both, then normalises: "
                        "add each face's to the sum (sum = sum + ..., not sum = ...) and return after the loop, "
                        "not inside it",
                        parts)
                  : tr_format(
                        "your normal {yours} is the normal of {face} alone, one of the {count} faces around "
                        "{vertex}; the reference {reference} adds the cross products of all {count}, then "
                        "normalises: add each face's to the sum (sum = sum + ..., not sum = ...) and return "
                        "after the loop, not inside it",
                        parts);
    case FacesCounted::All: break;
  }
  return tr_format("your normal {yours} differs from the reference's {reference}", parts);
}

// The recipe described: "the normalised sum of the unit normals of the faces around v0 except f3".
std::string describe(const NormalRecipe& r, bool normalised, const Said& s) {
  const MessageParts parts = {{"vertex", s.vertex},
                              {"count", std::to_string(r.face_count)},
                              {"face", format_id(r.face)},
                              {"inward", format_id(r.inward_face)},
                              {"terms", tr(r.weight == FaceWeight::Area ? "the cross products" : "the unit normals")}};
  if (r.faces == FacesCounted::OneOnly) {
    if (r.orientation == Orientation::Inward) {
      return normalised ? tr_format(
                              "{face}'s cross product alone, the wrong way round (pointing inwards), one of the "
                              "{count} faces around {vertex}, normalised",
                              parts)
                        : tr_format(
                              "{face}'s cross product alone, the wrong way round (pointing inwards), one of the "
                              "{count} faces around {vertex} (not normalised)",
                              parts);
    }
    return normalised
               ? tr_format("{face}'s cross product alone, one of the {count} faces around {vertex}, normalised", parts)
               : tr_format("{face}'s cross product alone, one of the {count} faces around {vertex} (not normalised)",
                           parts);
  }
  std::string terms;
  switch (r.faces) {
    case FacesCounted::AllButOne: terms = tr_format("{terms} of the faces around {vertex} except {face}", parts); break;
    case FacesCounted::WithBoundaryLoop:
      terms = tr_format("{terms} of the {count} faces around {vertex} and of the boundary loop {face}", parts);
      break;
    default: terms = tr_format("{terms} of the {count} faces around {vertex}", parts); break;
  }
  std::string text = normalised ? tr_format("the normalised sum of {terms}", {{"terms", terms}})
                                : tr_format("the sum (not normalised) of {terms}", {{"terms", terms}});
  if (r.weight == FaceWeight::Angle) {
    text = tr_format("{text}, each weighted by its face's angle at {vertex}", {{"text", text}, {"vertex", s.vertex}});
  }
  if (r.orientation == Orientation::Inward) {
    text = tr_format("{text}, each taken the wrong way round (pointing inwards)", {{"text", text}});
  }
  if (r.orientation == Orientation::OneFaceInward) {
    text = tr_format("{text}, with {inward}'s the wrong way round",
                     {{"text", text}, {"inward", format_id(r.inward_face)}});
  }
  return text;
}

// One fix per choice that differs from the course's, in the order the description names them.
std::vector<std::string> fixes(const NormalRecipe& r, bool normalised) {
  std::vector<std::string> out;
  const MessageParts parts = {{"face", format_id(r.face)}, {"inward", format_id(r.inward_face)}};
  if (r.faces == FacesCounted::AllButOne) {
    out.push_back(tr_format("count {face} too (walk h = h.twin.next until h is back at v.halfedge)", parts));
  }
  if (r.faces == FacesCounted::OneOnly) {
    out.push_back(tr_format("add every face's cross product, not {face}'s alone (return after the loop)", parts));
  }
  if (r.faces == FacesCounted::WithBoundaryLoop) out.push_back(tr("skip faces with f:is_boundary()"));
  if (r.weight != FaceWeight::Area) {
    out.push_back(tr("weight each face by its area (add the cross products themselves)"));
  }
  if (r.orientation == Orientation::Inward) {
    out.push_back(tr("take the cross product of the edges in the face's order, (p1 - p0):cross(p2 - p0)"));
  }
  if (r.orientation == Orientation::OneFaceInward) {
    out.push_back(tr_format("take {inward}'s cross product in the face's order too, (p1 - p0):cross(p2 - p0)", parts));
  }
  if (!normalised) out.push_back(tr("normalise the sum (n:normalized())"));
  return out;
}

std::string described_with_fixes(const NormalMatch& m, const Said& s) {
  const std::vector<std::string> all = fixes(m.recipe, m.normalised);
  std::string listed;
  for (size_t i = 0; i < all.size(); ++i) {
    listed = i == 0 ? all[i] : tr_format("{list}; {item}", {{"list", listed}, {"item", all[i]}});
  }
  const double degrees = std::round(m.angle * 180.0 / std::numbers::pi * 100.0) / 100.0;
  const MessageParts parts = {{"yours", s.yours},
                              {"reference", s.reference},
                              {"vertex", s.vertex},
                              {"count", std::to_string(m.recipe.face_count)},
                              {"degrees", format_number(degrees)},
                              {"description", describe(m.recipe, m.normalised, s)},
                              {"fixes", listed}};
  if (m.near) {
    return tr_format(
        "your normal {yours} is close to ({degrees} degrees from) {description}; the reference "
        "{reference} is the normalised sum of the cross products of the {count} faces around {vertex}: "
        "{fixes}",
        parts);
  }
  return tr_format(
      "your normal {yours} is {description}; the reference {reference} is the normalised sum of the "
      "cross products of the {count} faces around {vertex}: {fixes}",
      parts);
}

}  // namespace

std::string explain_vertex_normal(const HalfedgeMesh& mesh, VertexId v, const glm::dvec3& yours,
                                  const glm::dvec3& reference) {
  const double off = glm::distance(yours, reference);
  if (off <= kSameNormal) return "";
  const Said s{format_position(yours), format_position(reference), format_id(v), glm::length(yours)};
  const std::optional<NormalMatch> m = match_normal(mesh, v, yours, reference);
  if (!m) {
    return tr_format("your normal {yours} differs from the reference's {reference} by {distance}",
                     {{"yours", s.yours}, {"reference", s.reference}, {"distance", format_number(off)}});
  }
  if (m->recipe.changes() == 0) {
    return tr_format("your normal {yours} points the right way but has length {length}; normalise it (n:normalized())",
                     {{"yours", s.yours}, {"length", format_number(s.length)}});
  }
  std::string text = m->recipe.changes() == 1 && !m->near ? one_change(m->recipe, s) : described_with_fixes(*m, s);
  if (m->recipe.changes() == 1 && !m->near && !m->normalised) {
    text = tr_format("{text}; and normalise the sum (n:normalized()): yours has length {length}",
                     {{"text", text}, {"length", format_number(s.length)}});
  }
  if (m->also) {
    text = tr_format("{text}; on this mesh that is also {description}",
                     {{"text", text}, {"description", describe(*m->also, m->normalised, s)}});
  }
  return text;
}

}  // namespace meshedit
