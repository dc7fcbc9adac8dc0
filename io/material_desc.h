// Materials as mesh files and scene files describe them (glTF PBR, OBJ MTL, a scene's
// "materials" entries); the renderer compiles them into its own materials.
#pragma once

#include <string>

#include "util/errors.h"
#include "util/math.h"

namespace phellem {

// A texture is an image file or a built-in procedural pattern.
struct TextureDesc {
  std::string file;        // resolved absolute path, empty if procedural/none
  std::string procedural;  // "bark" or empty
  Color color_a{0.35f, 0.27f, 0.2f};
  Color color_b{0.12f, 0.09f, 0.07f};
  Vec2f scale{1, 1};  // UV multiplier
  bool srgb = true;   // colour textures: sRGB-encoded 8-bit inputs
  bool empty() const { return file.empty() && procedural.empty(); }
};

enum class MaterialType { Diffuse, Bark, Conductor, Dielectric, Emissive };
struct MaterialDesc {
  std::string name;
  Location where;
  MaterialType type = MaterialType::Diffuse;
  Color base_color{0.8f, 0.8f, 0.8f};
  TextureDesc base_color_texture;
  float roughness = 0.5f;
  TextureDesc roughness_texture;
  TextureDesc normal_texture;
  float specular = 0.5f;  // bark: F0 = 0.08 * specular
  float ior = 1.5f;       // dielectric
  Color emission{1, 1, 1};
  float strength = 1.0f;
  bool double_sided = true;
};

}  // namespace phellem
