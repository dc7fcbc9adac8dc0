#include "compare/cielab.h"

#include <Eigen/Dense>

#include <cmath>

namespace phellem {
namespace {

// CIE 15:2004 eq. 8.3: f(t) = t^(1/3) above (6/29)³, else t/(3·(6/29)²) + 4/29.
double lab_f(double t) {
  constexpr double d = 6.0 / 29.0;
  return t > d * d * d ? std::cbrt(t) : t / (3 * d * d) + 4.0 / 29.0;
}

}  // namespace

Eigen::Vector3d linear_rec709_to_lab(const Eigen::Vector3d& rgb) {
  // IEC 61966-2-1:1999, linear sRGB (Rec.709 primaries, D65) → XYZ.
  static const Eigen::Matrix3d M = (Eigen::Matrix3d() << 0.4124, 0.3576, 0.1805,  //
                                    0.2126, 0.7152, 0.0722,                       //
                                    0.0193, 0.1192, 0.9505)
                                       .finished();
  static const Eigen::Vector3d white = M * Eigen::Vector3d::Ones();  // D65: (0.9505, 1, 1.0890)
  const Eigen::Vector3d xyz = M * rgb;
  const double fx = lab_f(xyz[0] / white[0]), fy = lab_f(xyz[1] / white[1]), fz = lab_f(xyz[2] / white[2]);
  // CIE 15:2004 eq. 8.1–8.2.
  return {116 * fy - 16, 500 * (fx - fy), 200 * (fy - fz)};
}

}  // namespace phellem
