#include <tiny_obj_loader.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string_view>

#include "io/mesh_io.h"
#include "util/errors.h"
#include "util/input_file.h"

namespace phellem {

namespace {

// Coordinates and normals must fit a float (the loader keeps them as floats).
constexpr double kMaxFloat = 3.4028234663852886e38;
constexpr const char* kFloatRange = "coordinates must be finite and fit a float (magnitude at most 3.4e38)";

// An OBJ index field: optional sign and decimal digits, saturated far beyond any count (so
// 4294967299 stays 4294967299 instead of wrapping to 3 as atoi does in tinyobjloader).
bool parse_index(std::string_view text, int64_t* out) {
  size_t i = 0;
  const bool negative = !text.empty() && text[0] == '-';
  if (!text.empty() && (text[0] == '-' || text[0] == '+')) ++i;
  if (i == text.size()) return false;
  int64_t v = 0;
  for (; i < text.size(); ++i) {
    if (text[i] < '0' || text[i] > '9') return false;
    v = std::min<int64_t>(v * 10 + (text[i] - '0'), int64_t(1) << 62);
  }
  *out = negative ? -v : v;
  return true;
}

// The numbers of a v, vn or vt line: its first `count` fields (a v line's w or vertex colour
// and a vt line's w are not used), each a finite number that fits a float, within ±`limit`.
// tinyobjloader reads "nan" and "inf" as 0 without a word and 1e39 as a float infinity.
// Missing fields are left to tinyobjloader (it reads them as 0).
void check_obj_numbers(std::string_view fields, const char* key, int count, double limit, const char* allowed,
                       const std::string& path, size_t line_num) {
  for (int k = 0; k < count; ++k) {
    const size_t b = fields.find_first_not_of(" \t");
    if (b == std::string_view::npos || fields[b] == '#') return;
    fields.remove_prefix(b);
    const std::string_view token = fields.substr(0, std::min(fields.find_first_of(" \t"), fields.size()));
    fields.remove_prefix(token.size());
    std::string_view digits = token;
    if (digits.size() > 1 && digits[0] == '+' && digits[1] != '-') digits.remove_prefix(1);  // from_chars takes no '+'
    double v = 0;
    const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), v);
    const bool whole = end == digits.data() + digits.size();
    // A literal too small for a double (1e-400) is 0 for a float as well.
    const bool underflow = ec == std::errc::result_out_of_range &&
                           (digits.find("e-") != std::string_view::npos || digits.find("E-") != std::string_view::npos);
    auto fail = [&](const char* what) {
      throw UserError(path, "line " + std::to_string(line_num),
                      std::string("'") + key + "' field " + std::to_string(k + 1) + " \"" + printable(token) + "\" " + what +
                          "; " + allowed);
    };
    if (!whole || ec == std::errc::invalid_argument || !std::isfinite(v)) fail("is not a finite number");
    if (!underflow && (ec == std::errc::result_out_of_range || std::abs(v) > limit)) fail("is out of range");
  }
}

// tinyobjloader triangulates a face of more than four corners by ear clipping in time that
// grows with the square of its corners or faster (measured: 0.4 s for one face of 4000
// corners, 1.7 s for 8000, whether they are distinct points of a convex polygon or one index
// repeated; a face "f 1 1 1 ..." of 200000 corners ran for over two minutes). Small faces
// cost little beyond reading them, so the squared corner counts of the faces with more than
// kLargeFace corners are summed and bounded: about 3 s of triangulation here, while an
// ordinary mesh (caps of a few hundred corners, hundreds of them) stays far below.
struct LargeFaceWork {
  static constexpr uint64_t kLargeFace = 64;
  static constexpr uint64_t kMaxWork = 100'000'000;
  uint64_t work = 0;
  void add(uint64_t corners, const std::string& path, const std::string& where) {
    if (corners <= kLargeFace) return;
    work += corners < (uint64_t(1) << 31) ? corners * corners : kMaxWork + 1;  // no overflow: work <= kMaxWork before
    if (work > kMaxWork)
      throw UserError(path, where,
                      "this face has " + std::to_string(corners) + " corners; faces of more than " + std::to_string(kLargeFace) +
                          " corners take time growing with the square of their corners to triangulate, and with this one "
                          "the file's sum of those squares reaches " + std::to_string(work) + ", more than the " +
                          std::to_string(kMaxWork) + " allowed (one face of 10000 corners, or hundreds of a few hundred)");
  }
};

