#include "bark/strips/strip_domain.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace phellem::bark {

namespace {

constexpr double kTwoPi = 6.283185307179586;

// Dilatation d(s, θ): sum of the user's Gaussian bulges (θ distance wraps).
double dilatation(const StripParams& p, double s, double theta) {
  double d = 0;
  for (const DilatationBulge& b : p.dilatation) {
    double dt = std::fmod(std::abs(theta - b.theta), kTwoPi);
    dt = std::min(dt, kTwoPi - dt);
    const double ds = s - b.s;
    d += b.amount * std::exp(-0.5 * (ds * ds / (b.sigma_s * b.sigma_s) + dt * dt / (b.sigma_theta * b.sigma_theta)));
  }
  return d;
}

void fill_exponents(const StripParams& p, StripMetric& m, int bins) {
  if (p.dilatation.empty()) return;
  m.exponent.resize(size_t(bins));
  for (int k = 0; k < bins; ++k) m.exponent[size_t(k)] = 1.0 + dilatation(p, m.s, kTwoPi * (k + 0.5) / bins);
}

// Refuses (rather than overflowing, or running for days) more strips than kMaxStrips.
int strip_count(double length, double width) {
  const double n = length / width;
  if (!(n <= kMaxStrips)) {
    std::ostringstream m;
    m << "must be at least " << length / kMaxStrips << " m here: the bark is " << length << " m across its strips, and " << width
      << " m strips would make " << n << " of them, more than the " << kMaxStrips << " a simulation allows";
    throw StripParamError{"strip_width", m.str()};
  }
  return std::max(1, int(std::lround(n)));
}

}  // namespace

StripDomain cylinder_domain(const GeneralizedCylinder& c, const StripParams& p, int bins) {
  StripDomain d;
  d.length = c.length();
  const int n = strip_count(d.length, p.strip_width);
  d.strip_width = d.length / n;
  d.cyclic = true;
  d.strips.resize(size_t(n));
  const double h = 0.25 * d.strip_width;
  // Strips are independent (each a few hundred surface points): measured in parallel.
  tbb::parallel_for(0, n, [&](int j) {
    StripMetric& m = d.strips[size_t(j)];
    m.s = (j + 0.5) * d.strip_width;
    m.bin_length.resize(size_t(bins));
    m.width.resize(size_t(bins));
    const double s0 = std::max(0.0, m.s - h), s1 = std::min(d.length, m.s + h);
    for (int k = 0; k < bins; ++k) {
      const double t0 = kTwoPi * k / bins, t1 = kTwoPi * (k + 1) / bins, tm = 0.5 * (t0 + t1);
      // Arc length of the bin: midpoint rule on |∂P/∂θ| over two halves (radius varies in θ).
      // GeneralizedCylinder takes s normalized to [0, 1].
      const double L = d.length;
      const Eigen::Vector3d a = c.position(m.s / L, t0), b = c.position(m.s / L, tm), e = c.position(m.s / L, t1);
      m.bin_length[size_t(k)] = (b - a).norm() + (e - b).norm();
      m.width[size_t(k)] = (c.position(s1 / L, tm) - c.position(s0 / L, tm)).norm() / (s1 - s0);
    }
    fill_exponents(p, m, bins);
  });
  return d;
}

StripDomain longitudinal_domain(const GeneralizedCylinder& c, const StripParams& p, int bins) {
  // Mean circumference over the length, from 16 sections × 32 chords.
  constexpr int kSections = 16, kChords = 32;
  auto circumference = [&](double u) {
    double sum = 0;
    for (int i = 0; i < kChords; ++i)
      sum += (c.position(u, kTwoPi * (i + 1) / kChords) - c.position(u, kTwoPi * i / kChords)).norm();
    return sum;
  };
  double mean = 0;
  for (int i = 0; i < kSections; ++i) mean += circumference((i + 0.5) / kSections) / kSections;
  StripDomain d;
  d.length = mean;
  const int n = std::max(3, strip_count(mean, p.strip_width));
  d.strip_width = mean / n;
  d.cyclic = false;  // strips end at the base and the top of the limb
  d.wrap_s = true;   // and close around it
  d.along_axis = true;
  d.axis_length = c.length();
  d.strips.resize(size_t(n));
  std::vector<double> local(static_cast<size_t>(bins));  // circumference at each bin's middle / mean
  for (int k = 0; k < bins; ++k) local[size_t(k)] = circumference((k + 0.5) / bins) / mean;
  tbb::parallel_for(0, n, [&](int j) {
    StripMetric& m = d.strips[size_t(j)];
    m.s = (j + 0.5) * d.strip_width;
    const double theta = kTwoPi * (j + 0.5) / n;
    m.bin_length.resize(size_t(bins));
    m.width = local;
    for (int k = 0; k < bins; ++k)
      m.bin_length[size_t(k)] = (c.position(double(k + 1) / bins, theta) - c.position(double(k) / bins, theta)).norm();
    if (!p.dilatation.empty()) {
      m.exponent.resize(size_t(bins));
      for (int k = 0; k < bins; ++k) m.exponent[size_t(k)] = 1.0 + dilatation(p, (k + 0.5) / bins * d.axis_length, theta);
    }
  });
  return d;
}

StripDomain oriented_domain(const GeneralizedCylinder& c, const StripParams& p) {
  return p.orientation == FractureOrientation::Horizontal ? longitudinal_domain(c, p) : cylinder_domain(c, p);
}

StripDomain flat_domain(double width, double height, const StripParams& p, int bins) {
  StripDomain d;
  d.length = height;
  const int n = strip_count(height, p.strip_width);
  d.strip_width = height / n;
  d.cyclic = p.tile_theta;
  d.wrap_s = p.tile_s;
  d.strips.resize(size_t(n));
  for (int j = 0; j < n; ++j) {
    StripMetric& m = d.strips[size_t(j)];
    m.s = (j + 0.5) * d.strip_width;
    m.bin_length.assign(size_t(bins), width / bins);
    m.width.assign(size_t(bins), 1.0);
    fill_exponents(p, m, bins);
  }
  return d;
}

}  // namespace phellem::bark
