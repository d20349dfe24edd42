// MeshRenderer (see mesh_renderer.h for the contract).
//
// GPU layout, rebuilt by update() only when the mesh or its version changes:
// - faces: positions and smooth normals indexed by vertex id, an index buffer of fanned triangles, and
//   two buffer textures looked up by gl_PrimitiveID / face slot (triangle -> face, face -> normal), so
//   flat shading needs no duplicated vertices;
// - edges (and a second batch with the boundary edges only), vertices, and on demand halfedge arrows,
//   as segments and points (gpu_batches.h).
// Highlights never touch those: hovered and selected are uniforms (one id per kind), "changed" is one
// byte per element in a buffer texture per kind. Elements that are highlighted but whose full pass is
// off (no wireframe, no vertices, no arrows) are drawn again from small batches built from the mesh for
// just those elements.
#include "render/mesh_renderer.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include <epoxy/gl.h>
#include <glm/geometric.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "render/gl_objects.h"
#include "render/gpu_batches.h"
#include "render/mesh_geometry.h"
#include "render/pick_id.h"
#include "render/render_error.h"

namespace meshedit {
namespace {

constexpr uint32_t kNoElement = 0xFFFFFFFFu;

// The kinds that have a "changed" flag texture, in this order.
enum KindSlot : int { kVertexSlot = 0, kHalfedgeSlot, kEdgeSlot, kFaceSlot, kKindSlots };

int slot_of(ElementKind kind) {
  switch (kind) {
    case ElementKind::Vertex: return kVertexSlot;
    case ElementKind::Halfedge: return kHalfedgeSlot;
    case ElementKind::Edge: return kEdgeSlot;
    case ElementKind::Face: return kFaceSlot;
    case ElementKind::Boundary: break;
  }
  return -1;
}

uint32_t id_if(ElementRef ref, ElementKind kind) { return ref.valid() && ref.kind == kind ? ref.index : kNoElement; }

void add_arrow_segments(const HalfedgeArrow& arrow, std::vector<EdgeSegment>& out) {
  out.push_back({arrow.tail, arrow.tip, arrow.halfedge, 0});
  out.push_back({arrow.tip, arrow.barb_inner, arrow.halfedge, 0});
  out.push_back({arrow.tip, arrow.barb_outer, arrow.halfedge, 0});
}

bool finite(const glm::dvec3& p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); }

// The small batches of highlighted elements: segments for edges, segments for arrows, points.
struct ItemLists {
  std::vector<EdgeSegment> edges, arrows;
  std::vector<VertexPoint> points;

  void add(const HalfedgeMesh& mesh, ElementRef ref) {
    if (!ref.valid()) return;
    switch (ref.kind) {
      case ElementKind::Vertex: {
        const VertexId v(ref.index);
        if (mesh.alive(v) && finite(mesh.position(v))) points.push_back({glm::vec3(mesh.position(v)), v.index});
        break;
      }
      case ElementKind::Edge:
        if (auto segment = edge_segment(mesh, EdgeId(ref.index))) edges.push_back(*segment);
        break;
      case ElementKind::Halfedge:
        if (auto arrow = halfedge_arrow(mesh, HalfedgeId(ref.index))) add_arrow_segments(*arrow, arrows);
        break;
      case ElementKind::Face:
      case ElementKind::Boundary: break;  // faces are tinted by the face shader; loops have no area
    }
  }
};

// What update() compares to decide that the mesh is the one already uploaded: the object and its
// version, and (cheap insurance for a mesh object that was assigned a different mesh whose version
// happens to match) its capacities and live counts.
struct MeshKey {
  const HalfedgeMesh* mesh = nullptr;
  uint64_t version = 0;
  std::array<size_t, 9> sizes{};

