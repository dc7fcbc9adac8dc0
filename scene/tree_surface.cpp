#include "scene/tree_surface.h"

#include "scene/displacement.h"

namespace phellem {

namespace {

using bark::GeneralizedCylinder;

TreePart make_part(std::shared_ptr<const GeneralizedCylinder> cyl, const DisplacementFn& disp, const DisplacementFn& texture_disp,
                   float uv_repeat, float mean_radius) {
  TreePart part;
  part.cylinder = cyl;
  const float L = float(cyl->length());
  const float circumference = kTwoPi * mean_radius;
  auto texcoord = [uv_repeat, L, circumference](float u, float v) {
    return Vec2f(u * uv_repeat, v * L / circumference * uv_repeat);
  };
  part.surface.periodic_u = true;
  part.surface.position = [cyl, disp, texture_disp, texcoord, L](float u, float v, float* offset) {
    const double theta = 2.0 * M_PI * double(u);
    const Eigen::Vector3d p = cyl->position(v, theta);
    const Eigen::Vector3d n = cyl->normal(v, theta);
    const Vec3f pf = p.cast<float>();
    float d = disp(Vec2f(u, v * L), pf);
    if (texture_disp) d += texture_disp(texcoord(u, v), pf);
    if (offset) *offset = d;
    return Vec3f(pf + n.cast<float>() * d);
  };
  part.surface.texcoord = texcoord;
  // Patches roughly square in world space; edges are then refined per patch edge.
  part.surface.patches_u = 16;
  part.surface.patches_v = std::clamp(int(std::ceil(L / (circumference / 16.0f))), 1, 4096);
  return part;
}

float mean(const std::vector<float>& r) {
  float s = 0;
  for (float x : r) s += x;
  return s / float(r.size());
}

void add_branches(const GeneralizedCylinder& parent, int parent_index, const std::vector<BranchDesc>& branches,
                  const std::function<DisplacementFn(size_t)>& disp, const DisplacementFn& texture_disp, float uv_repeat,
                  std::vector<TreePart>& out) {
  for (const BranchDesc& b : branches) {
    const Eigen::Vector3d a = parent.axis_point(b.attach);
    const Eigen::Matrix3d f = parent.frame(b.attach);
    const double phi = b.azimuth_deg * M_PI / 180.0, ang = b.angle_deg * M_PI / 180.0;
    const Eigen::Vector3d radial = std::cos(phi) * f.col(1) + std::sin(phi) * f.col(2);
    const Eigen::Vector3d dir = std::cos(ang) * f.col(0) + std::sin(ang) * radial;
    std::vector<Eigen::Vector3d> axis;
    for (int k = 0; k <= 3; ++k) {
      const double t = k / 3.0;
      axis.push_back(a + dir * (b.length * t) + f.col(0) * (b.curvature * b.length * t * t));
    }
    std::vector<double> radius(b.radius.begin(), b.radius.end());
    auto cyl = std::make_shared<GeneralizedCylinder>(axis, radius, f.col(0));
    out.push_back(make_part(cyl, disp(out.size()), texture_disp, uv_repeat, mean(b.radius)));
    out.back().parent = parent_index;
    out.back().attach = b.attach;
    add_branches(*cyl, int(out.size()) - 1, b.branches, disp, texture_disp, uv_repeat, out);
  }
}

}  // namespace

std::vector<TreePart> build_tree(const TreeDesc& desc, const DisplacementFn& disp) {
  return build_tree(desc, [&](size_t) { return disp; });
}

std::vector<TreePart> build_tree(const TreeDesc& desc, const std::function<DisplacementFn(size_t)>& disp) {
  std::vector<Eigen::Vector3d> axis;
  for (const Vec3f& p : desc.axis) axis.push_back(p.cast<double>());
  std::vector<double> radius(desc.radius.begin(), desc.radius.end());
  auto trunk = std::make_shared<GeneralizedCylinder>(axis, radius, Eigen::Vector3d::UnitX());
  std::vector<TreePart> parts;
  // An image displacement is looked up where the albedo texture is: at the texcoords.
  const DisplacementFn texture_disp =
      desc.texture_displacement.type == DisplacementDesc::Type::None ? DisplacementFn{} : make_displacement(desc.texture_displacement);
  parts.push_back(make_part(trunk, disp(0), texture_disp, desc.uv_repeat, mean(desc.radius)));
  add_branches(*trunk, 0, desc.branches, disp, texture_disp, desc.uv_repeat, parts);
  return parts;
}

}  // namespace phellem
