#include "io/image_output.h"

#include <OpenColorIO/OpenColorIO.h>
#include <OpenImageIO/imageio.h>

#include <sstream>

#include "io/image_file.h"
#include "util/atomic_file.h"
#include "util/errors.h"
#include "util/math.h"

namespace OCIO = OCIO_NAMESPACE;

namespace phellem {

namespace {

OCIO::ConstConfigRcPtr config() {
  static OCIO::ConstConfigRcPtr cfg = [] {
    std::istringstream in(ocio_config_text());
    return OCIO::Config::CreateFromStream(in);
  }();
  return cfg;
}

}  // namespace

std::vector<std::string> exr_channel_names() {
  return {"beauty.R",   "beauty.G",   "beauty.B",     "beauty.A",   "albedo.R",    "albedo.G",
          "albedo.B",   "normal.X",   "normal.Y",     "normal.Z",   "depth.Z",     "position.X",
          "position.Y", "position.Z", "object_id.id", "crack.mask", "crack.depth", "displacement.D"};
}

void write_exr(const Film& f, const std::string& path, const std::optional<ExrCamera>& camera) {
  const auto names = exr_channel_names();
  const int nc = int(names.size());
  OIIO::ImageSpec spec(f.width, f.height, nc, OIIO::TypeDesc::HALF);
  spec.channelnames = names;
  spec.channelformats.assign(nc, OIIO::TypeDesc::HALF);
  spec.channelformats[14] = OIIO::TypeDesc::FLOAT;  // ids stay exact
  // Positions in metres: half's 2^-11 relative step is half a millimetre at a metre, more than
  // a pixel of bark; compare measures the scale from neighbouring positions.
  for (int c = 11; c < 14; ++c) spec.channelformats[size_t(c)] = OIIO::TypeDesc::FLOAT;
  if (camera) {
    spec.attribute("phellem:camera_position", OIIO::TypeDesc::TypeVector, camera->position.data());
    const Eigen::Matrix4f row_major = camera->world_to_camera;  // Eigen is column-major: its storage is Mᵀ row by row
    spec.attribute("worldToCamera", OIIO::TypeDesc::TypeMatrix44, row_major.data());
  }
  spec.alpha_channel = 3;
  spec.z_channel = 10;
  spec.attribute("compression", "zip");
  spec.attribute("oiio:ColorSpace", "lin_rec709");
  spec.attribute("Software", "Phellem");
  std::vector<float> px(size_t(f.width) * f.height * nc);
  for (size_t p = 0; p < size_t(f.width) * f.height; ++p) {
    float* o = &px[p * nc];
    for (int c = 0; c < 4; ++c) o[c] = f.beauty[p * 4 + c];
    for (int c = 0; c < 3; ++c) o[4 + c] = f.albedo[p * 3 + c];
    for (int c = 0; c < 3; ++c) o[7 + c] = f.normal[p * 3 + c];
    o[10] = f.depth[p];
    for (int c = 0; c < 3; ++c) o[11 + c] = f.position[p * 3 + c];
    o[14] = f.object_id[p];
    o[15] = f.crack[p * 2];
    o[16] = f.crack[p * 2 + 1];
    o[17] = f.displacement[p];
  }
  write_atomically(path, [&](const std::string& tmp) { write_image_file(path, tmp, spec, OIIO::TypeDesc::FLOAT, px.data()); });
}

std::vector<std::string> ocio_views() {
  std::vector<std::string> v;
  auto cfg = config();
  for (int i = 0; i < cfg->getNumViews("sRGB"); ++i) v.emplace_back(cfg->getView("sRGB", i));
  return v;
}

void require_view(const std::string& view) {
  const auto views = ocio_views();
  if (std::find(views.begin(), views.end(), view) != views.end()) return;
  std::string all;
  for (auto& v : views) all += (all.empty() ? "\"" : ", \"") + v + "\"";
  throw UserError("", "--view", "unknown view \"" + view + "\"; allowed: " + all);
}

std::string default_view() { return config()->getDefaultView("sRGB"); }

void apply_display_view(std::vector<float>& rgb, const std::string& view) {
  auto cfg = config();
  auto t = OCIO::DisplayViewTransform::Create();
  t->setSrc("lin_rec709");
  t->setDisplay("sRGB");
  t->setView(view.c_str());
  auto cpu = cfg->getProcessor(t)->getDefaultCPUProcessor();
  OCIO::PackedImageDesc img(rgb.data(), long(rgb.size() / 3), 1, 3);
  cpu->apply(img);
}

void srgb_texture_to_linear(float* px, long count, int channels) {
  auto cpu = config()->getProcessor("sRGB - Texture", "lin_rec709")->getDefaultCPUProcessor();
  if (channels >= 3) {
    OCIO::PackedImageDesc img(px, count, 1, channels);
    cpu->apply(img);
    return;
  }
  std::vector<float> rgb(size_t(count) * 3);
  for (long i = 0; i < count; ++i) rgb[i * 3] = rgb[i * 3 + 1] = rgb[i * 3 + 2] = px[i * channels];
  OCIO::PackedImageDesc img(rgb.data(), count, 1, 3);
  cpu->apply(img);
  for (long i = 0; i < count; ++i) px[i * channels] = luminance(Color(rgb[i * 3], rgb[i * 3 + 1], rgb[i * 3 + 2]));
}

void write_png(const Film& f, const std::string& path, const std::string& view) {
  require_view(view);
  const size_t n = size_t(f.width) * f.height;
  std::vector<float> rgb(n * 3);
  for (size_t p = 0; p < n; ++p)
    for (int c = 0; c < 3; ++c) rgb[p * 3 + c] = f.beauty[p * 4 + c];
  apply_display_view(rgb, view);
  std::vector<unsigned char> px(n * 3);
  for (size_t i = 0; i < n * 3; ++i) {
    // Display-referred: clamp and quantize with a tiny ordered dither against banding.
    const size_t p = i / 3;
    const int x = int(p % f.width), y = int(p / f.width);
    const float dither = (float(((x * 7 + y * 13) % 16)) / 16.0f - 0.5f) / 255.0f;
    px[i] = static_cast<unsigned char>(std::clamp(rgb[i] + dither, 0.0f, 1.0f) * 255.0f + 0.5f);
  }
  OIIO::ImageSpec spec(f.width, f.height, 3, OIIO::TypeDesc::UINT8);
  spec.attribute("oiio:ColorSpace", "sRGB");
  spec.attribute("Software", "Phellem (OCIO view: " + view + ")");
  write_atomically(path, [&](const std::string& tmp) { write_image_file(path, tmp, spec, OIIO::TypeDesc::UINT8, px.data()); });
}

}  // namespace phellem