  static MeshKey of(const HalfedgeMesh& m) {
    return {&m, m.version(),
            {m.vertex_capacity(), m.halfedge_capacity(), m.edge_capacity(), m.face_capacity(), m.boundary_capacity(),
             m.num_vertices(), m.num_halfedges(), m.num_edges(), m.num_faces()}};
  }
  bool operator==(const MeshKey& o) const { return mesh == o.mesh && version == o.version && sizes == o.sizes; }
};

struct PickKey {
  const HalfedgeMesh* mesh = nullptr;
  uint64_t version = 0;
  glm::dmat4 view_projection{0.0};
  int width = 0, height = 0;
  bool halfedges = false;

  bool operator==(const PickKey& o) const {
    return mesh == o.mesh && version == o.version && view_projection == o.view_projection && width == o.width &&
           height == o.height && halfedges == o.halfedges;
  }
};

// Polygon offset factor of the back-side pass (see draw_triangles); 12 was the least that removed every
// back-coloured pixel from the cube's silhouettes in the three-quarter view, 16 leaves a margin.
constexpr float kBackOffsetFactor = 16.0f;

// Every face triangle of the bound vertex array, pushed back by polygon offset so lines and points
// drawn later at the same depth win. Front sides first, then back sides where they are nearer. Along a
// silhouette a front and a back side meet at equal depth, and polygon offset pushes each back by about
// one pixel of its own depth slope: the grazing front side further than the back one, so a fringe of
// back colour would win there. The back pass is pushed much further to lose it; the price is that a
// back side closer than that margin in front of a front side is hidden, which real scenes rarely have.
void draw_triangles(GLuint vertex_array, size_t index_count) {
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(1.0f, 1.0f);
  glBindVertexArray(vertex_array);
  glFrontFace(GL_CCW);  // faces are counter-clockwise seen from outside (core/primitives.h)
  glEnable(GL_CULL_FACE);
  glCullFace(GL_BACK);
  glDrawElements(GL_TRIANGLES, GLsizei(index_count), GL_UNSIGNED_INT, nullptr);
  glCullFace(GL_FRONT);
  glDepthFunc(GL_LESS);
  glPolygonOffset(kBackOffsetFactor, 1.0f);
  glDrawElements(GL_TRIANGLES, GLsizei(index_count), GL_UNSIGNED_INT, nullptr);
  glDepthFunc(GL_LEQUAL);
  glCullFace(GL_BACK);
  glDisable(GL_CULL_FACE);
  glDisable(GL_POLYGON_OFFSET_FILL);
}

void set_colour(const ShaderProgram& program, const char* name, const glm::vec4& colour) {
  glUniform4fv(program.uniform(name), 1, glm::value_ptr(colour));
}

}  // namespace

