#include "renderer/textures.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <OpenImageIO/texture.h>
#include <unistd.h>

#include <filesystem>
#include <mutex>

#include "io/builtin_files.h"
#include "io/image_decode.h"
#include "io/image_limits.h"
#include "io/image_output.h"
#include "util/cache_dir.h"
#include "util/errors.h"
#include "util/hash.h"
#include "util/noise.h"

namespace phellem {

namespace fs = std::filesystem;

namespace {

// Bump when the conversion changes so stale cached .tx files are not reused (3: every source is
// decoded through io/image_decode.h, which refuses a truncated JPEG that version 2 converted).
constexpr uint32_t kTextureCacheVersion = 3;

struct Entry {
  TextureDesc desc;
  OIIO::TextureSystem::TextureHandle* handle = nullptr;
  int channels = 0;
};

// Every pixel of `file` (`spec` its header) as floats, through the checked decoder
// (io/image_decode.h): OpenImageIO's own texture conversion would take a truncated JPEG whole.
std::vector<float> decode_texture(const std::string& file, const OIIO::ImageSpec& spec, const Location& where) {
  ImageSource src = open_image_source(file);
  if (!src.in) throw UserError(where.file, where.path, "cannot read image " + file + ": " + src.why);
  std::vector<float> px(size_t(spec.width) * size_t(spec.height) * size_t(spec.depth) * size_t(spec.nchannels));
  if (auto why = decode_image(*src.in, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, px.data()))
    throw UserError(where.file, where.path, "cannot read image " + file + ": " + *why);
  return px;
}

// Converts `src` to a linear, tiled, mip-mapped .tx (once; keyed by path, size, mtime).
std::string make_tx(const TextureDesc& d, const Location& where) {
  // The header alone decides whether the image may be decoded (io/image_limits.h): OIIO's
  // texture set-up crashes on a header that claims 100000 x 100000 pixels.
  std::string why;
  const std::optional<OIIO::ImageSpec> header = read_image_header(d.file, &why);
  if (!header) throw UserError(where.file, where.path, why);
  const OIIO::ImageSpec& spec = *header;
  std::error_code ec;
  const auto size = fs::file_size(d.file, ec);
  if (ec) throw UserError(where.file, where.path, "cannot read texture " + d.file);
  const auto mtime = fs::last_write_time(d.file, ec).time_since_epoch().count();
  uint32_t h = hash_u32(uint32_t(size)) ^ hash_u32(uint32_t(mtime)) ^ hash_u32(uint32_t(uint64_t(mtime) >> 32));
  for (char c : d.file) h = hash_combine(h, uint8_t(c));
  h = hash_combine(h, d.srgb ? 1 : 0);
  h = hash_combine(h, kTextureCacheVersion);
  char name[64];
  std::snprintf(name, sizeof name, "%08x.tx", h);
  const fs::path out = fs::path(texture_cache_dir()) / name;
  if (fs::exists(out)) return out.string();

  const bool eight_bit = spec.format == OIIO::TypeDesc::UINT8;
  OIIO::ImageSpec config;
  config.attribute("maketx:filtername", "lanczos3");
  config.attribute("maketx:constant_color_detect", 0);
  config.attribute("maketx:fixnan", "box3");
  config.attribute("tile_width", 64);
  config.attribute("tile_height", 64);
  const fs::path tmp = out.string() + "." + std::to_string(getpid()) + ".tmp.tx";
  std::stringstream log;
  bool ok;
  // Decoded whole once, checked, whichever way it is converted.
  std::vector<float> px = decode_texture(d.file, spec, where);
  if (d.srgb && eight_bit) {
    // sRGB 8-bit colour: decode to linear through the OCIO config, store as half.
    srgb_texture_to_linear(px.data(), long(spec.width) * spec.height, spec.nchannels);
    OIIO::ImageBuf lin(OIIO::ImageSpec(spec.width, spec.height, spec.nchannels, OIIO::TypeDesc::FLOAT), px.data());
    config.format = OIIO::TypeDesc::HALF;
    ok = OIIO::ImageBufAlgo::make_texture(OIIO::ImageBufAlgo::MakeTxTexture, lin, tmp.string(), config, &log);
  } else {
    px = {};  // only checked: the file converts from its own type
    ok = OIIO::ImageBufAlgo::make_texture(OIIO::ImageBufAlgo::MakeTxTexture, d.file, tmp.string(), config, &log);
  }
  if (!ok) {
    fs::remove(tmp, ec);
    throw UserError(where.file, where.path, "cannot convert texture " + d.file + ": " + OIIO::geterror());
  }
  fs::rename(tmp, out, ec);
  if (ec) throw std::runtime_error("cannot move texture into cache: " + ec.message());
  return out.string();
}

// Procedural bark: elongated noise streaks with dark fissures, periodic in u with period 1,
// band-limited to the lookup's footprint (uv units) like a mip-mapped image.
Color procedural_bark(const TextureDesc& d, const Vec2f& uv, float footprint) {
  const float a = kTwoPi * uv.x() * d.scale.x() / std::max(1.0f, std::round(d.scale.x()));
  const float ring = std::max(1.0f, std::round(d.scale.x())) / kTwoPi;
  const Vec3f q(std::cos(a) * ring * 3.0f, std::sin(a) * ring * 3.0f, uv.y() * d.scale.y());
  // Lattice cells per unit of u (around the trunk) and of v; the footprint in cells is
  // taken along the finer of the two.
  const float cells_per_uv = std::max(3.0f * std::max(1.0f, std::round(d.scale.x())), d.scale.y());
  const float fp = std::max(0.0f, footprint) * cells_per_uv;
  const float streak = fbm_filtered(Vec3f(q.x(), q.y(), q.z() * 0.25f), 11, 3, fp);
  const float fleck_w = band_weight(4.0f * fp);
  const float fleck = fleck_w > 0 ? fleck_w * gradient_noise(q * 4.0f, 23) : 0.0f;
  const float t = std::clamp(0.55f + 0.9f * streak + 0.25f * fleck, 0.0f, 1.0f);
  return d.color_b + (d.color_a - d.color_b) * t;
}

OIIO::TextureOpt texture_options(bool primary) {
  OIIO::TextureOpt opt;
  opt.swrap = opt.twrap = OIIO::TextureOpt::WrapPeriodic;
  if (!primary) opt.interpmode = OIIO::TextureOpt::InterpBilinear;
  return opt;
}

}  // namespace

struct TextureStore::Impl {
  std::shared_ptr<OIIO::TextureSystem> ts;
  std::vector<Entry> entries;
  std::mutex mutex;
};

TextureStore::TextureStore() : impl_(std::make_unique<Impl>()) {
  impl_->ts = std::shared_ptr<OIIO::TextureSystem>(OIIO::TextureSystem::create(false),
                                                   [](OIIO::TextureSystem* t) { OIIO::TextureSystem::destroy(t); });
  impl_->ts->attribute("max_memory_MB", 512.0f);
  impl_->ts->attribute("autotile", 64);
  impl_->ts->attribute("automip", 1);
}

TextureStore::~TextureStore() = default;

int TextureStore::add(const TextureDesc& desc, const Location& where) {
  if (desc.empty()) return -1;
  std::lock_guard<std::mutex> lock(impl_->mutex);
  Entry e;
  e.desc = desc;
  if (!desc.file.empty()) {
    const std::string tx = make_tx(desc, where);
    e.handle = impl_->ts->get_texture_handle(OIIO::ustring(tx));
    const OIIO::ImageSpec* spec = e.handle ? impl_->ts->imagespec(e.handle, nullptr) : nullptr;
    if (!spec) throw UserError(where.file, where.path, "cannot open texture " + desc.file + ": " + impl_->ts->geterror());
    e.channels = spec->nchannels;
  }
  impl_->entries.push_back(std::move(e));
  return int(impl_->entries.size() - 1);
}

Color TextureStore::rgb(int handle, const Vec2f& uv, float footprint, bool primary) const {
  const Entry& e = impl_->entries[handle];
  const Vec2f st(uv.x() * e.desc.scale.x(), uv.y() * e.desc.scale.y());
  if (!e.handle) return procedural_bark(e.desc, uv, footprint);
  OIIO::TextureOpt opt = texture_options(primary);  // OIIO takes it by non-const reference
  float out[4] = {0, 0, 0, 0};
  const float fw = footprint * std::max(e.desc.scale.x(), e.desc.scale.y());
  const int nc = std::min(3, e.channels);
  impl_->ts->texture(e.handle, nullptr, opt, st.x(), 1.0f - st.y(), fw, 0, 0, fw, nc, out);
  if (nc == 1) return Color::Constant(out[0]);
  if (nc == 2) return Color(out[0], out[0], out[0]);
  return Color(out[0], out[1], out[2]);
}

float TextureStore::scalar(int handle, const Vec2f& uv, float footprint, bool primary) const {
  const Entry& e = impl_->entries[handle];
  if (!e.handle) return luminance(procedural_bark(e.desc, uv, footprint));
  OIIO::TextureOpt opt = texture_options(primary);  // OIIO takes it by non-const reference
  const Vec2f st(uv.x() * e.desc.scale.x(), uv.y() * e.desc.scale.y());
  const float fw = footprint * std::max(e.desc.scale.x(), e.desc.scale.y());
  float out = 0;
  impl_->ts->texture(e.handle, nullptr, opt, st.x(), 1.0f - st.y(), fw, 0, 0, fw, 1, &out);
  return out;
}

size_t TextureStore::memory_bytes() const {
  int64_t bytes = 0;
  impl_->ts->getattribute("stat:cache_memory_used", OIIO::TypeInt64, &bytes);
  return size_t(bytes);
}

}  // namespace phellem
