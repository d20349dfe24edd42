// Helpers shared by the io tests: the message of the FileError a call throws, and exact comparison of
// polygon meshes (by index, or by the corner positions of each face).
#pragma once

#include <gtest/gtest.h>

#include <string>

#include "core/polygon_mesh.h"
#include "io/file_error.h"

namespace meshedit::testing {

// The FileError's message, "<no error>" when the call succeeds, "<other exception: ...>" for anything
// else (which every test treats as a failure).
template <class Fn>
std::string error_of(Fn&& fn) {
  try {
    fn();
  } catch (const FileError& e) {
    return e.what();
  } catch (const std::exception& e) {
    return std::string("<other exception: ") + e.what() + ">";
  }
  return "<no error>";
}

// Asserts that `fn` throws a FileError whose message contains every one of `parts`.
#define EXPECT_FILE_ERROR(call, ...)                                                                           \
  do {                                                                                                         \
    const std::string message_ = ::meshedit::testing::error_of([&] { (void)(call); });                         \
    for (const char* part_ : {__VA_ARGS__}) {                                                                  \
      EXPECT_NE(message_.find(part_), std::string::npos) << "message: " << message_ << "\nmissing: " << part_; \
    }                                                                                                          \
  } while (0)

inline void expect_same_faces(const PolygonMesh& a, const PolygonMesh& b) {
  ASSERT_EQ(a.num_faces(), b.num_faces());
  EXPECT_EQ(a.indices, b.indices);
  EXPECT_EQ(a.face_offsets, b.face_offsets);
}

inline void expect_same_mesh(const PolygonMesh& a, const PolygonMesh& b) {
  ASSERT_EQ(a.num_vertices(), b.num_vertices());
  for (size_t v = 0; v < a.num_vertices(); ++v) {
    EXPECT_EQ(a.positions[v].x, b.positions[v].x) << "vertex " << v;
    EXPECT_EQ(a.positions[v].y, b.positions[v].y) << "vertex " << v;
    EXPECT_EQ(a.positions[v].z, b.positions[v].z) << "vertex " << v;
  }
  expect_same_faces(a, b);
}

// The same faces by the positions of their corners, in order, whatever the vertex numbering: what a format
// that stores every face's corners separately (STL) keeps.
inline void expect_same_face_positions(const PolygonMesh& a, const PolygonMesh& b) {
  ASSERT_EQ(a.num_faces(), b.num_faces());
  for (size_t f = 0; f < a.num_faces(); ++f) {
    ASSERT_EQ(a.face(f).size(), b.face(f).size()) << "face " << f;
    for (size_t c = 0; c < a.face(f).size(); ++c) {
      EXPECT_EQ(a.positions[a.face(f)[c]], b.positions[b.face(f)[c]]) << "face " << f << " corner " << c;
    }
  }
}

}  // namespace meshedit::testing