struct MeshRenderer::Impl {
  explicit Impl(const ShaderLibrary& shaders)
      : face(shaders.program("face.vert", "face.frag")),
        face_pick(shaders.program("face.vert", "face_pick.frag")),
        segment(shaders.program("segment.vert", "segment.frag")),
        segment_pick(shaders.program("segment.vert", "id.frag")),
        point(shaders.program("point.vert", "point.frag")),
        point_pick(shaders.program("point.vert", "id.frag")),
        face_vao(gl::make_vertex_array()),
        positions(gl::make_buffer()),
        normals(gl::make_buffer()),
        indices(gl::make_buffer()),
        changed{gl::BufferTexture(GL_R8UI), gl::BufferTexture(GL_R8UI), gl::BufferTexture(GL_R8UI),
                gl::BufferTexture(GL_R8UI)} {
    glBindVertexArray(face_vao.get());
    glBindBuffer(GL_ARRAY_BUFFER, positions.get());
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(glm::vec3), nullptr);
    glBindBuffer(GL_ARRAY_BUFFER, normals.get());
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, sizeof(glm::vec3), nullptr);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, indices.get());
    glBindVertexArray(0);
    GLint max_texels = 0;
    glGetIntegerv(GL_MAX_TEXTURE_BUFFER_SIZE, &max_texels);
    max_buffer_texels = size_t(std::max(max_texels, 0));
  }

  void upload(const HalfedgeMesh& mesh);
  void refresh_changed(const std::vector<ElementRef>& list);
  void refresh_focus(ElementRef hovered, ElementRef selected);
  void ensure_arrows();
  void draw_faces(const gl::CameraUniforms& uniforms, const OrbitCamera& camera, const ViewOptions& options,
                  const Highlights& highlights);
  void draw_lines_and_points(const gl::CameraUniforms& uniforms, const ViewOptions& options,
                             const Highlights& highlights);
  void draw_ids(const gl::CameraUniforms& uniforms, bool halfedges);
  void ensure_pick_target(Viewport viewport);
  void count_gpu_bytes();

  ShaderProgram face, face_pick, segment, segment_pick, point, point_pick;
  gl::VertexArray face_vao;
  gl::Buffer positions, normals, indices;
  size_t index_count = 0;
  size_t vertex_bytes = 0;  // of each of `positions` and `normals`
  gl::BufferTexture triangle_faces{GL_R32UI};
  gl::BufferTexture face_normals{GL_RGBA32F};
  std::array<gl::BufferTexture, kKindSlots> changed;
  std::array<std::vector<uint8_t>, kKindSlots> changed_flags;
  gl::SegmentBatch edges, boundary_edges, arrows;
  gl::PointBatch points;
  gl::SegmentBatch changed_edges, changed_arrows, focus_edges, focus_arrows;
  gl::PointBatch changed_points, focus_points;
  size_t max_buffer_texels = 0;

  // What is uploaded.
  const HalfedgeMesh* mesh = nullptr;
  uint64_t version = 0;
  MeshKey uploaded_key;
  bool uploaded = false;
  BoundingBox bounds;
  // Keys of the derived uploads; each is refreshed when its key no longer matches.
  uint64_t arrows_upload = ~uint64_t(0);   // the `uploads` count the arrows were built for
  uint64_t changed_upload = ~uint64_t(0);
  std::vector<ElementRef> changed_list;
  uint64_t focus_upload = ~uint64_t(0);
  ElementRef focus_hovered, focus_selected;

  ViewOptions last_options;
  gl::Framebuffer pick_framebuffer;
  gl::Renderbuffer pick_ids, pick_depth;
  Viewport pick_size{0, 0};
  PickKey pick_key;
  bool pick_valid = false;

  RenderStats stats;
  RenderStyle style;
};

void MeshRenderer::Impl::upload(const HalfedgeMesh& source) {
  const MeshGeometry g = build_mesh_geometry(source);
  // Buffer textures: one texel per triangle, face, or element flag; two per edge segment.
  const size_t largest = std::max({g.triangle_count(), g.face_normals.size(), size_t(source.vertex_capacity()),
                                   size_t(source.halfedge_capacity()), 2 * g.edges.size()});
  if (largest > max_buffer_texels) {
    throw RenderError("the mesh is too large to draw: it needs " + std::to_string(largest) +
                      " texels in one buffer texture, and this OpenGL allows " + std::to_string(max_buffer_texels));
  }
  glBindBuffer(GL_ARRAY_BUFFER, positions.get());
  glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(g.positions.size() * sizeof(glm::vec3)), g.positions.data(),
               GL_STATIC_DRAW);
  glBindBuffer(GL_ARRAY_BUFFER, normals.get());
  glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(g.smooth_normals.size() * sizeof(glm::vec3)), g.smooth_normals.data(),
               GL_STATIC_DRAW);
  glBindVertexArray(face_vao.get());
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(g.triangle_corners.size() * sizeof(uint32_t)),
               g.triangle_corners.data(), GL_STATIC_DRAW);
  glBindVertexArray(0);
  index_count = g.triangle_corners.size();
  vertex_bytes = g.positions.size() * sizeof(glm::vec3);

  triangle_faces.upload(g.triangle_faces.data(), g.triangle_faces.size() * sizeof(uint32_t), GL_STATIC_DRAW);
  std::vector<glm::vec4> normals4(g.face_normals.size());
  for (size_t i = 0; i < normals4.size(); ++i) normals4[i] = glm::vec4(g.face_normals[i], 0.0f);
  face_normals.upload(normals4.data(), normals4.size() * sizeof(glm::vec4), GL_STATIC_DRAW);

  edges.upload(g.edges.data(), g.edges.size(), GL_STATIC_DRAW);
  std::vector<EdgeSegment> boundary;
  for (const EdgeSegment& s : g.edges) {
    if (s.flags & kEdgeBoundaryFlag) boundary.push_back(s);
  }
  boundary_edges.upload(boundary.data(), boundary.size(), GL_STATIC_DRAW);
  points.upload(g.points.data(), g.points.size(), GL_STATIC_DRAW);

  mesh = &source;
  version = source.version();
  uploaded_key = MeshKey::of(source);
  uploaded = true;
  bounds = g.bounds;
  pick_valid = false;
  ++stats.uploads;
  stats.triangles = g.triangle_count();
  stats.edges = g.edges.size();
  stats.boundary_edges = boundary.size();
  stats.vertices = g.points.size();
  stats.arrows = 0;
  stats.skipped_faces = g.skipped_faces.size();
  stats.skipped_edges = g.skipped_edges.size();
  arrows.upload(nullptr, 0, GL_STATIC_DRAW);  // stale until asked for again
  count_gpu_bytes();
}

