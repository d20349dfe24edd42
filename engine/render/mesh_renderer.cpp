// MeshRenderer (see mesh_renderer.h for the contract).
//
// GPU layout (gpu_mesh.h, slot_geometry.h), by element slot so an edit rewrites only its slots:
// - faces: positions and smooth normals by vertex slot, one triangle per face slot (gl_PrimitiveID = face slot) plus
//   the packed later triangles of polygons, and face normals by face slot in a buffer texture, so flat shading
//   needs no duplicated vertices;
// - edges by edge slot (and a compact batch of the boundary edges), points by vertex slot, and on demand halfedge
//   arrows by halfedge slot, as segments and points (gpu_batches.h); empty slots are hidden.
// update() keeps them current: a full build (build_slot_geometry) or a patch (incremental_update.h).
// Highlights never touch those: hovered and selected are uniforms (one id per kind), "changed" is one
// byte per element in a buffer texture per kind, rewritten where the list changed. Elements that are highlighted
// but whose full pass is off (no wireframe, no vertices, no arrows) are drawn again from small batches built from
// the mesh for just those elements.
//
// Map of this file (each part starts at its `// ---- name` banner):
//   helpers              KindSlot (the kinds with a "changed" texture), ItemLists, MeshKey, PickKey, draw_triangles
//   Impl                 what the renderer keeps: the GPU mesh, the highlight textures, the pick target
//   uploads and patches  upload (a full build), patch (incremental_update.h), uploaded_state
//   highlights           refresh_changed, refresh_focus, ensure_arrows, count_gpu_bytes
//   drawing              draw_faces, draw_lines_and_points; the pick pass: pick_key_for, draw_ids, ensure_pick_target
//   MeshRenderer         the public functions: update, draw, pick, read_gpu_buffers
#include "render/mesh_renderer.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <string>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "core/finite.h"
#include "core/parallel_for.h"
#include "render/gl_api.h"
#include "render/gl_objects.h"
#include "render/gpu_batches.h"
#include "render/gpu_mesh.h"
#include "render/incremental_update.h"
#include "render/mesh_geometry.h"
#include "render/pick_from_faces.h"
#include "render/pick_id.h"
#include "render/render_error.h"

namespace meshedit {
namespace {

// ---- helpers ---------------------------------------------------------------------------------------

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

  static MeshKey of(const HalfedgeMesh& m) { return {&m, m.version(), sizes_of(m)}; }
  // Capacities and live counts of a mesh, or of the state before an edit (StateBefore).
  template <class Mesh>
  static std::array<size_t, 9> sizes_of(const Mesh& m) {
    return {m.vertex_capacity(), m.halfedge_capacity(), m.edge_capacity(), m.face_capacity(), m.boundary_capacity(),
            m.num_vertices(),    m.num_halfedges(),     m.num_edges(),     m.num_faces()};
  }
  bool operator==(const MeshKey& o) const { return mesh == o.mesh && version == o.version && sizes == o.sizes; }
};

struct PickKey {
  const HalfedgeMesh* mesh = nullptr;
  uint64_t version = 0;
  glm::dmat4 view_projection{0.0};
  int width = 0, height = 0;
  bool halfedges = false;
  bool faces_only = false;  // the pass drew faces only (pick_from_faces.h)
  bool front_only = false;  // the pass skipped back sides (ViewOptions::back_sides)

