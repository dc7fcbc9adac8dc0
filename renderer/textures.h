// Textures through OpenImageIO's TextureSystem: every image becomes a tiled, mip-mapped,
// scene-linear .tx file in a cache (sRGB 8-bit inputs are linearized once, by maketx), so
// lookups are filtered and large texture sets stay out of memory. Procedural textures are
// evaluated directly.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "scene/scene_desc.h"
#include "util/math.h"

namespace phellem {

class TextureStore {
 public:
  TextureStore();
  ~TextureStore();
  TextureStore(const TextureStore&) = delete;
  TextureStore& operator=(const TextureStore&) = delete;

  // Registers a texture; returns its handle (-1 for an empty desc). Image problems are
  // UserErrors naming `where`.
  int add(const TextureDesc& desc, const Location& where);

  // uv with v up (origin bottom-left); `footprint` is the filter width in uv units.
  // `primary` lookups (seen directly by the camera) interpolate bicubically within a mip
  // level; secondary ones, whose result is averaged over a bounce, bilinearly (cheaper).
  Color rgb(int handle, const Vec2f& uv, float footprint, bool primary = true) const;
  float scalar(int handle, const Vec2f& uv, float footprint, bool primary = true) const;

  size_t memory_bytes() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace phellem