void MeshRenderer::Impl::refresh_changed(const std::vector<ElementRef>& list) {
  if (changed_upload == stats.uploads && list == changed_list) return;
  const std::array<uint32_t, kKindSlots> capacity = {mesh->vertex_capacity(), mesh->halfedge_capacity(),
                                                     mesh->edge_capacity(), mesh->face_capacity()};
  for (int k = 0; k < kKindSlots; ++k) changed_flags[k].assign(capacity[k], 0);
  ItemLists items;
  for (ElementRef ref : list) {
    const int slot = slot_of(ref.kind);
    if (slot < 0 || !ref.valid() || ref.index >= changed_flags[slot].size()) continue;
    changed_flags[slot][ref.index] = 1;
    items.add(*mesh, ref);
  }
  for (int k = 0; k < kKindSlots; ++k) {
    changed[k].upload(changed_flags[k].data(), changed_flags[k].size(), GL_DYNAMIC_DRAW);
  }
  changed_edges.upload(items.edges.data(), items.edges.size(), GL_DYNAMIC_DRAW);
  changed_arrows.upload(items.arrows.data(), items.arrows.size(), GL_DYNAMIC_DRAW);
  changed_points.upload(items.points.data(), items.points.size(), GL_DYNAMIC_DRAW);
  changed_list = list;
  changed_upload = stats.uploads;
  ++stats.highlight_uploads;
  count_gpu_bytes();
}

void MeshRenderer::Impl::refresh_focus(ElementRef hovered, ElementRef selected) {
  if (focus_upload == stats.uploads && hovered == focus_hovered && selected == focus_selected) return;
  ItemLists items;
  items.add(*mesh, hovered);
  if (selected != hovered) items.add(*mesh, selected);
  focus_edges.upload(items.edges.data(), items.edges.size(), GL_STREAM_DRAW);
  focus_arrows.upload(items.arrows.data(), items.arrows.size(), GL_STREAM_DRAW);
  focus_points.upload(items.points.data(), items.points.size(), GL_STREAM_DRAW);
  focus_hovered = hovered;
  focus_selected = selected;
  focus_upload = stats.uploads;
  ++stats.highlight_uploads;
}

