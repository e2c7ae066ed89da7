// What the material tests share: the paper's six beam angles and rotations built from an axis and an angle.
#pragma once

#include <cmath>

#include "core/small_math.hpp"

namespace polymech::testing {

constexpr double kPi = 3.14159265358979323846;
// The beam-axis angles from [001] in the (110) plane of seed 002 paper 5; 54.7356 deg is exactly [1-11].
constexpr double kBeamAnglesDeg[6] = {0.0, 5.0, 10.0, 20.0, 30.0, 54.735610317245345};
inline double rad(double deg) { return deg * kPi / 180.0; }

// The rotation by `angle` about the unit axis w (Rodrigues): R = cos I + (1 - cos) w w^T + sin [w]x.
inline Mat3<double> axis_angle_rotation(const double (&w)[3], double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  Mat3<double> R;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const double cross = i == j ? 0.0 : ((j - i + 3) % 3 == 1 ? -1.0 : 1.0) * w[3 - i - j];
      R.a[i][j] = (i == j ? c : 0.0) + (1 - c) * w[i] * w[j] + s * cross;
    }
  return R;
}

}  // namespace polymech::testing