  bool operator==(const PickKey& o) const {
    return mesh == o.mesh && version == o.version && view_projection == o.view_projection && width == o.width &&
           height == o.height && halfedges == o.halfedges && faces_only == o.faces_only && front_only == o.front_only;
  }
};

// Polygon offset factor of the back-side pass (see draw_triangles); 12 was the least that removed every
// back-coloured pixel from the cube's silhouettes in the three-quarter view, 16 leaves a margin.
constexpr float kBackOffsetFactor = 16.0f;

// Every face triangle of `mesh` with the bound program, pushed back by polygon offset so lines and points
// drawn later at the same depth win. Front sides first, then back sides where they are nearer. Along a
// silhouette a front and a back side meet at equal depth, and polygon offset pushes each back by about
// one pixel of its own depth slope: the grazing front side further than the back one, so a fringe of
// back colour would win there. The back pass is pushed much further to lose it; the price is that a
// back side closer than that margin in front of a front side is hidden, which real scenes rarely have.
// A closed mesh (no boundary, every face drawn) shows no back side from outside: its back pass, a quarter of
// llvmpipe's frame on a dense mesh, is skipped when the options say so (`front_only`).
void draw_triangles(const gl::GpuMesh& mesh, const ShaderProgram& program, bool front_only) {
  const GLint extra = program.uniform("u_extra");
  glUniform1i(program.uniform("u_extra_faces"), 3);
  // The pulled face data where GLSL has no gl_PrimitiveID (gpu_mesh.h); natively the program has no such uniforms.
  glUniform1i(program.uniform("u_corners"), GLint(gl::GpuMesh::kPullUnits[0]));
  glUniform1i(program.uniform("u_positions"), GLint(gl::GpuMesh::kPullUnits[1]));
  glUniform1i(program.uniform("u_normals"), GLint(gl::GpuMesh::kPullUnits[2]));
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(1.0f, 1.0f);
  glFrontFace(GL_CCW);  // faces are counter-clockwise seen from outside (core/primitives.h)
  glEnable(GL_CULL_FACE);
  glCullFace(GL_BACK);
  mesh.draw_triangles(extra, 3);
  if (front_only) {
    glDisable(GL_CULL_FACE);
    glDisable(GL_POLYGON_OFFSET_FILL);
    return;
  }
  glCullFace(GL_FRONT);
  glDepthFunc(GL_LESS);
  glPolygonOffset(kBackOffsetFactor, 1.0f);
  mesh.draw_triangles(extra, 3);
  glDepthFunc(GL_LEQUAL);
  glCullFace(GL_BACK);
  glDisable(GL_CULL_FACE);
  glDisable(GL_POLYGON_OFFSET_FILL);
}

void set_colour(const ShaderProgram& program, const char* name, const glm::vec4& colour) {
  glUniform4fv(program.uniform(name), 1, glm::value_ptr(colour));
}

}  // namespace

// ---- Impl ------------------------------------------------------------------------------------------

struct MeshRenderer::Impl {
  explicit Impl(const ShaderLibrary& shaders)
      : face(shaders.program("face.vert", "face.frag")),
        face_pick(shaders.program("face.vert", "face_pick.frag")),
        segment(shaders.program("segment.vert", "segment.frag")),
        segment_pick(shaders.program("segment.vert", "id.frag")),
        point(shaders.program("point.vert", "point.frag")),
        point_pick(shaders.program("point.vert", "id.frag")),
        changed{gl::BufferTexture(GL_R8UI), gl::BufferTexture(GL_R8UI), gl::BufferTexture(GL_R8UI),
                gl::BufferTexture(GL_R8UI)} {
    max_buffer_texels = gl::max_buffer_texture_texels();
    glGetIntegerv(GL_SAMPLES, &stats.framebuffer_samples);
  }