void MeshRenderer::Impl::ensure_arrows() {
  if (arrows_upload == stats.uploads) return;
  arrows_upload = stats.uploads;
  // Three segments of two texels per halfedge; past the driver's limit (22 million halfedges on
  // llvmpipe) there are no arrows, which would be unreadable at that size anyway.
  if (6 * size_t(mesh->num_halfedges()) > max_buffer_texels) return;
  const std::vector<HalfedgeArrow> built = build_halfedge_arrows(*mesh);
  std::vector<EdgeSegment> segments;
  segments.reserve(built.size() * 3);
  for (const HalfedgeArrow& arrow : built) add_arrow_segments(arrow, segments);
  arrows.upload(segments.data(), segments.size(), GL_STATIC_DRAW);
  stats.arrows = built.size();
  ++stats.arrow_uploads;
  pick_valid = false;
  count_gpu_bytes();
}

void MeshRenderer::Impl::count_gpu_bytes() {
  size_t total = index_count * sizeof(uint32_t) + 2 * vertex_bytes;
  total += triangle_faces.bytes() + face_normals.bytes();
  for (const auto& flags : changed) total += flags.bytes();
  for (const gl::SegmentBatch* b : {&edges, &boundary_edges, &arrows, &changed_edges, &changed_arrows}) {
    total += b->bytes();
  }
  total += points.bytes() + changed_points.bytes();
  stats.gpu_bytes = total;
}

void MeshRenderer::Impl::draw_faces(const gl::CameraUniforms& uniforms, const OrbitCamera& camera,
                                    const ViewOptions& options, const Highlights& highlights) {
  face.use();
  gl::set_camera(face, uniforms);
  const glm::vec3 eye(camera.eye());
  // A light a little above and to the left of the eye, moving with it: no side of the mesh stays dark,
  // and the three faces a three-quarter view shows get three clearly different shades.
  const glm::vec3 light(glm::normalize(-camera.forward_direction() + 0.3 * camera.screen_up_direction() -
                                       0.2 * camera.right_direction()));
  glUniform3fv(face.uniform("u_eye"), 1, glm::value_ptr(eye));
  glUniform3fv(face.uniform("u_light"), 1, glm::value_ptr(light));
  glUniform1i(face.uniform("u_smooth"), options.smooth_shading ? 1 : 0);
  glUniform1ui(face.uniform("u_selected"), id_if(highlights.selected, ElementKind::Face));
  glUniform1ui(face.uniform("u_hovered"), id_if(highlights.hovered, ElementKind::Face));
  set_colour(face, "u_face_colour", style.face);
  set_colour(face, "u_back_colour", style.back_face);
  set_colour(face, "u_selected_colour", style.selected);
  set_colour(face, "u_hovered_colour", style.hovered);
  set_colour(face, "u_changed_colour", style.changed);
  triangle_faces.bind(0);
  face_normals.bind(1);
  changed[kFaceSlot].bind(2);
  glUniform1i(face.uniform("u_triangle_faces"), 0);
  glUniform1i(face.uniform("u_face_normals"), 1);
  glUniform1i(face.uniform("u_changed"), 2);
  draw_triangles(face_vao.get(), index_count);
}

