// CIE 1976 L*a*b* of linear Rec.709 RGB under D65 (the lit statistics' colour, issue 44 item 2).
#pragma once

#include <Eigen/Core>

namespace phellem {

// Linear Rec.709/sRGB → XYZ (IEC 61966-2-1, the 4-decimal matrix) → L*a*b* (CIE 15:2004, eq. 8.1–8.3)
// with the reference white taken as XYZ of RGB (1, 1, 1) (D65, Y = 1), so that grey is exactly
// neutral. Lab of RGB (1, 1, 1) is (100, 0, 0). Negative channels are allowed (the cube root is
// continued by the linear segment of f below (6/29)³).
Eigen::Vector3d linear_rec709_to_lab(const Eigen::Vector3d& rgb);

}  // namespace phellem
