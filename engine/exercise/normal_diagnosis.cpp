// A wrong vertex normal in words, from the recipe it is made of (see normal_diagnosis.h).
#include "exercise/internal/normal_diagnosis.h"

#include <cmath>
#include <numbers>
#include <optional>
#include <vector>

#include <glm/geometric.hpp>

#include "core/value_format.h"
#include "exercise/internal/normal_recipes.h"

namespace meshedit {
namespace {

constexpr double kSameNormal = 1e-9;

const char* const kAreaWeights = "weights each face by its area: add the cross products themselves, then normalise";
const char* const kFaceOrder = "(p1 - p0):cross(p2 - p0)";

// What the words need besides the recipe.
struct Said {
  std::string yours, reference, vertex;  // "(0.1, 0.2, 0.97)", "(0, 0, 1)", "v0"
  double length = 1.0;                   // of yours
  std::string faces() const { return " faces around " + vertex; }
};

std::string count_of(size_t n) { return std::to_string(n); }

// "all 4 (of them)", "both".
std::string all_of(size_t n) { return n == 2 ? "both" : "all " + count_of(n); }

// A recipe with one choice changed, in its own words.
std::string one_change(const NormalRecipe& r, const Said& s) {
  const std::string n = count_of(r.face_count), face = format_id(r.face);
  const std::string mine = "your normal " + s.yours;
  if (r.weight == FaceWeight::UnitNormal) {
    return mine + " is the average of the faces' unit normals; the reference " + s.reference + " " + kAreaWeights;
  }
  if (r.weight == FaceWeight::Angle) {
    return mine + " weights each face by its angle at " + s.vertex + " (an angle-weighted normal); the reference " +
           s.reference + " " + kAreaWeights;
  }
  if (r.orientation == Orientation::Inward) {
    return mine + " points inwards (the reference's is " + s.reference +
           "): take the cross product of the edges in the face's order, " + kFaceOrder;
  }
  if (r.orientation == Orientation::OneFaceInward) {
    return mine + " takes " + format_id(r.inward_face) +
           "'s cross product the wrong way round, pointing inwards (the reference's is " + s.reference +
           "): take every face's in the face's order, " + kFaceOrder +
           " with p0 = h.vertex.position, p1 = h.next.vertex.position and p2 = h.next.next.vertex.position";
  }
  switch (r.faces) {
    case FacesCounted::WithBoundaryLoop:
      return mine + " counts the boundary loop as a face (" + face + "); the reference " + s.reference +
             " adds only the " + n + " real" + s.faces() + ": skip faces with f:is_boundary()";
    case FacesCounted::AllButOne:
      return mine + " leaves out " + face + ", one of the " + n + s.faces() + "; the reference " + s.reference +
             " adds the cross products of " + all_of(r.face_count) +
             ": walk h = h.twin.next until h is back at v.halfedge and count the face of every h (a loop that tests "
             "before adding, or stops one step early, misses one)";
    case FacesCounted::OneOnly:
      return mine + " is the normal of " + face + " alone, one of the " + n + s.faces() + "; the reference " +
             s.reference + " adds the cross products of " + all_of(r.face_count) +
             ", then normalises: add each face's to the sum (sum = sum + ..., not sum = ...) and return after the "
             "loop, not inside it";
    case FacesCounted::All: break;
  }
  return mine + " differs from the reference's " + s.reference;
}

// The recipe described: "the normalised sum of the unit normals of the faces around v0 except f3".
std::string describe(const NormalRecipe& r, bool normalised, const Said& s) {
  const std::string n = count_of(r.face_count), face = format_id(r.face);
  if (r.faces == FacesCounted::OneOnly) {
    return face + "'s cross product alone" +
           (r.orientation == Orientation::Inward ? ", the wrong way round (pointing inwards)" : "") + ", one of the " +
           n + s.faces() + (normalised ? ", normalised" : " (not normalised)");
  }
  std::string text = normalised ? "the normalised sum of " : "the sum (not normalised) of ";
  text += r.weight == FaceWeight::Area ? "the cross products" : "the unit normals";
  if (r.faces == FacesCounted::All) text += " of the " + n + s.faces();
  if (r.faces == FacesCounted::AllButOne) text += " of the" + s.faces() + " except " + face;
  if (r.faces == FacesCounted::WithBoundaryLoop) {
    text += " of the " + n + s.faces() + " and of the boundary loop " + face;
  }
  if (r.weight == FaceWeight::Angle) text += ", each weighted by its face's angle at " + s.vertex;
  if (r.orientation == Orientation::Inward) text += ", each taken the wrong way round (pointing inwards)";
  if (r.orientation == Orientation::OneFaceInward) {
    text += ", with " + format_id(r.inward_face) + "'s the wrong way round";
  }
  return text;
}

// One fix per choice that differs from the course's, in the order the description names them.
std::vector<std::string> fixes(const NormalRecipe& r, bool normalised) {
  std::vector<std::string> out;
  const std::string face = format_id(r.face);
  if (r.faces == FacesCounted::AllButOne) {
    out.push_back("count " + face + " too (walk h = h.twin.next until h is back at v.halfedge)");
  }
  if (r.faces == FacesCounted::OneOnly) {
    out.push_back("add every face's cross product, not " + face + "'s alone (return after the loop)");
  }
  if (r.faces == FacesCounted::WithBoundaryLoop) out.push_back("skip faces with f:is_boundary()");
  if (r.weight != FaceWeight::Area) out.push_back("weight each face by its area (add the cross products themselves)");
  if (r.orientation == Orientation::Inward) {
    out.push_back(std::string("take the cross product of the edges in the face's order, ") + kFaceOrder);
  }
  if (r.orientation == Orientation::OneFaceInward) {
    out.push_back("take " + format_id(r.inward_face) + "'s cross product in the face's order too, " + kFaceOrder);
  }
  if (!normalised) out.push_back("normalise the sum (n:normalized())");
  return out;
}

std::string described_with_fixes(const NormalMatch& m, const Said& s) {
  std::string text = "your normal " + s.yours + " is ";
  if (m.near) {
    const double degrees = std::round(m.angle * 180.0 / std::numbers::pi * 100.0) / 100.0;
    text += "close to (" + format_number(degrees) + " degrees from) ";
  }
  text += describe(m.recipe, m.normalised, s) + "; the reference " + s.reference +
          " is the normalised sum of the cross products of the " + count_of(m.recipe.face_count) + s.faces() + ": ";
  const std::vector<std::string> all = fixes(m.recipe, m.normalised);
  for (size_t i = 0; i < all.size(); ++i) text += (i > 0 ? "; " : "") + all[i];
  return text;
}

}  // namespace

std::string explain_vertex_normal(const HalfedgeMesh& mesh, VertexId v, const glm::dvec3& yours,
                                  const glm::dvec3& reference) {
  const double off = glm::distance(yours, reference);
  if (off <= kSameNormal) return "";
  const Said s{format_position(yours), format_position(reference), format_id(v), glm::length(yours)};
  const std::optional<NormalMatch> m = match_normal(mesh, v, yours, reference);
  if (!m) {
    return "your normal " + s.yours + " differs from the reference's " + s.reference + " by " + format_number(off);
  }
  if (m->recipe.changes() == 0) {
    return "your normal " + s.yours + " points the right way but has length " + format_number(s.length) +
           "; normalise it (n:normalized())";
  }
  std::string text = m->recipe.changes() == 1 && !m->near ? one_change(m->recipe, s) : described_with_fixes(*m, s);
  if (m->recipe.changes() == 1 && !m->near && !m->normalised) {
    text += "; and normalise the sum (n:normalized()): yours has length " + format_number(s.length);
  }
  if (m->also) text += "; on this mesh that is also " + describe(*m->also, m->normalised, s);
  return text;
}

}  // namespace meshedit