void MeshRenderer::Impl::draw_lines_and_points(const gl::CameraUniforms& uniforms, const ViewOptions& options,
                                               const Highlights& highlights) {
  segment.use();
  gl::set_camera(segment, uniforms);
  glUniform1i(segment.uniform("u_segments"), 1);
  glUniform1i(segment.uniform("u_lines"), 0);
  glUniform1i(segment.uniform("u_styles"), 2);
  glUniform1i(segment.uniform("u_element_colours"), 1);
  glUniform1f(segment.uniform("u_pick_width"), 0.0f);
  glUniform1f(segment.uniform("u_cap"), 0.0f);
  glUniform1i(segment.uniform("u_changed"), 0);
  set_colour(segment, "u_boundary_colour", style.boundary);
  set_colour(segment, "u_selected_colour", style.selected);
  set_colour(segment, "u_hovered_colour", style.hovered);
  set_colour(segment, "u_changed_colour", style.changed);
  glUniform1f(segment.uniform("u_boundary_width"), style.boundary_width);
  glUniform1f(segment.uniform("u_highlight_width"), style.highlight_width);

  // Edges: all of them (W), or the boundary only; then the highlighted ones on top.
  set_colour(segment, "u_base_colour", style.wire);
  glUniform1f(segment.uniform("u_base_width"), style.wire_width);
  glUniform1i(segment.uniform("u_show_boundary"), options.show_boundary ? 1 : 0);
  glUniform1ui(segment.uniform("u_selected"), id_if(highlights.selected, ElementKind::Edge));
  glUniform1ui(segment.uniform("u_hovered"), id_if(highlights.hovered, ElementKind::Edge));
  changed[kEdgeSlot].bind(0);
  // A hairline wireframe is drawn as GL_LINES: one primitive per edge instead of two triangles, which
  // halves what llvmpipe spends on it. The boundary then goes over it at its own width.
  const bool hairlines = style.wire_width <= 1.0f;
  if (options.wireframe && hairlines) {
    glUniform1i(segment.uniform("u_lines"), 1);
    edges.draw_lines();
    glUniform1i(segment.uniform("u_lines"), 0);
  } else if (options.wireframe) {
    edges.draw();
  }
  if (options.show_boundary && (!options.wireframe || hairlines)) boundary_edges.draw();
  changed_edges.draw();
  focus_edges.draw();

  // Halfedge arrows.
  set_colour(segment, "u_base_colour", style.arrow);
  glUniform1f(segment.uniform("u_base_width"), style.arrow_width);
  glUniform1i(segment.uniform("u_show_boundary"), 0);
  glUniform1ui(segment.uniform("u_selected"), id_if(highlights.selected, ElementKind::Halfedge));
  glUniform1ui(segment.uniform("u_hovered"), id_if(highlights.hovered, ElementKind::Halfedge));
  changed[kHalfedgeSlot].bind(0);
  if (options.show_halfedges) arrows.draw();
  changed_arrows.draw();
  focus_arrows.draw();

  // Vertices.
  point.use();
  gl::set_camera(point, uniforms);
  glUniform1i(point.uniform("u_element_colours"), 1);
  glUniform1f(point.uniform("u_pick_size"), 0.0f);
  glUniform1i(point.uniform("u_changed"), 0);
  set_colour(point, "u_base_colour", style.vertex);
  set_colour(point, "u_selected_colour", style.selected);
  set_colour(point, "u_hovered_colour", style.hovered);
  set_colour(point, "u_changed_colour", style.changed);
  glUniform1f(point.uniform("u_base_size"), style.vertex_size);
  glUniform1f(point.uniform("u_highlight_size"), style.highlight_vertex_size);
  glUniform1ui(point.uniform("u_selected"), id_if(highlights.selected, ElementKind::Vertex));
  glUniform1ui(point.uniform("u_hovered"), id_if(highlights.hovered, ElementKind::Vertex));
  changed[kVertexSlot].bind(0);
  if (options.show_vertices) points.draw();
  changed_points.draw();
  focus_points.draw();
}