// Reads the file line by line before tinyobjloader does, checking what it would take
// silently or take too long over: the numbers of v, vt and vn lines (check_obj_numbers), the
// size of faces (LargeFaceWork), and every index of the face (f), line (l) and point (p)
// statements against the positions (v), texture coordinates (vt) and normals (vn) defined
// before that line, as OBJ defines them (1-based, negative = relative to the last one
// defined): tinyobjloader parses indices with atoi (a huge index wraps to a valid one) and
// drops out-of-range texture coordinate and normal indices without a word.
// Lines end at \n, \r\n or \r, as in tinyobjloader, so the line numbers agree.
void check_obj_lines(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw UserError(path, "open", "cannot open OBJ file");
  std::streambuf* sb = in.rdbuf();
  int64_t counts[3] = {0, 0, 0};  // v, vt, vn
  LargeFaceWork large_faces;
  static const char* kinds[3] = {"vertex", "texture coordinate", "normal"};
  static const char* keys[3] = {"v", "vt", "vn"};
  std::string line;
  size_t line_num = 0;
  bool more = true;
  while (more) {
    line.clear();
    for (;;) {
      const int c = sb->sbumpc();
      if (c == std::char_traits<char>::eof()) {
        more = false;
        break;
      }
      if (c == '\n') break;
      if (c == '\r') {
        if (sb->sgetc() == '\n') sb->sbumpc();
        break;
      }
      line.push_back(char(c));
    }
    if (!more && line.empty()) break;
    ++line_num;
    std::string_view t(line);
    const size_t start = t.find_first_not_of(" \t");
    if (start == std::string_view::npos) continue;
    t.remove_prefix(start);
    auto statement = [&](std::string_view key) {
      return t.size() > key.size() && t.substr(0, key.size()) == key && (t[key.size()] == ' ' || t[key.size()] == '\t');
    };
    if (statement("v")) {
      check_obj_numbers(t.substr(2), "v", 3, kMaxFloat, kFloatRange, path, line_num);
      ++counts[0];
      continue;
    }
    if (statement("vt")) {
      check_obj_numbers(t.substr(3), "vt", 2, kMaxUv, "texture coordinates must lie in [-1e6, 1e6]", path, line_num);
      ++counts[1];
      continue;
    }
    if (statement("vn")) {
      check_obj_numbers(t.substr(3), "vn", 3, kMaxFloat, kFloatRange, path, line_num);
      ++counts[2];
      continue;
    }
    if (!statement("f") && !statement("l") && !statement("p")) continue;
    const char statement_key = t[0];
    t.remove_prefix(2);
    const std::string where = "line " + std::to_string(line_num);
    uint64_t corners = 0;
    while (!t.empty()) {
      const size_t b = t.find_first_not_of(" \t");
      if (b == std::string_view::npos) break;
      t.remove_prefix(b);
      const size_t e = std::min(t.find_first_of(" \t"), t.size());
      const std::string_view token = t.substr(0, e);
      t.remove_prefix(e);
      ++corners;
      // v, v/vt, v//vn or v/vt/vn
      std::string_view fields[3];
      size_t nf = 0;
      for (std::string_view rest = token;; ++nf) {
        const size_t slash = rest.find('/');
        if (nf == 3 || (slash != std::string_view::npos && nf == 2))
          throw UserError(
              path, where,
              std::string("'") + statement_key + "' element \"" + printable(token) + "\" has more than three indices (v/vt/vn)");
        fields[nf] = rest.substr(0, slash);
        if (slash == std::string_view::npos) {
          ++nf;
          break;
        }
        rest.remove_prefix(slash + 1);
      }
      for (size_t k = 0; k < nf; ++k) {
        if (k == 1 && fields[k].empty() && nf == 3) continue;  // v//vn
        int64_t idx = 0;
        if (!parse_index(fields[k], &idx))
          throw UserError(path, where,
                          std::string("'") + statement_key + "' element \"" + printable(token) + "\": " + kinds[k] + " index \"" +
                              printable(fields[k]) + "\" is not an integer");
        const int64_t n = counts[k];
        if (idx == 0 || idx > n || -idx > n)
          throw UserError(path, where,
                          std::string("'") + statement_key + "' element \"" + printable(token) + "\": " + kinds[k] + " index " +
                              std::to_string(idx) + " is out of range: " + std::to_string(n) + " " + keys[k] + " line" +
                              (n == 1 ? "" : "s") + " before it (indices run from 1 to " + std::to_string(n) +
                              ", or from -1 back to -" + std::to_string(n) + ")");
      }
    }
    if (statement_key == 'f') large_faces.add(corners, path, where);
  }
}

