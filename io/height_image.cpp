#include "io/height_image.h"

#include <OpenImageIO/imageio.h>

#include <Eigen/LU>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <tuple>

#include "io/image_chroma.h"
#include "io/image_decode.h"
#include "io/image_limits.h"
#include "io/image_output.h"
#include "util/errors.h"
#include "util/input_file.h"

namespace phellem {

namespace {

struct OpenImage {
  std::string path;
  std::unique_ptr<OIIO::ImageInput> in;
  OIIO::ImageSpec spec;

  size_t pixels() const { return size_t(spec.width) * size_t(spec.height); }
  int channel(const char* name) const {
    for (int c = 0; c < spec.nchannels; ++c)
      if (spec.channelnames[size_t(c)] == name) return c;
    return -1;
  }
  [[noreturn]] void fail(const std::string& where, const std::string& what) const { throw UserError(path, where, what); }
};

// Opens `path` and checks its header against the image limits before any pixel is decoded.
OpenImage open_image(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw UserError(path, "", "no such file");
  require_input_file(path, path, "", "an image");  // before opening: a FIFO would block
  OIIO::ImageSpec config;
  config.attribute("oiio:UnassociatedAlpha", 1);  // PNG would otherwise multiply colour by alpha
  config.attribute("oiio:RawColor", 1);           // no colour-model conversion
  OpenImage im;
  im.path = path;
  im.in = OIIO::ImageInput::open(path, &config);
  if (!im.in) throw UserError(path, "header", "not a readable image: " + printable(OIIO::geterror()));
  im.spec = im.in->spec();
  if (auto why = image_size_problem(im.spec.width, im.spec.height, im.spec.depth, im.spec.nchannels)) im.fail("header", *why);
  if (im.spec.depth > 1) im.fail("header", "a volume image (depth " + std::to_string(im.spec.depth) + ") is not a height map");
  return im;
}

// Channels [begin, end) as floats, interleaved. Integer pixels are their code values divided
// by the largest code, read in the file's own type so that nothing but that division happens.
std::vector<float> read_channels(OpenImage& im, int begin, int end, const std::string& where) {
  const int n = end - begin;
  std::vector<float> out(im.pixels() * size_t(n));
  auto decode = [&](OIIO::TypeDesc type, void* data) {
    if (auto why = decode_image(*im.in, begin, end, type, data)) im.fail(where, "cannot decode the pixels: " + *why);
  };
  const auto base = OIIO::TypeDesc::BASETYPE(im.spec.format.basetype);
  if (base == OIIO::TypeDesc::UINT8) {
    std::vector<uint8_t> raw(out.size());
    decode(OIIO::TypeDesc::UINT8, raw.data());
    for (size_t i = 0; i < raw.size(); ++i) out[i] = float(raw[i]) / 255.0f;
  } else if (base == OIIO::TypeDesc::UINT16) {
    std::vector<uint16_t> raw(out.size());
    decode(OIIO::TypeDesc::UINT16, raw.data());
    for (size_t i = 0; i < raw.size(); ++i) out[i] = float(raw[i]) / 65535.0f;
  } else {
    decode(OIIO::TypeDesc::FLOAT, out.data());
  }
  return out;
}

bool integer_pixels(const OIIO::ImageSpec& spec) {
  const auto b = spec.format.basetype;
  return b != OIIO::TypeDesc::FLOAT && b != OIIO::TypeDesc::HALF && b != OIIO::TypeDesc::DOUBLE;
}

void require_finite(const OpenImage& im, const std::vector<float>& v, int channels, const std::string& where) {
  size_t bad = 0, first = 0;
  for (size_t i = 0; i < v.size(); ++i)
    if (!std::isfinite(v[i]) && bad++ == 0) first = i;
  if (bad == 0) return;
  const size_t p = first / size_t(channels);
  const int x = int(p % size_t(im.spec.width)), y = int(p / size_t(im.spec.width));
  im.fail(where, std::to_string(bad) + " value(s) are not finite, the first " + (std::isnan(v[first]) ? "NaN" : "infinite") +
                     " at pixel (" + std::to_string(x) + ", " + std::to_string(y) + "); heights and colours must be finite");
}

// A positive, finite float attribute of the header.
double scale_attribute(const OpenImage& im, const char* name) {
  const float v = im.spec.get_float_attribute(name, std::nanf(""));
  if (!std::isfinite(v) || v <= 0)
    im.fail(name, im.spec.find_attribute(name) ? "must be a positive number of the header" : "missing from the header");
  return double(v);
}

std::vector<float> channel_or_fail(OpenImage& im, const char* name, const std::string& kind) {
  const int c = im.channel(name);
  if (c < 0) im.fail(name, "missing: a " + kind + " EXR has a " + name + " channel");
  return read_channels(im, c, c + 1, name);
}

// The camera position a render's header states: phellem:camera_position, else the
// translation of the inverse of the standard worldToCamera matrix (Imath: row vectors, so the
// camera centre c satisfies c·M = 0).
std::optional<Eigen::Vector3d> camera_position(const OpenImage& im) {
  if (const OIIO::ParamValue* p = im.spec.find_attribute(kCameraPositionAttribute, OIIO::TypeDesc::TypeVector)) {
    const float* v = static_cast<const float*>(p->data());
    const Eigen::Vector3d c(v[0], v[1], v[2]);
    if (!c.allFinite()) im.fail(kCameraPositionAttribute, "must be three finite numbers");
    return c;
  }
  if (const OIIO::ParamValue* p = im.spec.find_attribute(kWorldToCameraAttribute, OIIO::TypeDesc::TypeMatrix44)) {
    Eigen::Matrix4d m;
    const float* v = static_cast<const float*>(p->data());
    for (int r = 0; r < 4; ++r)
      for (int c = 0; c < 4; ++c) m(r, c) = v[4 * r + c];
    const Eigen::Matrix4d inv = m.inverse();
    if (!inv.allFinite()) im.fail(kWorldToCameraAttribute, "is not an invertible matrix");
    return Eigen::Vector3d(inv(3, 0), inv(3, 1), inv(3, 2)) / inv(3, 3);
  }
  return std::nullopt;
}

// Three named channels, interleaved.
std::vector<float> vector_channels(OpenImage& im, const char* const names[3], const std::string& layer) {
  const int c = im.channel(names[0]);
  if (c < 0 || im.channel(names[1]) != c + 1 || im.channel(names[2]) != c + 2)
    im.fail(layer, "missing: a render EXR has the " + layer + " layer (" + names[0] + ", " + names[1] + ", " + names[2] +
                       "); render it again");
  return read_channels(im, c, c + 3, layer);
}

// Render EXR: the displacement AOV and the layers that say which pixels show bark.
void read_render(OpenImage& im, HeightImage& h) {
  h.kind = HeightImage::Kind::render;
  if (im.channel(kRenderDisplacementChannel) < 0)
    im.fail(kRenderDisplacementChannel,
            "missing: this render has no displacement layer (rendered before it existed?); render it again");
  RenderLayers r;
  r.object_id = channel_or_fail(im, kRenderObjectIdChannel, "render");
  r.alpha = channel_or_fail(im, kRenderAlphaChannel, "render");
  r.normal = vector_channels(im, kRenderNormalChannels, "normal");
  r.position = vector_channels(im, kRenderPositionChannels, "position");
  if (im.channel(kRenderAlbedoChannels[0]) >= 0) r.albedo = vector_channels(im, kRenderAlbedoChannels, "albedo");
  for (const auto& [layer, v, n] : {std::tuple<const char*, const std::vector<float>*, int>{kRenderObjectIdChannel, &r.object_id, 1},
                                    {kRenderAlphaChannel, &r.alpha, 1},
                                    {"normal", &r.normal, 3},
                                    {"position", &r.position, 3},
                                    {"albedo", &r.albedo, 3}})
    require_finite(im, *v, n, layer);
  r.camera = camera_position(im);
  h.z = channel_or_fail(im, kRenderDisplacementChannel, "render");
  h.render = std::move(r);
}

// FractureField EXR: height = −depth; the field spans the circumference across and the
// length along.
void read_fracture_field(OpenImage& im, HeightImage& h) {
  h.kind = HeightImage::Kind::fracture_field;
  h.px_per_cm_x = h.width / (100.0 * scale_attribute(im, kFieldCircumferenceAttribute));
  h.px_per_cm_y = h.height / (100.0 * scale_attribute(im, kFieldLengthAttribute));
  h.z = channel_or_fail(im, kFieldDepthChannel, "FractureField");
  for (float& z : h.z) z = -z;
}

void read_patch(OpenImage& im, HeightImage& h) {
  h.kind = HeightImage::Kind::patch;
  h.px_per_cm_x = h.px_per_cm_y = scale_attribute(im, kPxPerCmAttribute);
  h.z = channel_or_fail(im, kPatchHeightChannel, "patch");
}

// Plain image: channel 0, or the mean of the first three for colour.
void read_plain(OpenImage& im, HeightImage& h) {
  h.kind = HeightImage::Kind::plain;
  const int n = im.spec.nchannels >= 3 ? 3 : 1;
  const std::vector<float> v = read_channels(im, 0, n, "pixels");
  if (n == 1) {
    h.z = v;
    return;
  }
  h.chroma = colour_chroma(v.data(), h.width, h.height, 3);
  h.z.resize(im.pixels());
  for (size_t p = 0; p < h.z.size(); ++p) h.z[p] = (v[3 * p] + v[3 * p + 1] + v[3 * p + 2]) / 3.0f;
}

}  // namespace

HeightImage read_height_image(const std::string& path) {
  OpenImage im = open_image(path);
  HeightImage h;
  h.width = im.spec.width;
  h.height = im.spec.height;
  if (im.channel(kRenderDisplacementChannel) >= 0 || im.channel(kRenderObjectIdChannel) >= 0)
    read_render(im, h);  // an older render, without the displacement layer, is refused there
  else if (im.spec.find_attribute(kPxPerCmAttribute))
    read_patch(im, h);
  else if (im.spec.find_attribute(kFieldCircumferenceAttribute) || im.spec.find_attribute(kFieldLengthAttribute) ||
           im.channel(kFieldDepthChannel) >= 0)
    read_fracture_field(im, h);
  else
    read_plain(im, h);
  require_finite(im, h.z, 1, "pixels");
  return h;
}

RgbImage read_albedo_image(const std::string& path) {
  OpenImage im = open_image(path);
  RgbImage img;
  img.width = im.spec.width;
  img.height = im.spec.height;
  const int n = im.spec.nchannels >= 3 ? 3 : 1;
  const std::vector<float> v = read_channels(im, 0, n, "pixels");
  if (n == 3) {
    img.rgb = v;
  } else {
    img.rgb.resize(im.pixels() * 3);
    for (size_t p = 0; p < im.pixels(); ++p) img.rgb[3 * p] = img.rgb[3 * p + 1] = img.rgb[3 * p + 2] = v[p];
  }
  require_finite(im, img.rgb, 3, "pixels");
  // Integer images hold sRGB-encoded colour; float images are scene-linear already.
  if (integer_pixels(im.spec)) srgb_texture_to_linear(img.rgb.data(), long(im.pixels()), 3);
  return img;
}

}  // namespace phellem