  // A full build of `source` into the buffers; the smooth normals of the vertices in `normals` (by vertex slot) are
  // those given instead of the area-weighted ones.
  void upload(const HalfedgeMesh& source, std::string reason, std::span<const glm::vec3> normals = {});
  size_t buffer_texel_cap() const {
    return style.max_buffer_texels != 0 ? std::min(style.max_buffer_texels, max_buffer_texels) : max_buffer_texels;
  }
  // Throws RenderError, with nothing drawn until a mesh is uploaded, when a buffer texture would need more texels.
  void refuse_if_too_large(size_t texels);
  bool patch(const HalfedgeMesh& source, const MeshChange& change);
  template <class Before>
  bool patch_from(const Before& before, uint64_t before_version, const HalfedgeMesh& source, const MeshChange& change);
  void uploaded_state(const HalfedgeMesh& source);
  void refresh_changed(std::span<const ElementRef> list, uint64_t key);
  void refresh_focus(ElementRef hovered, ElementRef selected);
  void ensure_arrows();
  void draw_faces(const gl::CameraUniforms& uniforms, const OrbitCamera& camera, const ViewOptions& options,
                  const Highlights& highlights);
  void draw_lines_and_points(const gl::CameraUniforms& uniforms, const ViewOptions& options,
                             const Highlights& highlights);
  void draw_ids(const gl::CameraUniforms& uniforms, bool halfedges, bool faces_only) const;
  void ensure_pick_target(Viewport viewport);
  void count_gpu_bytes();
  PickKey pick_key_for(const OrbitCamera& camera, Viewport viewport) const;
  bool front_only(const ViewOptions& options) const { return !options.back_sides && is_closed(stats); }
  // A large mesh whose live faces and edges are all drawn is picked from a faces-only id pass
  // (pick_from_faces.h): every edge and vertex with a face is found through the faces around the cursor.
  bool pick_faces_only() const {
    return is_large_mesh(stats.triangles, style) && stats.skipped_faces == 0 && stats.skipped_edges == 0;
  }

  ShaderProgram face, face_pick, segment, segment_pick, point, point_pick;
  gl::GpuMesh gpu;
  SlotState slots;  // what the buffers describe besides themselves (counts, references, boundary list)
  std::array<gl::BufferTexture, kKindSlots> changed;
  std::array<std::vector<uint8_t>, kKindSlots> changed_flags;  // CPU copies, sized to what is allocated
  gl::SegmentBatch changed_edges, changed_arrows, focus_edges, focus_arrows;
  gl::PointBatch changed_points, focus_points;
  size_t max_buffer_texels = 0;

