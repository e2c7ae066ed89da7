// A straight crack in 2D (seed 000 §4, Fig. 1): a segment with centre c, unit tangent t and unit
// normal n = (-t3, t1) pointing from the lower face S- to the upper face S+. A bond (a, b) is cut when
// its end points lie on different sides and it crosses the line within the segment. A point exactly
// on the line counts as S+, so a crack through a row of particles acts as if it ran just below it.
// Host code (the crack is cut at set-up), free of Kokkos.
#pragma once

#include <cmath>

namespace polymech::contact {

struct CrackSegment {
  double c1 = 0, c3 = 0;  // centre
  double t1 = 1, t3 = 0;  // unit tangent (the shear direction s of eqs. (20)-(21))
  double n1 = 0, n3 = 1;  // unit normal, S- -> S+
  double half_length = 0;

  // angle_degrees: counter-clockwise from the x1 axis; 0 is a horizontal crack with S+ above.
  static CrackSegment make(double c1, double c3, double length, double angle_degrees) {
    CrackSegment s;
    const double a = angle_degrees * 3.14159265358979323846 / 180.0;
    s.c1 = c1;
    s.c3 = c3;
    s.t1 = std::cos(a);
    s.t3 = std::sin(a);
    s.n1 = -s.t3;
    s.n3 = s.t1;
    s.half_length = 0.5 * length;
    return s;
  }

  double side(double x1, double x3) const { return (x1 - c1) * n1 + (x3 - c3) * n3; }
  bool upper(double x1, double x3) const { return side(x1, x3) >= 0.0; }
  double along(double x1, double x3) const { return (x1 - c1) * t1 + (x3 - c3) * t3; }

  // Does the bond a -> b cross the crack segment?
  bool cuts(double a1, double a3, double b1, double b3) const {
    const double sa = side(a1, a3), sb = side(b1, b3);
    if ((sa >= 0.0) == (sb >= 0.0)) return false;
    const double w = sa / (sa - sb);  // where the bond meets the line
    const double tau = along(a1 + w * (b1 - a1), a3 + w * (b3 - a3));
    return tau >= -half_length && tau <= half_length;
  }
};

}  // namespace polymech::contact