void MeshRenderer::Impl::draw_ids(const gl::CameraUniforms& uniforms, bool halfedges) {
  face_pick.use();
  gl::set_camera(face_pick, uniforms);
  glUniform1ui(face_pick.uniform("u_kind_bits"), pick_kind_bits(ElementKind::Face));
  glUniform1i(face_pick.uniform("u_triangle_faces"), 0);
  triangle_faces.bind(0);
  draw_triangles(face_vao.get(), index_count);

  // Edges and arrows as hairlines: pick() reads a window around the cursor, so one within its radius is
  // found (and wins over the face by priority); hairlines cost llvmpipe half what wide segments do.
  // They are tested against the faces' depth but do not write it, so the vertices drawn last are hidden
  // only by faces: a line's first pixel can lie a little nearer than the vertex it starts from.
  segment_pick.use();
  gl::set_camera(segment_pick, uniforms);
  glUniform1i(segment_pick.uniform("u_segments"), 1);
  glUniform1i(segment_pick.uniform("u_lines"), 1);
  glUniform1i(segment_pick.uniform("u_styles"), 2);
  glUniform1i(segment_pick.uniform("u_element_colours"), 0);
  glUniform1f(segment_pick.uniform("u_pick_width"), 1.0f);
  glUniform1f(segment_pick.uniform("u_cap"), 0.0f);
  glUniform1ui(segment_pick.uniform("u_kind_bits"), pick_kind_bits(ElementKind::Edge));
  glDepthMask(GL_FALSE);
  edges.draw_lines();
  if (halfedges) {
    glUniform1ui(segment_pick.uniform("u_kind_bits"), pick_kind_bits(ElementKind::Halfedge));
    arrows.draw_lines();
  }
  glDepthMask(GL_TRUE);

  point_pick.use();
  gl::set_camera(point_pick, uniforms);
  glUniform1i(point_pick.uniform("u_element_colours"), 0);
  glUniform1f(point_pick.uniform("u_pick_size"), 1.0f);  // one pixel each: dots would cover neighbours
  glUniform1ui(point_pick.uniform("u_kind_bits"), pick_kind_bits(ElementKind::Vertex));
  points.draw();
}

void MeshRenderer::Impl::ensure_pick_target(Viewport viewport) {
  if (pick_framebuffer && pick_size.width == viewport.width && pick_size.height == viewport.height) return;
  pick_framebuffer = gl::make_framebuffer();
  pick_ids = gl::make_renderbuffer();
  pick_depth = gl::make_renderbuffer();
  glBindRenderbuffer(GL_RENDERBUFFER, pick_ids.get());
  glRenderbufferStorage(GL_RENDERBUFFER, GL_R32UI, viewport.width, viewport.height);
  glBindRenderbuffer(GL_RENDERBUFFER, pick_depth.get());
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, viewport.width, viewport.height);
  glBindFramebuffer(GL_FRAMEBUFFER, pick_framebuffer.get());
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, pick_ids.get());
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, pick_depth.get());
  if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
    pick_framebuffer.reset();
    throw RenderError("the picking framebuffer (R32UI + depth, " + std::to_string(viewport.width) + "x" +
                      std::to_string(viewport.height) + ") is incomplete");
  }
  pick_size = viewport;
  pick_valid = false;
}

MeshRenderer::MeshRenderer(const ShaderLibrary& shaders) : impl_(std::make_unique<Impl>(shaders)) {}

MeshRenderer::~MeshRenderer() = default;

void MeshRenderer::update(const HalfedgeMesh& mesh) {
  Impl& r = *impl_;
  if (r.uploaded && r.uploaded_key == MeshKey::of(mesh)) return;
  r.upload(mesh);
}

void MeshRenderer::draw(const OrbitCamera& camera, Viewport viewport, const ViewOptions& options,
                        const Highlights& highlights) {
  Impl& r = *impl_;
  r.last_options = options;
  if (!r.uploaded || viewport.width < 1 || viewport.height < 1) return;
  r.refresh_changed(highlights.changed);
  r.refresh_focus(highlights.hovered, highlights.selected);
  if (options.show_halfedges) r.ensure_arrows();

  const gl::CameraUniforms uniforms = gl::camera_uniforms(camera, viewport);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LEQUAL);
  glDepthMask(GL_TRUE);
  glDisable(GL_CULL_FACE);
  glEnable(GL_PROGRAM_POINT_SIZE);
  r.draw_faces(uniforms, camera, options, highlights);
  r.draw_lines_and_points(uniforms, options, highlights);
  glBindVertexArray(0);
  glUseProgram(0);
}

