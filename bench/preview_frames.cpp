// Frame time of the OpenGL preview on this machine's OpenGL (llvmpipe here), issue 23:
//   build/bench/phellem_bench_preview SCENE.json WxH [FRAMES] [EDGE_PX] [tints]
// Draws FRAMES frames (default 15) after 3 warm-up frames (llvmpipe compiles shader variants
// on first use) and prints the median wall time per frame (glFinish'ed, not read back: a
// window's cost) and the triangles a frame. Stress bark's per-plate tints are off (as the
// window starts) unless the fifth argument is "tints". Then Mesa's own ceiling in the same run: a plain mesh of the same triangle count
// drawn without tessellation by a trivial shader, so the ratio says what tessellation and the
// bark's displacement cost over drawing that many triangles at all.
#include <epoxy/gl.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <string>
#include <vector>

#include "preview/gl_context.h"
#include "preview/preview_renderer.h"
#include "preview/preview_scene.h"
#include "scene/bark_results.h"
#include "scene/camera_model.h"
#include "scene/scene_parser.h"
#include "util/errors.h"

using namespace phellem;
using Clock = std::chrono::steady_clock;

namespace {

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

GLuint plain_program() {
  const char* vs = "#version 450 core\nlayout(location=0) in vec3 p; uniform mat4 mvp; out vec3 c;\n"
                   "void main() { c = p; gl_Position = mvp * vec4(p, 1.0); }\n";
  const char* fs = "#version 450 core\nin vec3 c; out vec4 o; void main() { o = vec4(fract(c * 10.0), 1.0); }\n";
  GLuint prog = glCreateProgram();
  for (auto [type, src] : {std::pair{GL_VERTEX_SHADER, vs}, std::pair{GL_FRAGMENT_SHADER, fs}}) {
    GLuint s = glCreateShader(type);
    glShaderSource(s, 1, &src, nullptr);
    glCompileShader(s);
    glAttachShader(prog, s);
    glDeleteShader(s);
  }
  glLinkProgram(prog);
  return prog;
}

// A sheet of about `triangles` triangles facing the camera and filling the frame.
double mesa_ceiling_ms(const CameraModel& cam, long long triangles, int frames) {
  const int n = std::max(1, int(std::sqrt(double(triangles) / 2)));
  std::vector<Vec3f> pos;
  std::vector<uint32_t> idx;
  const Vec3f centre = cam.position() + cam.forward();
  const float half = cam.tan_half_fov() * 1.2f;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i)
      pos.push_back(centre + cam.right() * (half * (2.0f * float(i) / float(n) - 1.0f) * float(cam.width()) / float(cam.height())) +
                    cam.up() * (half * (2.0f * float(j) / float(n) - 1.0f)));
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const uint32_t a = uint32_t(j * (n + 1) + i), b = a + 1, c = a + uint32_t(n) + 1, d = c + 1;
      idx.insert(idx.end(), {a, b, d, a, d, c});
    }
  GLuint vao, vbo, ibo, fbo, color, depth;
  glCreateVertexArrays(1, &vao);
  glCreateBuffers(1, &vbo);
  glNamedBufferStorage(vbo, GLsizeiptr(pos.size() * sizeof(Vec3f)), pos.data(), 0);
  glCreateBuffers(1, &ibo);
  glNamedBufferStorage(ibo, GLsizeiptr(idx.size() * 4), idx.data(), 0);
  glVertexArrayVertexBuffer(vao, 0, vbo, 0, sizeof(Vec3f));
  glVertexArrayAttribFormat(vao, 0, 3, GL_FLOAT, GL_FALSE, 0);
  glVertexArrayAttribBinding(vao, 0, 0);
  glEnableVertexArrayAttrib(vao, 0);
  glVertexArrayElementBuffer(vao, ibo);
  glCreateTextures(GL_TEXTURE_2D, 1, &color);
  glTextureStorage2D(color, 1, GL_RGBA8, cam.width(), cam.height());
  glCreateTextures(GL_TEXTURE_2D, 1, &depth);
  glTextureStorage2D(depth, 1, GL_DEPTH_COMPONENT32F, cam.width(), cam.height());
  glCreateFramebuffers(1, &fbo);
  glNamedFramebufferTexture(fbo, GL_COLOR_ATTACHMENT0, color, 0);
  glNamedFramebufferTexture(fbo, GL_DEPTH_ATTACHMENT, depth, 0);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo);
  glViewport(0, 0, cam.width(), cam.height());
  const GLuint prog = plain_program();
  glUseProgram(prog);
  const Eigen::Matrix4f mvp = cam.projection(0.01f, 100.0f) * cam.view();
  glUniformMatrix4fv(glGetUniformLocation(prog, "mvp"), 1, GL_FALSE, mvp.data());
  glEnable(GL_DEPTH_TEST);
  glBindVertexArray(vao);
  std::vector<double> ms;
  for (int f = 0; f < frames + 3; ++f) {
    const auto t0 = Clock::now();
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glDrawElements(GL_TRIANGLES, GLsizei(idx.size()), GL_UNSIGNED_INT, nullptr);
    glFinish();
    if (f >= 3) ms.push_back(std::chrono::duration<double, std::milli>(Clock::now() - t0).count());
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glDeleteProgram(prog);
  glDeleteFramebuffers(1, &fbo);
  const GLuint tex[2] = {color, depth};
  glDeleteTextures(2, tex);
  glDeleteBuffers(1, &vbo);
  glDeleteBuffers(1, &ibo);
  glDeleteVertexArrays(1, &vao);
  return median(ms);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: %s SCENE.json WxH [FRAMES] [EDGE_PX] [tints]\n", argv[0]);
    return 2;
  }
  try {
    const std::string res = argv[2];
    const int w = std::stoi(res.substr(0, res.find('x'))), h = std::stoi(res.substr(res.find('x') + 1));
    const int frames = argc > 3 ? std::stoi(argv[3]) : 15;
    std::string why;
    auto gl = preview::HeadlessGl::create(&why);
    if (!gl) {
      std::fprintf(stderr, "no OpenGL 4.5: %s\n", why.c_str());
      return 1;
    }
    const SceneDesc desc = load_scene_file(argv[1]);
    const BarkResults bark = simulate_bark(desc, false);
    const preview::PreviewScene scene = preview::build_preview_scene(desc, bark);
    preview::PreviewRenderer renderer(scene);
    preview::PreviewSettings s;
    s.tints = argc > 5 && std::string(argv[5]) == "tints";
    if (argc > 4) {
      const float e = std::stof(argv[4]);
      s.target_far_px *= e / s.target_near_px;
      s.target_near_px = e;
    }
    const CameraModel cam(desc.camera, w, h);
    std::vector<double> ms;
    long long tris = 0;
    for (int f = 0; f < frames + 3; ++f) {
      const auto t0 = Clock::now();
      tris = renderer.draw_offscreen(cam, s);
      if (f >= 3) ms.push_back(std::chrono::duration<double, std::milli>(Clock::now() - t0).count());
    }
    const double frame = median(ms), ceiling = mesa_ceiling_ms(cam, tris, frames);
    std::printf("%s %dx%d%s: %.1f ms a frame (median of %d), %lld triangles, %.2f Mtri/s; plain mesh of as many: %.1f ms, %.2f Mtri/s; ratio %.2f\n",
                argv[1], w, h, s.tints ? " (tints)" : "", frame, frames, tris, double(tris) / frame * 1e-3, ceiling, double(tris) / ceiling * 1e-3,
                frame / ceiling);
  } catch (const UserError& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 2;
  }
  return 0;
}
