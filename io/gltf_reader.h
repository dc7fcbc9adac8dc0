// glTF in: opening a file with every failure reported as a UserError naming it, and reading
// accessors with their bounds checked (shared by the mesh loader and the CrackedMesh reader).
#pragma once

#include <tiny_gltf.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include "io/mesh_io.h"
#include "util/errors.h"

namespace phellem {

// Loads a .gltf or .glb (images are kept encoded; OpenImageIO decodes them later).
tinygltf::Model open_gltf(const std::string& path);

class GltfReader {
 public:
  GltfReader(const tinygltf::Model& m, std::string file) : m_(m), file_(std::move(file)) {}

  [[noreturn]] void fail(const std::string& where, const std::string& what) const { throw UserError(file_, where, what); }

  // Reads accessor `index` as floats with `comps` components per element.
  std::vector<float> floats(int index, int comps, const std::string& where) const {
    const tinygltf::Accessor& a = accessor(index, where);
    const int nc = tinygltf::GetNumComponentsInType(a.type);
    if (nc != comps)
      fail(where,
           "accessor " + std::to_string(index) + " has " + std::to_string(nc) + " components, expected " + std::to_string(comps));
    const Layout l = layout(a, index, where);  // bounds checked before anything is allocated
    std::vector<float> out(a.count * comps);
    visit(a, l, [&](size_t i, int c, const unsigned char* p) {
      float v;
      switch (a.componentType) {
        case TINYGLTF_COMPONENT_TYPE_FLOAT:
          std::memcpy(&v, p, 4);
          break;
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
          v = a.normalized ? *p / 255.0f : *p;
          break;
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
          uint16_t s;
          std::memcpy(&s, p, 2);
          v = a.normalized ? s / 65535.0f : s;
          break;
        }
        case TINYGLTF_COMPONENT_TYPE_BYTE:
          v = a.normalized ? std::max(*reinterpret_cast<const int8_t*>(p) / 127.0f, -1.0f) : *reinterpret_cast<const int8_t*>(p);
          break;
        case TINYGLTF_COMPONENT_TYPE_SHORT: {
          int16_t s;
          std::memcpy(&s, p, 2);
          v = a.normalized ? std::max(s / 32767.0f, -1.0f) : s;
          break;
        }
        default:
          fail(where, "accessor " + std::to_string(index) + " has a component type not allowed for vertex data");
      }
      if (!std::isfinite(v)) fail(where, "accessor " + std::to_string(index) + " contains a non-finite value");
      out[i * comps + c] = v;
    });
    return out;
  }

  // Reads the first component of every element of accessor `index` (SCALAR to VEC4: a painted
  // vertex colour's red, a custom attribute's value).
  std::vector<float> first_components(int index, const std::string& where) const {
    const int nc = tinygltf::GetNumComponentsInType(accessor(index, where).type);
    if (nc < 1 || nc > 4) fail(where, "accessor " + std::to_string(index) + " must be SCALAR, VEC2, VEC3 or VEC4");
    const std::vector<float> all = floats(index, nc, where);
    std::vector<float> out(all.size() / size_t(nc));
    for (size_t i = 0; i < out.size(); ++i) out[i] = all[i * size_t(nc)];
    return out;
  }

  // Reads accessor `index` as texture coordinates (VEC2), each within ±kMaxUv.
  std::vector<float> uvs(int index, const std::string& where) const {
    std::vector<float> out = floats(index, 2, where);
    for (size_t i = 0; i < out.size(); ++i)
      if (std::abs(out[i]) > kMaxUv)
        fail(where, "accessor " + std::to_string(index) + " element " + std::to_string(i / 2) + " has texture coordinate " +
                        std::to_string(out[i]) + "; at most 1e6 in magnitude are allowed");
    return out;
  }

  std::vector<uint32_t> indices(int index, const std::string& where) const {
    const tinygltf::Accessor& a = accessor(index, where);
    if (a.type != TINYGLTF_TYPE_SCALAR) fail(where, "index accessor must be SCALAR");
    const Layout l = layout(a, index, where);  // bounds checked before anything is allocated
    std::vector<uint32_t> out(a.count);
    visit(a, l, [&](size_t i, int, const unsigned char* p) {
      switch (a.componentType) {
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
          out[i] = *p;
          break;
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
          uint16_t s;
          std::memcpy(&s, p, 2);
          out[i] = s;
          break;
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
          std::memcpy(&out[i], p, 4);
          break;
        default:
          fail(where, "index accessor must be UNSIGNED_BYTE, UNSIGNED_SHORT or UNSIGNED_INT");
      }
    });
    return out;
  }

