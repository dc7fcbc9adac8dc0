#include "preview/preview_renderer.h"

#include "preview/shaders.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace phellem::preview {

namespace {

template <class T>
GLuint buffer(GLenum target, const std::vector<T>& data) {
  GLuint b = 0;
  glCreateBuffers(1, &b);
  glNamedBufferStorage(b, GLsizeiptr(std::max<size_t>(1, data.size()) * sizeof(T)), data.empty() ? nullptr : data.data(), 0);
  (void)target;
  return b;
}

}  // namespace

PreviewRenderer::PreviewRenderer(const PreviewScene& scene) : scene_(scene) {
  for (const auto& o : scene.objects) {  // compiled up front, not mid-frame
    program_for(o, true);
    program_for(o, false);
  }
  background_ = GlProgram::screen("background.frag");
  overlay_ = GlProgram::screen("overlay.frag");
  glCreateVertexArrays(1, &empty_vao_);
  if (const auto& e = scene.environment) {
    glCreateTextures(GL_TEXTURE_2D, 1, &environment_);
    const int levels = 1 + int(std::floor(std::log2(double(std::max(e->width, e->height)))));
    glTextureStorage2D(environment_, levels, GL_RGB32F, e->width, e->height);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTextureSubImage2D(environment_, 0, 0, 0, e->width, e->height, GL_RGB, GL_FLOAT, e->rgb.data());
    glGenerateTextureMipmap(environment_);
    glTextureParameteri(environment_, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTextureParameteri(environment_, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTextureParameteri(environment_, GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTextureParameteri(environment_, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  }
  // Near and far planes from the scene's extent (the depth buffer only orders fragments; the
  // distance AOV is exact).
  float extent = 1;
  for (const auto& o : scene.objects)
    for (const auto& p : o.positions) extent = std::max(extent, (o.model.topLeftCorner<3, 3>() * p + o.model.topRightCorner<3, 1>()).norm());
  far_ = 4 * extent + 100;
  near_ = 0.002f;
  for (const auto& o : scene.objects) {
    GpuMesh m;
    glCreateVertexArrays(1, &m.vao);
    m.vbo[0] = buffer(GL_ARRAY_BUFFER, o.positions);
    m.vbo[1] = buffer(GL_ARRAY_BUFFER, o.normals);
    m.vbo[2] = buffer(GL_ARRAY_BUFFER, o.params);
    m.vbo[3] = buffer(GL_ARRAY_BUFFER, o.crack_near);
    m.vbo[4] = buffer(GL_ARRAY_BUFFER, o.texcoords.size() == o.positions.size() ? o.texcoords
                                                                                : std::vector<Vec2f>(o.positions.size(), Vec2f::Zero()));
    m.ibo = buffer(GL_ELEMENT_ARRAY_BUFFER, o.indices);
    const GLint sizes[5] = {3, 3, 2, 1, 2};
    const GLsizei strides[5] = {sizeof(Vec3f), sizeof(Vec3f), sizeof(Vec2f), sizeof(float), sizeof(Vec2f)};
    for (GLuint a = 0; a < 5; ++a) {
      glVertexArrayVertexBuffer(m.vao, a, m.vbo[a], 0, strides[a]);
      glVertexArrayAttribFormat(m.vao, a, sizes[a], GL_FLOAT, GL_FALSE, 0);
      glVertexArrayAttribBinding(m.vao, a, a);
      glEnableVertexArrayAttrib(m.vao, a);
    }
    glVertexArrayElementBuffer(m.vao, m.ibo);
    m.count = GLsizei(o.indices.size());
    if (o.cracks) {
      m.ssbo[0] = buffer(GL_SHADER_STORAGE_BUFFER, o.cracks->segments);
      m.ssbo[1] = buffer(GL_SHADER_STORAGE_BUFFER, o.cracks->cell_start);
      m.ssbo[2] = buffer(GL_SHADER_STORAGE_BUFFER, o.cracks->items);
    }
    if (o.field) {
      glCreateTextures(GL_TEXTURE_2D, 2, m.tex);
      glTextureStorage2D(m.tex[0], 1, GL_RG32F, o.field->width, o.field->height);
      glTextureSubImage2D(m.tex[0], 0, 0, 0, o.field->width, o.field->height, GL_RG, GL_FLOAT, o.field->depth_mask.data());
      glTextureStorage2D(m.tex[1], 1, GL_RGBA32F, o.field->width, o.field->height);
      glTextureSubImage2D(m.tex[1], 0, 0, 0, o.field->width, o.field->height, GL_RGBA, GL_FLOAT, o.field->albedo.data());
    }
    if (o.image) {  // the map's values as they are stored: texel (i, j) is value[j × width + i], row 0 at the top
      const DisplacementMap& d = *o.image->map;
      glCreateTextures(GL_TEXTURE_2D, 1, &m.image);
      glTextureStorage2D(m.image, 1, GL_R32F, d.width, d.height);
      glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
      glTextureSubImage2D(m.image, 0, 0, 0, d.width, d.height, GL_RED, GL_FLOAT, d.value.data());
      m.image_reach = o.image->reach();
    }
    meshes_.push_back(m);
  }
}

PreviewRenderer::~PreviewRenderer() {
  for (auto& m : meshes_) {
    glDeleteVertexArrays(1, &m.vao);
    glDeleteBuffers(5, m.vbo);
    glDeleteBuffers(1, &m.ibo);
    glDeleteBuffers(3, m.ssbo);
    glDeleteTextures(2, m.tex);
    if (m.image) glDeleteTextures(1, &m.image);
  }
  if (environment_) glDeleteTextures(1, &environment_);
  glDeleteVertexArrays(1, &empty_vao_);
  release_targets();
}

void PreviewRenderer::release_targets() {
  if (fbo_) glDeleteFramebuffers(1, &fbo_);
  const GLuint t[3] = {color_, aov_, depth_};
  glDeleteTextures(3, t);
  fbo_ = color_ = aov_ = depth_ = 0;
}

void PreviewRenderer::ensure_targets(int width, int height) {
  if (fbo_ && width == width_ && height == height_) return;
  release_targets();
  width_ = width;
  height_ = height;
  glCreateTextures(GL_TEXTURE_2D, 1, &color_);
  glTextureStorage2D(color_, 1, GL_RGBA8, width, height);
  glCreateTextures(GL_TEXTURE_2D, 1, &aov_);
  glTextureStorage2D(aov_, 1, GL_RGBA32F, width, height);
  glCreateTextures(GL_TEXTURE_2D, 1, &depth_);
  glTextureStorage2D(depth_, 1, GL_DEPTH_COMPONENT32F, width, height);
  glCreateFramebuffers(1, &fbo_);
  glNamedFramebufferTexture(fbo_, GL_COLOR_ATTACHMENT0, color_, 0);
  glNamedFramebufferTexture(fbo_, GL_COLOR_ATTACHMENT1, aov_, 0);
  glNamedFramebufferTexture(fbo_, GL_DEPTH_ATTACHMENT, depth_, 0);
  const GLenum draw[2] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
  glNamedFramebufferDrawBuffers(fbo_, 2, draw);
  if (glCheckNamedFramebufferStatus(fbo_, GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
    throw std::runtime_error("the preview's framebuffer is incomplete");
}

void PreviewRenderer::set_uniforms(const GlProgram& p, const CameraModel& camera, const PreviewSettings& s) const {
  p.set("view_projection", Eigen::Matrix4f(camera.projection(near_, far_) * camera.view()));
  p.set("viewport", Vec2f(float(camera.width()), float(camera.height())));
  p.set("target_near_px", s.target_near_px);
  p.set("target_far_px", s.target_far_px);
  p.set("max_level", float(s.max_level));
  p.set("asymmetric_levels", s.asymmetric_levels ? 1 : 0);
  p.set("cull_patches", s.cull ? 1 : 0);
  p.set("camera_position", camera.position());
  p.set("show_mask", s.show_mask ? 1 : 0);
  p.set("show_darkening", s.darkening ? 1 : 0);
  p.set("sun_direction", scene_.sun_direction);
  p.set("sun_color", scene_.sun_color);
  p.set("sky_color", scene_.sky_color);
  p.set("ground_color", scene_.ground_color);
  p.set("field_depth_mask", 0);
  p.set("field_albedo", 1);
  p.set("displacement_map", 3);
}

void PreviewRenderer::bind_object(const GlProgram& p, size_t k) const {
  const PreviewObject& o = scene_.objects[k];
  const GpuMesh& m = meshes_[k];
  p.set("model", Eigen::Matrix4f(o.model));
  p.set("inverse_model", Eigen::Matrix4f(o.model.inverse()));
  if (!o.cracks) {
    p.set("ridge_tint_count", 0);
    p.set("fissure_tint_count", 0);
  }
  p.set("curved_patches", o.curved ? 1 : 0);
  p.set("base_color", o.base_color);
  if (o.cracks) {
    const GpuCracks& c = *o.cracks;
    for (GLuint b = 0; b < 3; ++b) glBindBufferBase(GL_SHADER_STORAGE_BUFFER, b, m.ssbo[b]);
    p.set("crack_grid_origin", c.origin);
    p.set("crack_grid_cell", c.cell);
    p.set("crack_grid_dims", c.dims);
    p.set("crack_seed", c.seed);
    p.set("crack_noise", c.look.noise);
    p.set("crack_wall_noise", c.look.wall_noise);
    p.set("crack_wall_size", c.look.wall_size);
    p.set("crack_max_depth", c.look.max_depth);
    p.set("crack_depth_per_width", c.look.depth_per_width);
    p.set("crack_shoulder", c.look.shoulder);
    p.set("crack_shoulder_width", c.look.shoulder_width);
    p.set("crack_detail", c.look.detail);
    p.set("crack_detail_size", c.look.detail_size);
    p.set("darkening", c.look.darkening);
    p.set("colored", c.look.colored ? 1 : 0);
    p.set("ridge_color", c.look.ridge_color);
    p.set("fissure_color", c.look.fissure_color);
    p.set("ridge_tint_count", int(c.ridge_tints.size()));
    p.set("fissure_tint_count", int(c.fissure_tints.size()));
    if (!c.ridge_tints.empty())
      glProgramUniform3fv(p.id(), p.location("ridge_tints"), GLsizei(c.ridge_tints.size()), c.ridge_tints[0].data());
    if (!c.fissure_tints.empty())
      glProgramUniform3fv(p.id(), p.location("fissure_tints"), GLsizei(c.fissure_tints.size()), c.fissure_tints[0].data());
    p.set("tint_size", c.look.tint_size);
    p.set("tint_seed", c.tint_seed);
  }
  p.set("displacement_reach", m.image_reach);
  if (o.image) {
    glBindTextureUnit(3, m.image);
    p.set("displacement_scale", o.image->scale);
    p.set("displacement_midlevel", o.image->midlevel);
    p.set("displacement_uv_repeat", o.image->uv_repeat);
    p.set("displacement_clamp", o.image->clamp ? 1 : 0);
  }
  if (o.field) {
    glBindTextureUnit(0, m.tex[0]);
    glBindTextureUnit(1, m.tex[1]);
    p.set("field_max_depth", o.field->max_depth);
  }
}

void PreviewRenderer::draw_background(const CameraModel& camera) const {
  const GlProgram& b = *background_;
  b.use();
  const Eigen::Matrix4f vp = camera.projection(near_, far_) * camera.view();
  b.set("inverse_view_projection", Eigen::Matrix4f(vp.inverse()));
  b.set("camera_position", camera.position());
  b.set("has_environment", environment_ ? 1 : 0);
  b.set("sky_color", scene_.sky_color);
  b.set("environment", 2);
  if (const auto& e = scene_.environment) {
    b.set("environment_intensity", e->intensity);
    b.set("environment_rotation", radians(e->rotation_deg));
    glBindTextureUnit(2, environment_);
  }
  glDisable(GL_DEPTH_TEST);
  glDepthMask(GL_FALSE);
  glBindVertexArray(empty_vao_);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glDepthMask(GL_TRUE);
}

void PreviewRenderer::draw_text(const std::string& text, int framebuffer_height, int scale) const {
  static const std::string kChars = "0123456789 .,mstriangledpxkMf|-";
  std::vector<int> glyphs;
  for (char ch : text) {
    const size_t k = kChars.find(ch);
    glyphs.push_back(k == std::string::npos ? 10 : int(k));  // unknown: a space
    if (glyphs.size() == 64) break;
  }
  const GlProgram& o = *overlay_;
  o.use();
  glProgramUniform1iv(o.id(), o.location("overlay_text"), GLsizei(glyphs.size()), glyphs.data());
  o.set("overlay_length", int(glyphs.size()));
  o.set("overlay_scale", std::max(1, scale));
  o.set("overlay_height", framebuffer_height);
  glDisable(GL_DEPTH_TEST);
  glBindVertexArray(empty_vao_);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glEnable(GL_DEPTH_TEST);
}

std::string PreviewRenderer::variant(const PreviewObject& o, bool tints) {
  return bark_defines(int(o.bark), tints && o.cracks && (!o.cracks->ridge_tints.empty() || !o.cracks->fissure_tints.empty()),
                      o.image != nullptr);
}

const GlProgram& PreviewRenderer::program_for(const PreviewObject& o, bool tints) {
  auto& p = programs_[variant(o, tints)];
  if (!p) p = std::make_unique<GlProgram>(variant(o, tints));
  return *p;
}

long long PreviewRenderer::draw(const CameraModel& camera, const PreviewSettings& s) {
  draw_background(camera);
  for (const auto& [defines, p] : programs_) set_uniforms(*p, camera, s);
  glPatchParameteri(GL_PATCH_VERTICES, 3);
  glEnable(GL_DEPTH_TEST);
  glPolygonMode(GL_FRONT_AND_BACK, s.wireframe ? GL_LINE : GL_FILL);
  GLuint query = 0;
  glCreateQueries(GL_PRIMITIVES_GENERATED, 1, &query);
  glBeginQuery(GL_PRIMITIVES_GENERATED, query);
  const Eigen::Matrix4f vp = camera.projection(near_, far_) * camera.view();
  for (size_t k = 0; k < meshes_.size(); ++k) {
    const GlProgram& p = program_for(scene_.objects[k], s.tints);
    p.use();
    bind_object(p, k);
    p.set("model_view_projection", Eigen::Matrix4f(vp * scene_.objects[k].model));
    glBindVertexArray(meshes_[k].vao);
    glDrawElements(GL_PATCHES, meshes_[k].count, GL_UNSIGNED_INT, nullptr);
  }
  glEndQuery(GL_PRIMITIVES_GENERATED);
  if (!s.overlay.empty()) draw_text(s.overlay, camera.height(), std::max(1, camera.height() / 360));
  GLuint64 primitives = 0;
  glGetQueryObjectui64v(query, GL_QUERY_RESULT, &primitives);
  glDeleteQueries(1, &query);
  glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
  return (long long)primitives;
}

void PreviewRenderer::clear_offscreen(int w, int h) {
  ensure_targets(w, h);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
  glViewport(0, 0, w, h);
  const float sky[4] = {scene_.sky_color.x(), scene_.sky_color.y(), scene_.sky_color.z(), 1};
  const float none[4] = {0, 0, std::numeric_limits<float>::infinity(), 0};
  glClearNamedFramebufferfv(fbo_, GL_COLOR, 0, sky);
  glClearNamedFramebufferfv(fbo_, GL_COLOR, 1, none);
  glClearNamedFramebufferfi(fbo_, GL_DEPTH_STENCIL, 0, 1.0f, 0);
}

long long PreviewRenderer::draw_offscreen(const CameraModel& camera, const PreviewSettings& s) {
  clear_offscreen(camera.width(), camera.height());
  // Colour only, as a window draws: the AOV target is not written.
  const GLenum colour_only[2] = {GL_COLOR_ATTACHMENT0, GL_NONE};
  glNamedFramebufferDrawBuffers(fbo_, 2, colour_only);
  const long long n = draw(camera, s);
  glFinish();
  const GLenum both[2] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
  glNamedFramebufferDrawBuffers(fbo_, 2, both);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  return n;
}

PreviewFrame PreviewRenderer::render(const CameraModel& camera, const PreviewSettings& s) {
  const int w = camera.width(), h = camera.height();
  clear_offscreen(w, h);
  GLuint timer = 0;
  glCreateQueries(GL_TIME_ELAPSED, 1, &timer);
  glBeginQuery(GL_TIME_ELAPSED, timer);
  PreviewFrame f;
  f.primitives = draw(camera, s);
  glEndQuery(GL_TIME_ELAPSED);
  GLuint64 ns = 0;
  glGetQueryObjectui64v(timer, GL_QUERY_RESULT, &ns);
  glDeleteQueries(1, &timer);
  f.milliseconds = double(ns) * 1e-6;
  f.width = w;
  f.height = h;
  const size_t n = size_t(w) * size_t(h);
  std::vector<uint8_t> rgba(4 * n);
  std::vector<float> aov(4 * n);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glGetTextureImage(color_, 0, GL_RGBA, GL_UNSIGNED_BYTE, GLsizei(rgba.size()), rgba.data());
  glGetTextureImage(aov_, 0, GL_RGBA, GL_FLOAT, GLsizei(aov.size() * sizeof(float)), aov.data());
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  // GL's rows run bottom-up: flip to the path tracer's top-down rows.
  f.rgba.resize(4 * n);
  f.mask.resize(n);
  f.crack_depth.resize(n);
  f.distance.resize(n);
  for (int y = 0; y < h; ++y) {
    const size_t src = size_t(h - 1 - y) * size_t(w), dst = size_t(y) * size_t(w);
    std::copy_n(&rgba[4 * src], 4 * size_t(w), &f.rgba[4 * dst]);
    for (int x = 0; x < w; ++x) {
      const float* a = &aov[4 * (src + size_t(x))];
      f.mask[dst + size_t(x)] = a[0];
      f.crack_depth[dst + size_t(x)] = a[1];
      f.distance[dst + size_t(x)] = a[3] > 0 ? a[2] : std::numeric_limits<float>::infinity();
    }
  }
  return f;
}

PreviewRenderer::Feedback PreviewRenderer::capture(size_t k, const CameraModel& camera, const PreviewSettings& s) {
  GlProgram p(variant(scene_.objects[k], s.tints), {"te_base", "te_world", "te_normal", "te_texcoord", "te_param"});
  // A surfaceless context has no default framebuffer: draw into ours (nothing is rasterized).
  ensure_targets(camera.width(), camera.height());
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
  p.use();
  set_uniforms(p, camera, s);
  bind_object(p, k);
  const Eigen::Matrix4f vp = camera.projection(near_, far_) * camera.view();
  p.set("model_view_projection", Eigen::Matrix4f(vp * scene_.objects[k].model));
  // First count the vertices, then capture them.
  GLuint query = 0;
  glCreateQueries(GL_PRIMITIVES_GENERATED, 1, &query);
  glEnable(GL_RASTERIZER_DISCARD);
  glPatchParameteri(GL_PATCH_VERTICES, 3);
  glBindVertexArray(meshes_[k].vao);
  glBeginQuery(GL_PRIMITIVES_GENERATED, query);
  glDrawElements(GL_PATCHES, meshes_[k].count, GL_UNSIGNED_INT, nullptr);
  glEndQuery(GL_PRIMITIVES_GENERATED);
  GLuint64 prims = 0;
  glGetQueryObjectui64v(query, GL_QUERY_RESULT, &prims);
  glDeleteQueries(1, &query);
  constexpr size_t kFloats = 3 + 3 + 3 + 2 + 2;  // a vertex's varyings, interleaved
  const size_t floats = size_t(prims) * 3 * kFloats;
  GLuint tfb = 0;
  glCreateBuffers(1, &tfb);
  glNamedBufferStorage(tfb, GLsizeiptr(std::max<size_t>(1, floats) * sizeof(float)), nullptr, GL_MAP_READ_BIT);
  glBindBufferBase(GL_TRANSFORM_FEEDBACK_BUFFER, 0, tfb);
  glBeginTransformFeedback(GL_TRIANGLES);
  glDrawElements(GL_PATCHES, meshes_[k].count, GL_UNSIGNED_INT, nullptr);
  glEndTransformFeedback();
  glDisable(GL_RASTERIZER_DISCARD);
  std::vector<float> data(floats);
  if (floats) glGetNamedBufferSubData(tfb, 0, GLsizeiptr(floats * sizeof(float)), data.data());
  glDeleteBuffers(1, &tfb);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  Feedback fb;
  for (size_t v = 0; v + kFloats <= data.size(); v += kFloats) {
    fb.base.emplace_back(data[v], data[v + 1], data[v + 2]);
    fb.displaced.emplace_back(data[v + 3], data[v + 4], data[v + 5]);
    fb.normal.emplace_back(data[v + 6], data[v + 7], data[v + 8]);
    fb.texcoord.emplace_back(data[v + 9], data[v + 10]);
    fb.param.emplace_back(data[v + 11], data[v + 12]);
  }
  return fb;
}

}  // namespace phellem::preview
