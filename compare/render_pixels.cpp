#include "compare/render_pixels.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <numbers>
#include <vector>

#include "compare/compare_params.h"
#include "util/errors.h"

namespace phellem {

namespace {

std::string number(double v, int digits) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", digits, v);
  return buf;
}

Eigen::Vector3d at3(const std::vector<float>& v, size_t p) { return {v[3 * p], v[3 * p + 1], v[3 * p + 2]}; }

// Median world distance (m) between the pixel pairs (p, p + step) that `inside` accepts, over
// the pixels `from` lists; 0 without pairs.
template <class Inside>
double median_spacing(const std::vector<float>& position, const std::vector<size_t>& from, size_t step, Inside inside) {
  std::vector<double> d;
  d.reserve(from.size());
  for (size_t p : from)
    if (inside(p)) d.push_back((at3(position, p + step) - at3(position, p)).norm());
  if (d.empty()) return 0;
  const auto mid = d.begin() + std::ptrdiff_t(d.size() / 2);
  std::nth_element(d.begin(), mid, d.end());
  if (d.size() % 2 == 1) return *mid;
  return 0.5 * (*mid + *std::max_element(d.begin(), mid));  // numpy's median of an even count
}

// The object covering most fully covered pixels (the smaller id on a tie), or the one chosen.
int choose_object(const RenderLayers& r, const RenderChoice& choice, const std::string& path, const std::string& label,
                  long long* pixels) {
  std::map<int, long long> count;
  for (size_t p = 0; p < r.object_id.size(); ++p)
    if (r.alpha[p] >= kFullCoverage && r.object_id[p] > 0) ++count[int(std::lround(r.object_id[p]))];
  if (count.empty())
    throw UserError(path, "render",
                    "no pixel is fully covered by an object (beauty.A ≥ " + number(kFullCoverage, 3) +
                        " and object_id > 0): there is no bark to measure in this render");
  if (choice.object_id) {
    const auto it = count.find(*choice.object_id);
    if (it == count.end()) {
      std::string present;
      int listed = 0;
      for (const auto& [id, n] : count)
        if (listed++ < 8) present += (present.empty() ? "" : ", ") + std::to_string(id) + " (" + std::to_string(n) + " px)";
      if (count.size() > 8) present += ", …";
      throw UserError(path, "--object " + label,
                      "object " + std::to_string(*choice.object_id) + " covers no pixel of this render; the objects it shows: " +
                          present);
    }
    *pixels = it->second;
    return it->first;
  }
  auto best = count.begin();
  for (auto it = count.begin(); it != count.end(); ++it)
    if (it->second > best->second) best = it;
  *pixels = best->second;
  return best->first;
}

// Box sums of the object's normals over [x − rx, x + rx] × [y − ry, y + ry] (summed-area table).
struct NormalBoxes {
  int w, h;
  std::vector<Eigen::Vector3d> sat;  // (w + 1) × (h + 1)
  NormalBoxes(const std::vector<float>& normal, const std::vector<uint8_t>& object, int w_, int h_)
      : w(w_), h(h_), sat(size_t(w_ + 1) * size_t(h_ + 1), Eigen::Vector3d::Zero()) {
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        const size_t p = size_t(y) * size_t(w) + size_t(x);
        const Eigen::Vector3d n = object[p] ? at3(normal, p) : Eigen::Vector3d::Zero();
        at(x + 1, y + 1) = n + at(x, y + 1) + at(x + 1, y) - at(x, y);
      }
  }
  Eigen::Vector3d& at(int x, int y) { return sat[size_t(y) * size_t(w + 1) + size_t(x)]; }
  const Eigen::Vector3d& at(int x, int y) const { return sat[size_t(y) * size_t(w + 1) + size_t(x)]; }
  Eigen::Vector3d box(int x, int y, int rx, int ry) const {
    const int x0 = std::max(0, x - rx), x1 = std::min(w, x + rx + 1), y0 = std::max(0, y - ry), y1 = std::min(h, y + ry + 1);
    return at(x1, y1) - at(x0, y1) - at(x1, y0) + at(x0, y0);
  }
};

}  // namespace