  // What is uploaded.
  const HalfedgeMesh* mesh = nullptr;
  uint64_t version = 0;
  MeshKey uploaded_key;
  bool uploaded = false;
  // +1 whenever the geometry changes (a full build or a patch); derived uploads are keyed by it.
  uint64_t geometry = 0;
  uint64_t arrows_geometry = ~uint64_t(0);  // the geometry the arrows show
  uint64_t changed_geometry = ~uint64_t(0);
  uint64_t changed_key = 0;
  std::vector<ElementRef> changed_list;  // the list the flags show
  uint64_t focus_geometry = ~uint64_t(0);
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

// ---- uploads and patches ---------------------------------------------------------------------------

void MeshRenderer::Impl::refuse_if_too_large(size_t texels) {
  if (texels <= buffer_texel_cap()) return;
  uploaded = false;  // what the buffers hold is not the mesh given: draw nothing, pick nothing
  ++stats.refusals;
  throw RenderError("the mesh is too large to draw: it needs " + std::to_string(texels) +
                    " texels in one buffer texture, and this OpenGL allows " + std::to_string(buffer_texel_cap()));
}

void MeshRenderer::Impl::upload(const HalfedgeMesh& source, std::string reason, std::span<const glm::vec3> normals) {
  const size_t sent = gl::uploaded_bytes();
  // Buffer textures: one texel per face slot, element flag or packed triangle; two per edge slot. Checked before the
  // slot build (a whole-mesh pass) as far as the capacities tell, so a refused mesh costs nothing per frame.
  refuse_if_too_large(
      gl::with_headroom(std::max({size_t(source.face_capacity()), size_t(source.vertex_capacity()),
                                  size_t(source.halfedge_capacity()), 2 * size_t(source.edge_capacity())})));
  SlotGeometry g = build_slot_geometry(source, hardware_threads());
  for (size_t v = 0; v < std::min(normals.size(), g.smooth_normals.size()); ++v) g.smooth_normals[v] = normals[v];
  refuse_if_too_large(gl::with_headroom(g.extra_faces.size()));  // the triangles of polygons past their first
  gpu.upload(g);
  slots = slot_state(source, g);
  stats.arrows = 0;
  arrows_geometry = ~uint64_t(0);  // stale until asked for again
  gpu.arrows.set_count(0);
  uploaded_state(source);
  ++stats.uploads;
  stats.last_update_patch = false;
  stats.last_update_bytes = gl::uploaded_bytes() - sent;
  stats.last_update_slots = g.positions.size() + g.face_normals.size() + g.edges.size();
  stats.last_rebuild_reason = std::move(reason);
}

// The bookkeeping both kinds of update share, once the buffers show `source`.
void MeshRenderer::Impl::uploaded_state(const HalfedgeMesh& source) {
  mesh = &source;
  version = source.version();
  uploaded_key = MeshKey::of(source);
  uploaded = true;
  pick_valid = false;
  ++geometry;
  stats.triangles = slots.counts.triangles;
  stats.edges = slots.counts.edges;
  stats.boundary_edges = slots.boundary_edges.size();
  stats.vertices = slots.counts.vertices;
  stats.skipped_faces = slots.counts.skipped_faces;
  stats.skipped_edges = slots.counts.skipped_edges;
  count_gpu_bytes();
}

bool MeshRenderer::Impl::patch(const HalfedgeMesh& source, const MeshChange& change) {
  if (change.before != nullptr) return patch_from(*change.before, change.before->version(), source, change);
  // The patch ends in `source` when its version is the change's version after (the document's patches do).
  if (change.patch != nullptr) {
    return patch_from(StateBefore(source, *change.patch), change.version_before, source, change);
  }
  return false;
}

template <class Before>
bool MeshRenderer::Impl::patch_from(const Before& before, uint64_t before_version, const HalfedgeMesh& source,
                                    const MeshChange& change) {
  // The change must start from exactly the state the buffers show and end at the mesh given.
  if (!uploaded || mesh != &source || version != change.version_before || before_version != change.version_before ||
      source.version() != change.version_after || !(MeshKey::sizes_of(before) == uploaded_key.sizes)) {
    return false;
  }
  const size_t sent = gl::uploaded_bytes();
  const bool with_arrows = arrows_geometry == geometry;
  std::string why;
  const std::optional<SlotPatch> p = plan_update(before, source, change.elements, slots, with_arrows, why);
  if (!p || !gpu.fits(*p) || (with_arrows && !gpu.arrows_fit(*p))) {
    upload(source, p ? "the mesh outgrew its buffers" : why);
    return true;
  }
  gpu.apply(*p);
  if (with_arrows) gpu.apply_arrows(*p);
  uploaded_state(source);
  if (with_arrows) arrows_geometry = geometry;
  ++stats.patches;
  stats.last_update_patch = true;
  stats.last_update_bytes = gl::uploaded_bytes() - sent;
  stats.last_update_slots = p->slots();
  return true;
}

// ---- highlights ------------------------------------------------------------------------------------

void MeshRenderer::Impl::refresh_changed(std::span<const ElementRef> list, uint64_t key) {
  const bool same_list =
      key != 0 ? key == changed_key : std::equal(list.begin(), list.end(), changed_list.begin(), changed_list.end());
  if (changed_geometry == geometry && same_list) return;
  const std::array<uint32_t, kKindSlots> capacity = {mesh->vertex_capacity(), mesh->halfedge_capacity(),
                                                     mesh->edge_capacity(), mesh->face_capacity()};
  // Flags: the previous list's cleared, the new list's set, and only those bytes sent, unless a kind outgrew
  // its allocation (then that kind is sent whole, with room to grow).
  std::array<std::vector<uint32_t>, kKindSlots> touched;
  for (const ElementRef& ref : changed_list) {
    const int slot = slot_of(ref.kind);
    if (slot >= 0 && ref.valid() && ref.index < changed_flags[slot].size()) {
      changed_flags[slot][ref.index] = 0;
      touched[slot].push_back(ref.index);
    }
  }
  std::array<bool, kKindSlots> reallocate{};
  for (int k = 0; k < kKindSlots; ++k) {
    if (changed_flags[k].size() < capacity[k] || changed_flags[k].empty()) {
      changed_flags[k].resize(gl::with_headroom(capacity[k]), 0);
      reallocate[k] = true;
    }
  }
  ItemLists items;
  for (ElementRef ref : list) {
    const int slot = slot_of(ref.kind);
    if (slot < 0 || !ref.valid() || ref.index >= capacity[slot]) continue;
    changed_flags[slot][ref.index] = 1;
    touched[slot].push_back(ref.index);
    items.add(*mesh, ref);
  }
  for (int k = 0; k < kKindSlots; ++k) {
    if (reallocate[k]) {
      changed[k].allocate(changed_flags[k].size(), changed_flags[k].data(), changed_flags[k].size());
      continue;
    }
    std::sort(touched[k].begin(), touched[k].end());
    touched[k].erase(std::unique(touched[k].begin(), touched[k].end()), touched[k].end());
    for (size_t i = 0; i < touched[k].size();) {
      size_t j = i + 1;
      while (j < touched[k].size() && touched[k][j] == touched[k][i] + (j - i)) ++j;
      changed[k].write(touched[k][i], &changed_flags[k][touched[k][i]], j - i);
      i = j;
    }
  }
  changed_edges.upload(items.edges.data(), items.edges.size(), GL_DYNAMIC_DRAW);
  changed_arrows.upload(items.arrows.data(), items.arrows.size(), GL_DYNAMIC_DRAW);
  changed_points.upload(items.points.data(), items.points.size(), GL_DYNAMIC_DRAW);
  changed_list.assign(list.begin(), list.end());
  changed_key = key;
  changed_geometry = geometry;
  ++stats.highlight_uploads;
  count_gpu_bytes();
}

void MeshRenderer::Impl::refresh_focus(ElementRef hovered, ElementRef selected) {
  if (focus_geometry == geometry && hovered == focus_hovered && selected == focus_selected) return;
  ItemLists items;
  items.add(*mesh, hovered);
  if (selected != hovered) items.add(*mesh, selected);
  focus_edges.upload(items.edges.data(), items.edges.size(), GL_STREAM_DRAW);
  focus_arrows.upload(items.arrows.data(), items.arrows.size(), GL_STREAM_DRAW);
  focus_points.upload(items.points.data(), items.points.size(), GL_STREAM_DRAW);
  focus_hovered = hovered;
  focus_selected = selected;
  focus_geometry = geometry;
  ++stats.highlight_uploads;
}

void MeshRenderer::Impl::ensure_arrows() {
  if (arrows_geometry == geometry) return;
  arrows_geometry = geometry;
  // Three segments of two texels per halfedge slot; past the driver's limit (22 million halfedges on
  // llvmpipe) there are no arrows, which would be unreadable at that size anyway.
  if (6 * gl::with_headroom(mesh->halfedge_capacity()) > buffer_texel_cap()) {
    gpu.arrows.set_count(0);
    stats.arrows = 0;
    arrows_geometry = ~uint64_t(0);
    return;
  }
  gpu.upload_arrows(build_slot_arrows(*mesh));
  stats.arrows = mesh->halfedge_capacity();
  ++stats.arrow_uploads;
  pick_valid = false;
  count_gpu_bytes();
}

void MeshRenderer::Impl::count_gpu_bytes() {
  size_t total = gpu.bytes();
  for (const auto& flags : changed) total += flags.bytes();
  for (const gl::SegmentBatch* b : {&changed_edges, &changed_arrows}) total += b->bytes();
  total += changed_points.bytes();
  stats.gpu_bytes = total;
}

// ---- drawing ---------------------------------------------------------------------------------------

PickKey MeshRenderer::Impl::pick_key_for(const OrbitCamera& camera, Viewport viewport) const {
  PickKey key;
  key.mesh = mesh;
  key.version = version;
  key.view_projection = camera.view_projection(viewport);
  key.width = viewport.width;
  key.height = viewport.height;
  key.halfedges = last_options.show_halfedges;
  key.faces_only = pick_faces_only();
  key.front_only = front_only(last_options);
  return key;
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
  gpu.face_normals.bind(1);
  changed[kFaceSlot].bind(2);
  glUniform1i(face.uniform("u_face_normals"), 1);
  glUniform1i(face.uniform("u_changed"), 2);
  draw_triangles(gpu, face, front_only(options));
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
    gpu.edges.draw_lines();
    glUniform1i(segment.uniform("u_lines"), 0);
  } else if (options.wireframe) {
    gpu.edges.draw();
  }
  if (options.show_boundary && (!options.wireframe || hairlines)) gpu.boundary_edges.draw();
  changed_edges.draw();
  focus_edges.draw();