// Reads the material libraries an OBJ names (mtllib) from its folder, as tinyobjloader's
// MaterialFileReader does, but refuses one that is not a regular file before opening it
// (util/input_file.h): a FIFO would block the reader for ever. A missing library is a warning
// and the default material, as in tinyobjloader.
class MaterialLibraryReader : public tinyobj::MaterialReader {
 public:
  MaterialLibraryReader(std::string obj_path, std::filesystem::path folder)
      : obj_path_(std::move(obj_path)), folder_(std::move(folder)) {}
  bool operator()(const std::string& name, std::vector<tinyobj::material_t>* materials,
                  std::map<std::string, int>* material_map, std::string* warn, std::string*) override {
    const std::string file = (folder_ / name).string();
    std::error_code ec;
    if (!std::filesystem::exists(file, ec)) {
      if (warn) *warn += "material library " + file + " not found\n";
      return false;
    }
    require_input_file(file, obj_path_, "mtllib " + printable(name), "a material library");
    std::ifstream in(file, std::ios::binary);
    if (!in) throw UserError(obj_path_, "mtllib " + printable(name), "cannot open " + printable(file));
    tinyobj::LoadMtl(material_map, materials, &in, warn, nullptr);
    return true;
  }

 private:
  std::string obj_path_;
  std::filesystem::path folder_;
};

struct ObjContents {
  tinyobj::attrib_t attrib;
  std::vector<tinyobj::shape_t> shapes;
  std::vector<tinyobj::material_t> materials;
};

ObjContents parse_obj(const std::string& path, const std::filesystem::path& folder) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw UserError(path, "open", "cannot open OBJ file");
  MaterialLibraryReader libraries(path, folder);
  ObjContents obj;
  std::string warn, err;
  if (!tinyobj::LoadObj(&obj.attrib, &obj.shapes, &obj.materials, &warn, &err, &in, &libraries, /*triangulate*/ true,
                        /*default_vcols_fallback*/ true)) {
    while (!err.empty() && err.back() == '\n') err.pop_back();
    throw UserError(path, "read", "invalid OBJ: " + (err.empty() ? std::string("unreadable file") : err));
  }
  return obj;
}

}  // namespace

LoadedModel load_obj(const std::string& path) {
  require_input_file(path, path, "open", "an OBJ file");  // before opening: a FIFO would block
  check_obj_lines(path);
  const std::filesystem::path folder = std::filesystem::path(path).parent_path();
  const ObjContents obj = parse_obj(path, folder);
  const auto& attrib = obj.attrib;
  LoadedModel out;
  for (size_t i = 0; i < obj.materials.size(); ++i) {
    const auto& m = obj.materials[i];
    MaterialDesc d;
    d.name = m.name;
    d.where = {path, "material " + m.name};
    d.type = MaterialType::Diffuse;
    d.base_color = Color(m.diffuse[0], m.diffuse[1], m.diffuse[2]).max(0.0f).min(1.0f);
    if (!m.diffuse_texname.empty()) {
      d.base_color_texture.file = (folder / m.diffuse_texname).string();
      std::error_code ec;
      if (!std::filesystem::exists(d.base_color_texture.file, ec))
        throw UserError(path, "material " + m.name + ": map_Kd", "texture not found: " + d.base_color_texture.file);
      require_input_file(d.base_color_texture.file, path, "material " + m.name + ": map_Kd", "a texture");
    }
    out.materials.push_back(d);
  }
  const size_t nv = attrib.vertices.size() / 3;
  for (size_t si = 0; si < obj.shapes.size(); ++si) {
    const auto& shape = obj.shapes[si];
    const std::string where = "shape " + (shape.name.empty() ? std::to_string(si) : shape.name);
    MeshData md;
    md.material = shape.mesh.material_ids.empty() ? -1 : shape.mesh.material_ids[0];
    const bool has_n = !attrib.normals.empty(), has_t = !attrib.texcoords.empty();
    for (const auto& idx : shape.mesh.indices) {
      if (idx.vertex_index < 0 || size_t(idx.vertex_index) >= nv) throw UserError(path, where, "vertex index out of range");
      const float* p = &attrib.vertices[3 * idx.vertex_index];
      md.positions.emplace_back(p[0], p[1], p[2]);
      if (has_n && idx.normal_index >= 0 && size_t(idx.normal_index) < attrib.normals.size() / 3) {
        const float* n = &attrib.normals[3 * idx.normal_index];
        md.normals.emplace_back(Vec3f(n[0], n[1], n[2]).normalized());
      }
      if (has_t && idx.texcoord_index >= 0 && size_t(idx.texcoord_index) < attrib.texcoords.size() / 2) {
        const float* t = &attrib.texcoords[2 * idx.texcoord_index];
        md.uvs.emplace_back(t[0], t[1]);
      }
      md.indices.push_back(uint32_t(md.indices.size()));
    }
    if (md.normals.size() != md.positions.size()) md.normals.clear();
    if (md.uvs.size() != md.positions.size()) md.uvs.clear();
    for (const auto& p : md.positions)
      if (!p.allFinite()) throw UserError(path, where, "non-finite vertex position");
    if (md.normals.empty()) compute_vertex_normals(md);
    compute_tangents(md);
    if (!md.indices.empty()) out.meshes.push_back(std::move(md));
  }
  if (out.meshes.empty()) throw UserError(path, "faces", "the file contains no faces");
  return out;
}

}  // namespace phellem
