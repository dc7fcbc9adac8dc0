#include "scene/strip_bark_tree.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "bark/dressing/bark_relief.h"
#include "bark/dressing/fracture_mesh.h"
#include "util/errors.h"
#include "util/progress.h"

namespace phellem {

TreeStripSimulation::TreeStripSimulation(const ObjectDesc& obj, size_t oi, std::optional<uint64_t> seed)
    : desc_(obj.tree.strip_bark) {
  if (!desc_) throw std::logic_error("TreeStripSimulation: the tree has no strip bark");
  parts_ = build_tree(obj.tree, [](const Vec2f&, const Vec3f&) { return 0.0f; });
  std::vector<bark::TreeCylinder> cylinders;
  for (const TreePart& p : parts_) cylinders.push_back({p.cylinder, p.parent, p.attach});
  bark::StripParams params = desc_->params;
  if (seed) params.seed = *seed;
  try {
    sim_ = std::make_unique<bark::TreeStripBark>(std::move(cylinders), params);
  } catch (const bark::StripParamError& e) {
    // The models re-check S against the softest element they actually built (strips narrower
    // than nominal on bent limbs are softer): report it at the scene's JSON path.
    throw UserError(obj.where.file, "/objects/" + std::to_string(oi) + "/bark/" + e.key, e.key + ": " + e.message);
  }
  label_ = "simulate " + (obj.name.empty() ? "tree" + std::to_string(oi) : obj.name);
}

void TreeStripSimulation::run_to(int step, bool progress) {
  step = std::min(step, steps_total());
  if (steps_done() >= step) return;
  Progress bar(label_, step - steps_done(), progress);
  // The simulation advances by blocks of steps (bark::kBlockSteps): a frame shows the end of
  // the block its step falls in.
  while (steps_done() < step) {
    const int before = steps_done();
    sim_->step();
    bar.advance(steps_done() - before);
  }
  sim_->settle();  // a growth frame reads this intermediate state
  bar.finish();
}

namespace {

// Mean circumference of the model's strips in the current state (m).
double mean_circumference(const bark::StripModel& model) {
  double C = 0;
  for (const auto& st : model.strips()) C += st.circumference / double(model.strips().size());
  return C;
}

// Field size for texels 1/`texels_per_strip` of a strip wide at the final size, and at most
// `max_texel` m (wide strips, as fits choose, keep narrow fissures sharp), at least
// min_w × min_h and at most max × max.
void automatic_size(const bark::StripModel& model, int texels_per_strip, double max_texel, int min_w, int min_h, int max, int* W,
                    int* H) {
  const double texel = std::min(max_texel, model.domain().strip_width / texels_per_strip);
  // Final extent along the strips and across them; strips along the axis swap the two.
  const double along = mean_circumference(model) / model.scale_at_step(model.steps_done()), across = model.domain().length;
  const bool axial = model.domain().along_axis;
  *W = std::clamp(int(std::lround((axial ? across : along) / texel)), min_w, max);
  *H = std::clamp(int(std::lround((axial ? model.domain().axis_length : across) / texel)), min_h, max);
}

}  // namespace

bark::FractureField TreeStripSimulation::field(size_t k, int W, int H) const {
  const bark::StripModel& model = sim_->model(k);
  if (W <= 0 || H <= 0) {
    W = desc_->field_width;
    H = desc_->field_height;
  }
  // Texels a quarter of a strip wide and at most 1.25 mm (a quarter of the presets' 5 mm
  // strips): fracture edges stay sharp in close-ups.
  if (W <= 0 || H <= 0) automatic_size(model, 4, 0.00125, 64, 16, 8192, &W, &H);
  bark::FractureField f = bark::rasterize(model, W, H, desc_->depth);
  bark::apply_relief(f, desc_->relief, desc_->depth);
  // Circumference of the epidermis when it formed: the texture's period around (UV0 × C0).
  // Strips along the axis grow in length only, and their UV0 around is the angle.
  const double C0 = model.domain().along_axis
                        ? model.domain().length
                        : mean_circumference(model) * model.scale_at_step(0) / model.scale_at_step(model.steps_done());
  bark::dress_colors(f, desc_->colors, desc_->depth.max_depth, C0);
  return f;
}

GlbMesh TreeStripSimulation::mesh(size_t k, int W, int H) const {
  const bark::StripModel& model = sim_->model(k);
  if (W <= 0 || H <= 0) automatic_size(model, 2, 0.0025, 32, 8, 4096, &W, &H);
  const bark::FractureField f = bark::rasterize(model, W, H, desc_->depth);
  const bark::FractureMesh fm = bark::mesh_fracture_field(f, desc_->depth.max_depth);
  const bark::GeneralizedCylinder& cyl = *parts_[k].cylinder;
  GlbMesh out;
  MeshData& all = out.vertices;
  for (size_t v = 0; v < fm.param.size(); ++v) {
    const double s = fm.param[v].y() / H, theta = 2 * M_PI * fm.param[v].x() / W;
    const Eigen::Vector3d p = cyl.position(s, theta) - cyl.normal(s, theta) * double(fm.depth[v]);
    all.positions.push_back(p.cast<float>());
    all.uvs.emplace_back(float(fm.param[v].x() / W), float(s));
  }
  for (const auto& t : fm.triangles) all.indices.insert(all.indices.end(), {uint32_t(t[0]), uint32_t(t[1]), uint32_t(t[2])});
  compute_vertex_normals(all);
  // The seam's two columns of vertices (θ = 0 and 2π) share their normal.
  std::map<double, std::pair<int, int>> twins;
  for (size_t v = 0; v < fm.param.size(); ++v) {
    if (fm.param[v].x() == 0) twins[fm.param[v].y()].first = int(v) + 1;
    if (fm.param[v].x() == W) twins[fm.param[v].y()].second = int(v) + 1;
  }
  for (const auto& [y, pair] : twins)
    if (pair.first && pair.second) {
      const Vec3f n = (all.normals[pair.first - 1] + all.normals[pair.second - 1]).normalized();
      all.normals[pair.first - 1] = all.normals[pair.second - 1] = n;
    }
  const bark::FieldColors& c = desc_->colors;
  std::vector<GlbPart>& parts = out.parts;
  parts.resize(2);
  parts[0].name = "epidermis";
  parts[0].base_color = Color(c.epidermis.base.x(), c.epidermis.base.y(), c.epidermis.base.z());
  parts[1].name = "fracture";
  parts[1].base_color = Color(c.fracture.base.x(), c.fracture.base.y(), c.fracture.base.z());
  for (size_t t = 0; t < fm.triangles.size(); ++t)
    for (int i = 0; i < 3; ++i) parts[fm.fracture[t] ? 1 : 0].indices.push_back(uint32_t(fm.triangles[t][i]));
  return out;
}

std::vector<std::shared_ptr<const bark::FieldBarkSurface>> TreeStripSimulation::surfaces() const {
  std::vector<std::shared_ptr<const bark::FieldBarkSurface>> out;
  for (size_t k = 0; k < parts_.size(); ++k)
    out.push_back(std::make_shared<bark::FieldBarkSurface>(field(k), desc_->depth.max_depth));
  return out;
}

}  // namespace phellem
