// Procedural meshes: the shared test fixtures, the benchmark input and the shapes lessons start from.
// Every shape is a consistently oriented manifold with outward (counter-clockwise) faces, vertices
// numbered as documented per function so tests can name elements.
#pragma once

#include <cstdint>

#include "core/polygon_mesh.h"

namespace meshedit {

// 4 vertices, 4 triangles; regular, centred at the origin.
PolygonMesh make_tetrahedron();
// The unit cube [-0.5, 0.5]^3 as 12 triangles (like the course's cube.dae); vertex i has
// x = (i & 1), y = (i >> 1 & 1), z = (i >> 2 & 1), shifted by -0.5.
PolygonMesh make_cube();
// The same cube as 6 quads (for n-gon paths).
PolygonMesh make_cube_quads();
// 12 vertices on the unit sphere, 20 triangles.
PolygonMesh make_icosahedron();
// A flat grid in the z = 0 plane: (nx+1)*(ny+1) vertices over [0,nx]x[0,ny], row-major from (0,0),
// 2*nx*ny triangles; one boundary loop.
PolygonMesh make_grid(uint32_t nx, uint32_t ny);
// A disk: vertex 0 at the centre, vertices 1..n on the unit circle, n triangles; the centre has
// valence n and the rim is a boundary loop.
PolygonMesh make_fan(uint32_t n);
// A torus around the z axis with major radius 1 and minor radius 0.35: rings*sides vertices,
// 2*rings*sides triangles. Closed, genus 1.
PolygonMesh make_torus(uint32_t rings, uint32_t sides);
// A torus with about `faces` triangles (rings = 2*sides, rounded): the benchmark input.
PolygonMesh make_torus_with_faces(uint32_t faces);

}  // namespace meshedit
