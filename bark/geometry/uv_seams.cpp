#include "bark/geometry/uv_seams.h"

#include <cmath>
#include <map>
#include <tuple>

namespace phellem::bark {

TriMesh cut_uv_seams(const TriMesh& m, std::vector<uint32_t>* source) {
  TriMesh out = m;
  if (source) {
    source->resize(m.positions.size());
    for (size_t i = 0; i < source->size(); ++i) (*source)[i] = uint32_t(i);
  }
  if (!m.has_uvs()) return out;
  std::map<std::tuple<uint32_t, long, long>, uint32_t> copies;  // (vertex, shift u, shift v) -> copy
  for (auto& f : out.triangles) {
    const Eigen::Vector2d first = m.uvs[f[0]];
    for (int k = 1; k < 3; ++k) {
      const Eigen::Vector2d d = m.uvs[f[k]] - first;
      const long su = std::lround(-d.x()), sv = std::lround(-d.y());  // whole periods back towards the first corner
      if (su == 0 && sv == 0) continue;
      const auto key = std::make_tuple(f[k], su, sv);
      auto it = copies.find(key);
      if (it == copies.end()) {
        const uint32_t v = f[k];
        out.positions.push_back(m.positions[v]);
        out.uvs.push_back(m.uvs[v] + Eigen::Vector2d(double(su), double(sv)));
        if (source) source->push_back(v);
        it = copies.emplace(key, uint32_t(out.positions.size() - 1)).first;
      }
      f[k] = it->second;
    }
  }
  return out;
}

}  // namespace phellem::bark
