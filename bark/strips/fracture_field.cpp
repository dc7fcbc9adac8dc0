#include "bark/strips/fracture_field.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <unordered_map>

namespace phellem::bark {

namespace {
constexpr double kTwoPi = 6.283185307179586;

struct Span {
  double left, right;  // θ of the lips (left < right, unwrapped)
  float id, age, level;
  OpeningMode mode;
  double width_m;  // opening in metres
};

struct StripSpans {
  std::vector<Span> spans;  // by fracture element index
  std::vector<char> valid;  // 1 where the fracture element is still open (not hardened)
};

}  // namespace

double DepthProfile::evaluate(double q) const {
  q = std::clamp(q, 0.0, 1.0);
  switch (shape) {
    case DepthProfileShape::V:
      return q;
    case DepthProfileShape::U:
      return 1.0 - (1.0 - q) * (1.0 - q);
    case DepthProfileShape::Box:
      return q > 0.05 ? 1.0 : q / 0.05;
    case DepthProfileShape::Round:
      return std::sqrt(std::max(0.0, 1.0 - (1.0 - q) * (1.0 - q)));
    case DepthProfileShape::Power:
      return 1.0 - std::pow(1.0 - q, exponent);
  }
  return q;
}

namespace {

// The field in the strips' own space: columns along the strips, rows across them.
FractureField rasterize_strips(const StripModel& model, int W, int H, const DepthProfile& profile) {
  const auto& strips = model.strips();
  const auto& dom = model.domain();
  const size_t n = strips.size();
  FractureField f;
  f.width = W;
  f.height = H;
  f.length = dom.length;
  for (const Strip& s : strips) f.circumference += s.circumference / double(n);
  const size_t px = size_t(W) * H;
  f.opening.assign(px, 0);
  f.depth.assign(px, 0);
  f.uv0.assign(2 * px, 0);
  f.interior.assign(px, 0);
  f.fracture_id.assign(px, 0);
  f.age.assign(px, 0);
  f.level.assign(px, 0);
  f.color.assign(3 * px, 0);

  // Canonical fracture ids: skeleton roots numbered in order of first appearance.
  std::unordered_map<int32_t, int32_t> canon;
  for (const Strip& s : strips)
    for (const FractureElement& fe : s.fractures) {
      const int32_t r = model.skeleton().find(fe.id);
      canon.emplace(r, int32_t(canon.size()) + 1);
    }
  std::vector<StripSpans> spans(n);
  tbb::parallel_for(size_t(0), n, [&](size_t j) {
    const Strip& s = strips[j];
    StripSpans& ss = spans[j];
    ss.spans.resize(s.fractures.size());
    ss.valid.assign(s.fractures.size(), 0);
    for (size_t i = 0; i < s.size(); ++i) {
      const Element& e = s.elements[i];
      if (e.kind != ElementKind::Fracture) continue;
      const FractureElement& fe = s.fractures[size_t(e.fracture)];
      Span sp;
      sp.left = model.theta_of(j, s.x[i]);
      sp.right = model.theta_of(j, s.x[i] + s.length(i));
      if (sp.right < sp.left) sp.right += kTwoPi;
      const int32_t root = model.skeleton().find(fe.id);
      sp.id = float(canon.at(root));
      sp.age = float(model.steps_done() - fe.birth);
      sp.level = float(e.level);
      sp.mode = model.opening_mode(root);
      // Width on the final surface (the field is in the final parameter space).
      sp.width_m = s.length(i) / model.scale_at_step(model.steps_done());
      ss.spans[size_t(e.fracture)] = sp;
      ss.valid[size_t(e.fracture)] = 1;
    }
  });

  const double ws = dom.strip_width;
  const double dtheta = kTwoPi / W;
  tbb::parallel_for(0, H, [&](int y) {
    const double s = (y + 0.5) / H * dom.length;
    // Bracketing strips j0 (below) and j1 (above), blend t ∈ [0, 1).
    const double fj = s / ws - 0.5;
    long j0 = long(std::floor(fj)), j1 = j0 + 1;
    double t = fj - double(j0);
    auto valid_strip = [&](long j) { return j >= 0 && j < long(n); };
    if (dom.wrap_s) {
      j0 = (j0 % long(n) + long(n)) % long(n);
      j1 = (j1 % long(n) + long(n)) % long(n);
    }
    // Epidermis: material coordinate of each column, blended between the two strips.
    auto material_row = [&](long j, std::vector<double>& out, std::vector<float>& lvl) {
      const Strip& st = strips[size_t(j)];
      const double E0 = st.original_epidermis();
      out.resize(size_t(W));
      lvl.resize(size_t(W));
      for (int x = 0; x < W; ++x) {
        const double th = (x + 0.5) * dtheta;
        const double xs = model.x_of(size_t(j), th);
        const size_t i = model.element_at(size_t(j), xs);
        const Element& e = st.elements[i];
        double off = xs - st.x[i];
        if (st.cyclic) off -= std::floor(off / st.circumference) * st.circumference;
        const double L = st.length(i);
        const double frac = L > 0 ? std::clamp(off / L, 0.0, 1.0) : 0.0;
        const double m0 = st.cold[i].material,
                     m = e.kind == ElementKind::Epidermis && e.level == 0 ? m0 + frac * e.rest / E0 : m0;
        out[size_t(x)] = m - std::floor(m);
        lvl[size_t(x)] = float(e.level);
      }
    };
    std::vector<double> m0, m1;
    std::vector<float> l0, l1;
    const long ja = valid_strip(j0) ? j0 : j1, jb = valid_strip(j1) ? j1 : j0;
    material_row(ja, m0, l0);
    material_row(jb, m1, l1);
    const double tb = (ja == jb) ? 0.0 : t;
    for (int x = 0; x < W; ++x) {
      const size_t p = f.index(x, y);
      double a = m0[size_t(x)], b = m1[size_t(x)];
      if (b - a > 0.5) b -= 1;
      if (a - b > 0.5) b += 1;
      const double m = a + tb * (b - a);
      f.uv0[2 * p] = float(m - std::floor(m));
      f.uv0[2 * p + 1] = float(s / dom.length);
      f.level[p] = tb < 0.5 ? l0[size_t(x)] : l1[size_t(x)];
    }

    // Fracture spans at this row.
    auto draw = [&](double left, double right, const Span& sp, double width_m) {
      if (!(right > left)) return;
      const int x0 = int(std::floor(left / dtheta)), x1 = int(std::floor(right / dtheta));
      const double depth_scale = std::min(profile.max_depth, profile.depth_per_width * width_m);
      for (int xi = x0; xi <= x1; ++xi) {
        const double c0 = xi * dtheta, c1 = c0 + dtheta;
        const double cover = (std::min(c1, right) - std::max(c0, left)) / dtheta;
        if (cover <= 0) continue;
        const int x = ((xi % W) + W) % W;
        const size_t p = f.index(x, y);
        const double mid = std::clamp(0.5 * (c0 + c1), left, right);
        const double a = (mid - left) / (right - left);  // 0 at the left lip, 1 at the right
        const double q = 1.0 - std::abs(2.0 * a - 1.0);  // 0 at the lips, 1 on the axis
        if (cover > f.opening[p]) {
          f.fracture_id[p] = sp.id;
          f.age[p] = sp.age;
          f.level[p] = sp.level;
          f.interior[p] = float(sp.mode == OpeningMode::Axis ? 1.0 - q : sp.mode == OpeningMode::OneSide ? a : q);
        }
        f.opening[p] = float(std::min(1.0, std::max(double(f.opening[p]), cover)));
        f.depth[p] = std::max(f.depth[p], float(depth_scale * profile.evaluate(q)));
      }
    };
    auto lerp_span = [&](const Span& a, const Span& b, double u) {
      // Unwrap b next to a.
      double off = std::round(((b.left + b.right) - (a.left + a.right)) * 0.5 / kTwoPi) * kTwoPi;
      const double l = a.left + u * (b.left - off - a.left), r = a.right + u * (b.right - off - a.right);
      draw(l, r, u < 0.5 ? a : b, a.width_m + u * (b.width_m - a.width_m));
    };
    auto tip = [&](const Span& a, double u) {
      // A tip closes half a strip beyond its element as a half-ellipse.
      if (u >= 0.5) return;
      const double k = std::sqrt(std::max(0.0, 1.0 - (u / 0.5) * (u / 0.5)));
      const double c = 0.5 * (a.left + a.right), h = 0.5 * (a.right - a.left) * k;
      draw(c - h, c + h, a, a.width_m * k);
    };
    if (valid_strip(j0)) {
      const Strip& s0 = strips[size_t(j0)];
      const StripSpans& sp0 = spans[size_t(j0)];
      for (size_t k = 0; k < s0.fractures.size(); ++k) {
        if (!sp0.valid[k]) continue;
        const int32_t up = s0.fractures[k].up;
        if (up >= 0 && valid_strip(j1) && spans[size_t(j1)].valid[size_t(up)])
          lerp_span(sp0.spans[k], spans[size_t(j1)].spans[size_t(up)], t);
        else
          tip(sp0.spans[k], t);
      }
    }
    if (valid_strip(j1)) {
      const Strip& s1 = strips[size_t(j1)];
      const StripSpans& sp1 = spans[size_t(j1)];
      for (size_t k = 0; k < s1.fractures.size(); ++k) {
        if (!sp1.valid[k]) continue;
        const int32_t down = s1.fractures[k].down;
        const bool linked = down >= 0 && valid_strip(j0) && spans[size_t(j0)].valid[size_t(down)];
        if (!linked) {
          tip(sp1.spans[k], 1.0 - t);
        } else if (strips[size_t(j0)].fractures[size_t(down)].up != int32_t(k)) {
          // A merge: this element links down to an element that continues elsewhere.
          lerp_span(spans[size_t(j0)].spans[size_t(down)], sp1.spans[k], t);
        }
      }
    }
  });
  return f;
}

// Strips along the axis: the strips' space is the bark's transposed.
FractureField transpose(const FractureField& t) {
  FractureField f;
  f.width = t.height;
  f.height = t.width;
  const size_t px = size_t(f.width) * f.height;
  auto resize = [&](std::vector<float>& v, int channels) { v.assign(px * size_t(channels), 0.0f); };
  resize(f.opening, 1), resize(f.depth, 1), resize(f.uv0, 2), resize(f.interior, 1);
  resize(f.fracture_id, 1), resize(f.age, 1), resize(f.level, 1), resize(f.color, 3);
  for (int y = 0; y < f.height; ++y)
    for (int x = 0; x < f.width; ++x) {
      const size_t p = f.index(x, y), q = t.index(y, x);
      f.opening[p] = t.opening[q];
      f.depth[p] = t.depth[q];
      f.interior[p] = t.interior[q];
      f.fracture_id[p] = t.fracture_id[q];
      f.age[p] = t.age[q];
      f.level[p] = t.level[q];
      // Around: the angle; along: the material coordinate (plates carry their texture along
      // the axis as they are pulled apart).
      f.uv0[2 * p] = t.uv0[2 * q + 1];
      f.uv0[2 * p + 1] = t.uv0[2 * q];
    }
  return f;
}

}  // namespace

FractureField rasterize(const StripModel& model, int W, int H, const DepthProfile& profile) {
  if (!model.domain().along_axis) return rasterize_strips(model, W, H, profile);
  FractureField f = transpose(rasterize_strips(model, H, W, profile));
  f.length = model.domain().axis_length;
  f.circumference = model.domain().length;
  return f;
}

}  // namespace phellem::bark