  // Halfedge arrows.
  set_colour(segment, "u_base_colour", style.arrow);
  glUniform1f(segment.uniform("u_base_width"), style.arrow_width);
  glUniform1i(segment.uniform("u_show_boundary"), 0);
  glUniform1ui(segment.uniform("u_selected"), id_if(highlights.selected, ElementKind::Halfedge));
  glUniform1ui(segment.uniform("u_hovered"), id_if(highlights.hovered, ElementKind::Halfedge));
  changed[kHalfedgeSlot].bind(0);
  if (options.show_halfedges) gpu.arrows.draw();
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
  glUniform1i(point.uniform("u_hide_invalid"), 1);
  if (options.show_vertices) gpu.points.draw();
  changed_points.draw();
  focus_points.draw();
}

void MeshRenderer::Impl::draw_ids(const gl::CameraUniforms& uniforms, bool halfedges, bool faces_only) const {
  face_pick.use();
  gl::set_camera(face_pick, uniforms);
  glUniform1ui(face_pick.uniform("u_kind_bits"), pick_kind_bits(ElementKind::Face));
  draw_triangles(gpu, face_pick, front_only(last_options));
  if (faces_only) return;

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
  gpu.edges.draw_lines();
  if (halfedges) {
    glUniform1ui(segment_pick.uniform("u_kind_bits"), pick_kind_bits(ElementKind::Halfedge));
    gpu.arrows.draw_lines();
  }
  glDepthMask(GL_TRUE);

  point_pick.use();
  gl::set_camera(point_pick, uniforms);
  glUniform1i(point_pick.uniform("u_element_colours"), 0);
  glUniform1f(point_pick.uniform("u_pick_size"), 1.0f);  // one pixel each: dots would cover neighbours
  glUniform1ui(point_pick.uniform("u_kind_bits"), pick_kind_bits(ElementKind::Vertex));
  glUniform1i(point_pick.uniform("u_hide_invalid"), 1);
  gpu.points.draw();
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

// ---- MeshRenderer ----------------------------------------------------------------------------------

MeshRenderer::MeshRenderer(const ShaderLibrary& shaders) : impl_(std::make_unique<Impl>(shaders)) {}

MeshRenderer::~MeshRenderer() = default;

void MeshRenderer::update(const HalfedgeMesh& mesh, const MeshChange* change) {
  Impl& r = *impl_;
  if (r.uploaded && r.uploaded_key == MeshKey::of(mesh)) return;
  if (change != nullptr && r.patch(mesh, *change)) return;
  r.upload(mesh, !r.uploaded ? "first upload" : change == nullptr ? "no change description" : "another mesh state");
}

void MeshRenderer::update_with_normals(const HalfedgeMesh& mesh, std::span<const glm::vec3> smooth_normals) {
  impl_->upload(mesh, "normals given", smooth_normals);
}

void MeshRenderer::draw(const OrbitCamera& camera, Viewport viewport, const ViewOptions& options,
                        const Highlights& highlights) {
  Impl& r = *impl_;
  r.last_options = options;
  if (!r.uploaded || viewport.width < 1 || viewport.height < 1) return;
  r.refresh_changed(highlights.changed, highlights.changed_key);
  r.refresh_focus(highlights.hovered, highlights.selected);
  if (options.show_halfedges) r.ensure_arrows();

  const gl::CameraUniforms uniforms = gl::camera_uniforms(camera, viewport);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LEQUAL);
  glDepthMask(GL_TRUE);
  glDisable(GL_CULL_FACE);
  gl::enable_program_point_size();
  // Drawn single-sampled into a multisampled framebuffer when the options say so (and the GL can switch).
  const bool multisample = gl::multisample_on();
  const bool single_sample = multisample && !options.multisampling && gl::kCanSwitchMultisample;
  glGetIntegerv(GL_SAMPLES, &r.stats.framebuffer_samples);
  if (single_sample) gl::set_multisample(false);
  r.draw_faces(uniforms, camera, options, highlights);
  r.draw_lines_and_points(uniforms, options, highlights);
  if (single_sample) gl::set_multisample(true);
  r.stats.multisampled = multisample && !single_sample;
  glBindVertexArray(0);
  glUseProgram(0);
}