ElementRef MeshRenderer::pick(const OrbitCamera& camera, Viewport viewport, int x, int y) {
  Impl& r = *impl_;
  if (!r.uploaded || x < 0 || y < 0 || x >= viewport.width || y >= viewport.height) return ElementRef();
  const bool halfedges = r.last_options.show_halfedges;
  if (halfedges) r.ensure_arrows();

  gl::FramebufferScope restore;
  r.ensure_pick_target(viewport);
  PickKey key;
  key.mesh = r.mesh;
  key.version = r.version;
  key.view_projection = camera.view_projection(viewport);
  key.width = viewport.width;
  key.height = viewport.height;
  key.halfedges = halfedges;
  glBindFramebuffer(GL_FRAMEBUFFER, r.pick_framebuffer.get());
  if (!r.pick_valid || !(key == r.pick_key)) {
    glViewport(0, 0, viewport.width, viewport.height);
    const GLuint background[4] = {0, 0, 0, 0};
    const GLfloat far_depth = 1.0f;
    glDepthMask(GL_TRUE);
    glClearBufferuiv(GL_COLOR, 0, background);
    glClearBufferfv(GL_DEPTH, 0, &far_depth);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);
    glDisable(GL_CULL_FACE);
    glEnable(GL_PROGRAM_POINT_SIZE);
    r.draw_ids(gl::camera_uniforms(camera, viewport), halfedges);
    glBindVertexArray(0);
    glUseProgram(0);
    r.pick_key = key;
    r.pick_valid = true;
    ++r.stats.id_passes;
  }

  // The window around the cursor, clamped to the viewport; OpenGL's rows count from the bottom.
  const int x0 = std::max(0, x - kVertexPickRadius), x1 = std::min(viewport.width - 1, x + kVertexPickRadius);
  const int y0 = std::max(0, y - kVertexPickRadius), y1 = std::min(viewport.height - 1, y + kVertexPickRadius);
  const int w = x1 - x0 + 1, h = y1 - y0 + 1;
  std::vector<uint32_t> bottom_up(size_t(w) * size_t(h));
  glReadBuffer(GL_COLOR_ATTACHMENT0);
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  glReadPixels(x0, viewport.height - 1 - y1, w, h, GL_RED_INTEGER, GL_UNSIGNED_INT, bottom_up.data());
  std::vector<uint32_t> top_down(bottom_up.size());
  for (int row = 0; row < h; ++row) {
    std::copy_n(bottom_up.begin() + long(row) * w, w, top_down.begin() + long(h - 1 - row) * w);
  }
  const ElementRef chosen = choose_pick(top_down, w, h, x - x0, y - y0);
  if (chosen.kind != ElementKind::Vertex || !chosen.valid()) return chosen;
  // Two vertices can share a pixel on a dense mesh, the last drawn covering the other: among the
  // vertices seen within reach, take the one whose position projects nearest the cursor.
  const glm::dvec2 cursor(x + 0.5, y + 0.5);
  ElementRef nearest = chosen;
  double best = 1e300;
  for (size_t i = 0; i < top_down.size(); ++i) {
    const ElementRef candidate = decode_pick_id(top_down[i]);
    if (candidate.kind != ElementKind::Vertex || !candidate.valid()) continue;
    const int dx = x0 + int(i % size_t(w)) - x, dy = y0 + int(i / size_t(w)) - y;
    if (dx * dx + dy * dy > kVertexPickRadius * kVertexPickRadius) continue;
    const VertexId v(candidate.index);
    if (!r.mesh->alive(v)) continue;
    const ScreenPoint p = camera.project(r.mesh->position(v), viewport);
    const double d = glm::dot(p.pixel - cursor, p.pixel - cursor);
    if (p.in_front && d < best) {
      best = d;
      nearest = candidate;
    }
  }
  return nearest;
}

void MeshRenderer::invalidate() { impl_->uploaded = false; }

const BoundingBox& MeshRenderer::bounds() const { return impl_->bounds; }
const RenderStats& MeshRenderer::stats() const { return impl_->stats; }
RenderStyle& MeshRenderer::style() { return impl_->style; }

}  // namespace meshedit