RenderSelection render_selection(const HeightImage& render, const RenderChoice& choice, const std::string& path,
                                 const std::string& label) {
  const RenderLayers& r = *render.render;
  const int w = render.width, h = render.height;
  const size_t n = size_t(w) * size_t(h);
  RenderSelection s;
  s.render_width = w;
  s.render_height = h;
  s.facing_deg = choice.facing_deg;
  s.object_chosen = choice.object_id.has_value();
  s.camera_known = r.camera.has_value();
  s.object_id = choose_object(r, choice, path, label, &s.object_pixels);

  std::vector<uint8_t> object(n, 0);
  std::vector<size_t> object_list;
  for (size_t p = 0; p < n; ++p)
    if (r.alpha[p] >= kFullCoverage && r.object_id[p] > 0 && int(std::lround(r.object_id[p])) == s.object_id) {
      object[p] = 1;
      object_list.push_back(p);
    }

  // Facing the camera: the angle between the normal (averaged over ±kFacingWindowCm among the
  // object's pixels, at the object's own scale) and the direction from the surface to the camera.
  std::vector<uint8_t> mask = object;
  if (choice.facing_deg < 180) {
    if (!r.camera)
      throw UserError(path, "--facing-deg " + label,
                      "this render states no camera position (no " + std::string(kCameraPositionAttribute) + " or " +
                          kWorldToCameraAttribute +
                          " in its header: rendered before phellem wrote them?), so which pixels face the camera is unknown: "
                          "render it again, or give --facing-deg " +
                          label + "=180 to keep the pixels whatever way they face");
    const double sx = median_spacing(r.position, object_list, 1, [&](size_t p) { return int(p % size_t(w)) + 1 < w && object[p + 1]; });
    const double sy = median_spacing(r.position, object_list, size_t(w), [&](size_t p) { return p + size_t(w) < n && object[p + size_t(w)]; });
    const int rx = sx > 0 ? int(std::lround(std::min(kFacingWindowCm / (100 * sx), double(w)))) : 0;
    const int ry = sy > 0 ? int(std::lround(std::min(kFacingWindowCm / (100 * sy), double(h)))) : 0;
    const NormalBoxes boxes(r.normal, object, w, h);
    const double cos_limit = std::cos(choice.facing_deg * std::numbers::pi / 180);
    for (size_t p : object_list) {
      const Eigen::Vector3d nbar = boxes.box(int(p % size_t(w)), int(p / size_t(w)), rx, ry);
      const Eigen::Vector3d view = *r.camera - at3(r.position, p);
      const double len = nbar.norm() * view.norm();
      if (!(len > 0) || nbar.dot(view) < cos_limit * len) mask[p] = 0;
    }
  }
  for (uint8_t m : mask) s.mask_pixels += m;
  if (s.mask_pixels == 0)
    throw UserError(path, "render",
                    "none of the " + std::to_string(s.object_pixels) + " pixels of object " + std::to_string(s.object_id) +
                        " faces the camera within " + number(choice.facing_deg, 0) + "°: give --facing-deg " + label +
                        "=DEG with a larger angle, or --object " + label + "=ID for another object");
  s.rect = maximal_rectangle(mask, w, h);
  const PixelRect& q = s.rect;

  // The scale over the rectangle: every pixel in it is on the bark.
  std::vector<size_t> inside;
  inside.reserve(size_t(q.area()));
  for (int y = q.y; y < q.y + q.height; ++y)
    for (int x = q.x; x < q.x + q.width; ++x) inside.push_back(size_t(y) * size_t(w) + size_t(x));
  const double dx = median_spacing(r.position, inside, 1, [&](size_t p) { return int(p % size_t(w)) + 1 < q.x + q.width; });
  const double dy = median_spacing(r.position, inside, size_t(w), [&](size_t p) { return int(p / size_t(w)) + 1 < q.y + q.height; });
  s.position_px_per_cm_x = dx > 0 ? 1 / (100 * dx) : 0;
  s.position_px_per_cm_y = dy > 0 ? 1 / (100 * dy) : 0;
  return s;
}

SelectedRender select_render_pixels(const HeightImage& render, const RenderChoice& choice, const std::string& path,
                                    const std::string& label, std::optional<double> px_per_cm) {
  const RenderLayers& r = *render.render;
  const int w = render.width;
  SelectedRender out;
  out.selection = render_selection(render, choice, path, label);
  const RenderSelection& s = out.selection;
  const PixelRect& q = s.rect;
  const std::string what = "bark pixels (fully covered by object " + std::to_string(s.object_id) +
                           (choice.facing_deg < 180 ? ", facing the camera within " + number(choice.facing_deg, 0) + "°" : "") + ")";
  const std::string found = "the largest rectangle of " + what + " is " + std::to_string(q.width) + "×" +
                            std::to_string(q.height) + " px at (" + std::to_string(q.x) + ", " + std::to_string(q.y) + ")";
  const double scale_x = px_per_cm ? *px_per_cm : s.position_px_per_cm_x, scale_y = px_per_cm ? *px_per_cm : s.position_px_per_cm_y;
  if (!px_per_cm && (!(s.position_px_per_cm_x > 0) || !(s.position_px_per_cm_y > 0) || !std::isfinite(scale_x) ||
                     !std::isfinite(scale_y)))
    throw UserError(path, "position",
                    found + ", but its positions do not change between neighbouring pixels, so its scale is unknown: give --scale " +
                        label + "=PX_PER_CM");
  const CompareParams& P = kCompareParams;
  const double w_cm = q.width / scale_x, h_cm = q.height / scale_y;
  if (q.width < P.min_size_px || q.height < P.min_size_px || w_cm < P.min_size_cm || h_cm < P.min_size_cm)
    throw UserError(path, "render",
                    found + ", " + number(w_cm, 1) + "×" + number(h_cm, 1) + " cm at " + number(scale_x, 2) +
                        (scale_x != scale_y ? "×" + number(scale_y, 2) : "") + " px/cm (of " + std::to_string(s.mask_pixels) +
                        " such pixels); compare needs at least " + std::to_string(P.min_size_px) + " px and " +
                        number(P.min_size_cm, 0) + " cm on each side: render the bark larger in the frame (closer, or more pixels), "
                        "give --facing-deg " + label + "=DEG with a larger angle, or --object " + label + "=ID for another object");

  HeightImage& im = out.image;
  im.kind = HeightImage::Kind::render;
  im.width = q.width;
  im.height = q.height;
  im.px_per_cm_x = s.position_px_per_cm_x;
  im.px_per_cm_y = s.position_px_per_cm_y;
  im.z.reserve(size_t(q.area()));
  for (int y = q.y; y < q.y + q.height; ++y)
    for (int x = q.x; x < q.x + q.width; ++x) im.z.push_back(render.z[size_t(y) * size_t(w) + size_t(x)]);
  if (!r.albedo.empty()) {
    RgbImage a;
    a.width = q.width;
    a.height = q.height;
    a.rgb.reserve(size_t(q.area()) * 3);
    for (int y = q.y; y < q.y + q.height; ++y)
      for (int x = q.x; x < q.x + q.width; ++x)
        for (int c = 0; c < 3; ++c) a.rgb.push_back(r.albedo[3 * (size_t(y) * size_t(w) + size_t(x)) + size_t(c)]);
    out.albedo = std::move(a);
  }
  return out;
}

}  // namespace phellem