ElementRef MeshRenderer::pick(const OrbitCamera& camera, Viewport viewport, int x, int y) {
  Impl& r = *impl_;
  if (!r.uploaded || x < 0 || y < 0 || x >= viewport.width || y >= viewport.height) return ElementRef();
  const bool halfedges = r.last_options.show_halfedges;
  const bool faces_only = r.pick_faces_only();
  if (halfedges && !faces_only) r.ensure_arrows();

  gl::FramebufferScope restore;
  r.ensure_pick_target(viewport);
  const PickKey key = r.pick_key_for(camera, viewport);
  glBindFramebuffer(GL_FRAMEBUFFER, r.pick_framebuffer.get());
  if (!r.pick_valid || !(key == r.pick_key)) {
    const auto start = std::chrono::steady_clock::now();
    glViewport(0, 0, viewport.width, viewport.height);
    const GLuint background[4] = {0, 0, 0, 0};
    const GLfloat far_depth = 1.0f;
    glDepthMask(GL_TRUE);
    glClearBufferuiv(GL_COLOR, 0, background);
    glClearBufferfv(GL_DEPTH, 0, &far_depth);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);
    glDisable(GL_CULL_FACE);
    gl::enable_program_point_size();
    r.draw_ids(gl::camera_uniforms(camera, viewport), halfedges, faces_only);
    glBindVertexArray(0);
    glUseProgram(0);
    r.pick_key = key;
    r.pick_valid = true;
    ++r.stats.id_passes;
    r.stats.last_id_pass_faces_only = faces_only;
    glFinish();  // so the time below is the pass's, not the next read's
    r.stats.last_id_pass_ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
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
  if (faces_only) {
    return pick_from_faces(*r.mesh, camera, viewport, PickWindow{top_down, w, h, x0, y0}, x, y, halfedges);
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

bool MeshRenderer::pick_is_cheap(const OrbitCamera& camera, Viewport viewport) const {
  const Impl& r = *impl_;
  return !r.uploaded || (r.pick_valid && r.pick_size.width == viewport.width && r.pick_size.height == viewport.height &&
                         r.pick_key_for(camera, viewport) == r.pick_key);
}

void MeshRenderer::read_gpu_buffers(SlotGeometry& out, std::vector<EdgeSegment>& arrows) const {
  const Impl& r = *impl_;
  const bool with_arrows = r.arrows_geometry == r.geometry;
  r.gpu.read(out, with_arrows ? &arrows : nullptr);
  if (!with_arrows) arrows.clear();
  out.counts = r.slots.counts;
  out.bounds = r.slots.bounds;
}

void MeshRenderer::invalidate() { impl_->uploaded = false; }

const BoundingBox& MeshRenderer::bounds() const { return impl_->slots.bounds; }
const RenderStats& MeshRenderer::stats() const { return impl_->stats; }
RenderStyle& MeshRenderer::style() { return impl_->style; }

}  // namespace meshedit