  // Where accessor `index`'s elements lie, every byte of them checked to be inside its
  // bufferView and buffer (without overflow, whatever the counts and offsets). Errors name
  // the glTF element at fault (e.g. "accessors[2].count") and, after "read as", the element
  // `where` that refers to the accessor (empty: none).
  struct Layout {
    const unsigned char* base = nullptr;
    size_t stride = 0, comp_size = 0;
    int components = 0;
  };
  Layout layout(const tinygltf::Accessor& a, int index, const std::string& where) const {
    const std::string acc = "accessors[" + std::to_string(index) + "]";
    const std::string use = where.empty() ? std::string() : " (read as " + where + ")";
    if (a.sparse.isSparse) fail(acc + ".sparse", "sparse accessors are not supported" + use);
    if (a.bufferView < 0 || size_t(a.bufferView) >= m_.bufferViews.size())
      fail(acc + ".bufferView", "bufferView index " + std::to_string(a.bufferView) + " out of range (file has " +
                                    std::to_string(m_.bufferViews.size()) + " bufferViews)" + use);
    const std::string view = "bufferViews[" + std::to_string(a.bufferView) + "]";
    const tinygltf::BufferView& bv = m_.bufferViews[a.bufferView];
    if (bv.buffer < 0 || size_t(bv.buffer) >= m_.buffers.size())
      fail(view + ".buffer", "buffer index " + std::to_string(bv.buffer) + " out of range (file has " +
                                 std::to_string(m_.buffers.size()) + " buffers)" + use);
    const tinygltf::Buffer& buf = m_.buffers[bv.buffer];
    const int comp_size = tinygltf::GetComponentSizeInBytes(a.componentType);
    const int nc = tinygltf::GetNumComponentsInType(a.type);
    if (comp_size <= 0) fail(acc + ".componentType", "invalid componentType " + std::to_string(a.componentType) + use);
    if (nc <= 0) fail(acc + ".type", "invalid type" + use);
    const size_t elem = size_t(comp_size) * nc;
    const size_t stride = bv.byteStride ? bv.byteStride : elem;
    if (stride < elem)
      fail(view + ".byteStride", "byteStride " + std::to_string(bv.byteStride) + " is smaller than one element of " + acc + " (" +
                                     std::to_string(elem) + " bytes)" + use);
    const size_t size = buf.data.size();
    if (bv.byteOffset > size || bv.byteLength > size - bv.byteOffset)
      fail(view, "reaches byte " + std::to_string(bv.byteOffset) + " + " + std::to_string(bv.byteLength) + " but buffers[" +
                     std::to_string(bv.buffer) + "] holds " + std::to_string(size) + " bytes (truncated or missing buffer?)" +
                     use);
    if (a.byteOffset > bv.byteLength)
      fail(acc + ".byteOffset", "byteOffset " + std::to_string(a.byteOffset) + " is beyond the end of " + view + " (" +
                                    std::to_string(bv.byteLength) + " bytes)" + use);
    // count elements: (count - 1) strides and one element after byteOffset, within the view.
    const size_t room = bv.byteLength - a.byteOffset;
    const size_t max_count = room < elem ? 0 : (room - elem) / stride + 1;
    if (a.count > max_count)
      fail(acc + ".count", "count " + std::to_string(a.count) + " of " + std::to_string(elem) + "-byte elements (stride " +
                               std::to_string(stride) + ") after byteOffset " + std::to_string(a.byteOffset) + " overruns " +
                               view + " (" + std::to_string(bv.byteLength) + " bytes: room for " + std::to_string(max_count) +
                               ")" + use);
    return {buf.data.data() + bv.byteOffset + a.byteOffset, stride, size_t(comp_size), nc};
  }

 private:
  const tinygltf::Accessor& accessor(int index, const std::string& where) const {
    if (index < 0 || size_t(index) >= m_.accessors.size())
      fail(where, "accessor index " + std::to_string(index) + " out of range (file has " + std::to_string(m_.accessors.size()) +
                      " accessors)");
    return m_.accessors[index];
  }

  template <typename F>
  void visit(const tinygltf::Accessor& a, const Layout& l, F&& f) const {
    for (size_t i = 0; i < a.count; ++i)
      for (int c = 0; c < l.components; ++c) f(i, c, l.base + i * l.stride + size_t(c) * l.comp_size);
  }

  const tinygltf::Model& m_;
  std::string file_;
};

}  // namespace phellem
