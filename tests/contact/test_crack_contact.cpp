// Crack-face contact kernels (seed 000 eqs. (17)-(21)) on hand-made pairs, against forces computed by
// hand: the penalty repulsion, the stick spring, the stick -> slip transition at mu_s |f'_n|, the
// kinetic force mu_d |f'_n|, the slip -> stick transition with a new anchor, and Newton's third law
// of the gathered forces. In double and in float (overlaps of 1e-10 m on 5e-5 m spacings).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "contact/crack_faces.hpp"

namespace pm = polymech;
namespace ct = polymech::contact;

namespace {

constexpr double l0 = 5e-5, mass = 7850 * l0 * l0, dt = 2e-9;

template <class T>
struct Fixture {
  // Particles: 0 (S+) at (0, l0/2), 1 (S-) at (0, -l0/2), 2 (S-) at (l0, -l0/2); pairs (0,1) and (0,2).
  ct::CrackPairs<T> pairs;
  ct::CrackContactState<T> st;
  ct::CrackContactParams<T> p;
  pm::VecView<T, 2> u{"u", 3}, v{"v", 3}, a{"a", 3};

  Fixture(int npairs, bool open_close, bool slip, double preload) {
    const std::vector<std::array<int, 2>> ends = {{0, 1}, {0, 2}};
    pairs.plus = pm::View1<pm::Index>("plus", npairs);
    pairs.minus = pm::View1<pm::Index>("minus", npairs);
    pairs.r0 = pm::VecView<T, 2>("r0", npairs);
    pairs.d0 = pm::View1<T>("d0", npairs);
    auto hp = Kokkos::create_mirror_view(pairs.plus);
    auto hm = Kokkos::create_mirror_view(pairs.minus);
    auto hr = Kokkos::create_mirror_view(pairs.r0);
    auto hd = Kokkos::create_mirror_view(pairs.d0);
    const double x[3][2] = {{0, l0 / 2}, {0, -l0 / 2}, {l0, -l0 / 2}};
    for (int k = 0; k < npairs; ++k) {
      hp(k) = ends[k][0];
      hm(k) = ends[k][1];
      hr(k, 0) = T(x[ends[k][1]][0] - x[ends[k][0]][0]);
      hr(k, 1) = T(x[ends[k][1]][1] - x[ends[k][0]][1]);
      hd(k) = T(std::hypot(double(hr(k, 0)), double(hr(k, 1))));
    }
    Kokkos::deep_copy(pairs.plus, hp);
    Kokkos::deep_copy(pairs.minus, hm);
    Kokkos::deep_copy(pairs.r0, hr);
    Kokkos::deep_copy(pairs.d0, hd);
    // gather lists: particle 0 has every pair, particles 1 and 2 one each
    pairs.face_particles = pm::View1<pm::Index>("faces", npairs + 1);
    pairs.face_offsets = Kokkos::View<pm::Offset*, pm::MemSpace>("foff", npairs + 2);
    pairs.face_pairs = pm::View1<pm::Index>("fpairs", 2 * npairs);
    auto hf = Kokkos::create_mirror_view(pairs.face_particles);
    auto ho = Kokkos::create_mirror_view(pairs.face_offsets);
    auto hfp = Kokkos::create_mirror_view(pairs.face_pairs);
    hf(0) = 0;
    ho(0) = 0;
    for (int k = 0; k < npairs; ++k) hfp(k) = k;
    ho(1) = npairs;
    for (int k = 0; k < npairs; ++k) {
      hf(k + 1) = ends[k][1];
      hfp(npairs + k) = k;
      ho(k + 2) = npairs + k + 1;
    }
    Kokkos::deep_copy(pairs.face_particles, hf);
    Kokkos::deep_copy(pairs.face_offsets, ho);
    Kokkos::deep_copy(pairs.face_pairs, hfp);

    st.state = Kokkos::View<int*, pm::MemSpace>("state", npairs);
    st.force = pm::VecView<T, 2>("force", npairs);
    if (open_close && slip) st.normal_force = pm::View1<T>("fn", npairs);
    if (slip) {
      st.du_anchor = pm::VecView<T, 2>("anchor", npairs);
      st.slip_sign = Kokkos::View<int*, pm::MemSpace>("sign", npairs);
      st.preload = pm::View1<T>("preload", npairs);
      Kokkos::deep_copy(st.preload, T(preload));
    }
    Kokkos::deep_copy(st.state, int(open_close ? ct::pair_separation : ct::pair_stick));
    p.kn = T(0.1 * mass / (dt * dt));
    p.ks = p.kn;
    p.mu_s = T(0.74);
    p.mu_d = T(0.57);
    p.s = pm::Vec2<T>{{T(1), T(0)}};
  }

  void set(const pm::VecView<T, 2>& view, int i, double x, double y) {
    auto h = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), view);
    h(i, 0) = T(x);
    h(i, 1) = T(y);
    Kokkos::deep_copy(view, h);
  }
  std::array<double, 2> accel(int i) {
    auto h = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), a);
    return {double(h(i, 0)), double(h(i, 1))};
  }
  int state(int k) {
    auto h = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), st.state);
    return h(k);
  }
  void apply() {
    Kokkos::deep_copy(a, T(0));
    ct::crack_apply_forces(pairs, st, a, T(mass));
  }
};

template <class T>
void check_open_close(double tol) {
  Fixture<T> fx(1, true, false, 0.0);
  const double delta = 1e-10, kn = 0.1 * mass / (dt * dt);
  fx.set(fx.u, 1, 0.0, delta);  // S- moves up by delta: overlap delta (eq. (17): stick)
  ct::crack_open_close<T, false>(fx.pairs, fx.st, fx.u, fx.p);
  fx.apply();
  EXPECT_EQ(fx.state(0), ct::pair_stick);
  // eq. (18): f_i = -kn (l0 - |r|) r / |r| with r pointing down: i is pushed up, j down
  EXPECT_NEAR(fx.accel(0)[1], kn * delta / mass, tol * kn * delta / mass);
  EXPECT_NEAR(fx.accel(1)[1], -kn * delta / mass, tol * kn * delta / mass);
  EXPECT_EQ(fx.accel(0)[0], 0.0);
  fx.set(fx.u, 1, 0.0, -delta);  // pulled apart: separation, no force
  ct::crack_open_close<T, false>(fx.pairs, fx.st, fx.u, fx.p);
  fx.apply();
  EXPECT_EQ(fx.state(0), ct::pair_separation);
  EXPECT_EQ(fx.accel(0)[1], 0.0);
  EXPECT_EQ(fx.accel(1)[1], 0.0);
}

template <class T>
void check_slip_cycle(double tol) {
  const double fn = 1e-3;  // fixed normal reaction [N/m]
  Fixture<T> fx(1, false, true, fn);
  const double ks = 0.1 * mass / (dt * dt);
  // stick: relative tangential displacement d with ks d = 0.5 mu_s fn
  const double d1 = 0.5 * 0.74 * fn / ks;
  fx.set(fx.u, 1, d1, 0.0);
  ct::crack_slip<T, false>(fx.pairs, fx.st, fx.u, fx.v, fx.p);
  fx.apply();
  EXPECT_EQ(fx.state(0), ct::pair_stick);
  EXPECT_NEAR(fx.accel(0)[0] * mass, ks * d1, tol * ks * d1);  // eq. (21) stick: drags i along j
  EXPECT_NEAR(fx.accel(1)[0] * mass, -ks * d1, tol * ks * d1);
  // beyond the static limit: slip with the kinetic force mu_d fn in the same direction
  const double d2 = 1.5 * 0.74 * fn / ks;
  fx.set(fx.u, 1, d2, 0.0);
  fx.set(fx.v, 1, 1e-3, 0.0);  // j still sliding forward
  ct::crack_slip<T, false>(fx.pairs, fx.st, fx.u, fx.v, fx.p);
  fx.apply();
  EXPECT_EQ(fx.state(0), ct::pair_slip);
  EXPECT_NEAR(fx.accel(0)[0] * mass, 0.57 * fn, tol * fn);
  // still sliding the same way: kinetic force again
  ct::crack_slip<T, false>(fx.pairs, fx.st, fx.u, fx.v, fx.p);
  fx.apply();
  EXPECT_EQ(fx.state(0), ct::pair_slip);
  EXPECT_NEAR(fx.accel(0)[0] * mass, 0.57 * fn, tol * fn);
  // the relative velocity turns: slip -> stick with the anchor at the current displacement (eq. (20))
  fx.set(fx.v, 1, -1e-3, 0.0);
  ct::crack_slip<T, false>(fx.pairs, fx.st, fx.u, fx.v, fx.p);
  fx.apply();
  EXPECT_EQ(fx.state(0), ct::pair_stick);
  EXPECT_EQ(fx.accel(0)[0], 0.0);
  // and the spring now acts on the displacement since that anchor
  const double d3 = d2 - 0.3 * 0.74 * fn / ks;
  fx.set(fx.u, 1, d3, 0.0);
  ct::crack_slip<T, false>(fx.pairs, fx.st, fx.u, fx.v, fx.p);
  fx.apply();
  EXPECT_EQ(fx.state(0), ct::pair_stick);
  EXPECT_NEAR(fx.accel(0)[0] * mass, ks * (d3 - d2), tol * std::abs(ks * (d3 - d2)));
}

}  // namespace

TEST(CrackContact, OpenCloseRepulsionMatchesEquation18Double) { check_open_close<double>(1e-12); }
TEST(CrackContact, OpenCloseRepulsionMatchesEquation18Float) { check_open_close<float>(1e-5); }
TEST(CrackContact, StickSlipCycleMatchesEquations20And21Double) { check_slip_cycle<double>(1e-9); }
TEST(CrackContact, StickSlipCycleMatchesEquations20And21Float) { check_slip_cycle<float>(2e-3); }

// Eq. (18) on i for the pair (0, 1) with S- displaced by (dx, dy), in double on the host.
std::array<double, 2> repulsion_on_plus(double dx, double dy) {
  const double kn = 0.1 * mass / (dt * dt);
  const double rx = dx, ry = -l0 + dy, len = std::hypot(rx, ry);
  const double overlap = -(2 * (-l0) * dy + dx * dx + dy * dy) / (len + l0);
  return overlap > 0 ? std::array<double, 2>{-kn * overlap * rx / len, -kn * overlap * ry / len}
                     : std::array<double, 2>{0.0, 0.0};
}

TEST(CrackContact, FrictionNeedsContactWhenBothModelsAreOn) {
  Fixture<double> fx(1, true, true, 0.0);
  const double kn = 0.1 * mass / (dt * dt), d = 1e-11, press = 1e-10;
  fx.set(fx.u, 1, d, -press);  // apart: separation, no friction however large the shear
  ct::crack_open_close<double, true>(fx.pairs, fx.st, fx.u, fx.p);
  ct::crack_slip<double, true>(fx.pairs, fx.st, fx.u, fx.v, fx.p);
  fx.apply();
  EXPECT_EQ(fx.state(0), ct::pair_separation);
  EXPECT_EQ(fx.accel(0)[0], 0.0);
  EXPECT_EQ(fx.accel(0)[1], 0.0);
  // pressed: the tangential anchor is set at the moment of contact, so a shear of d since then is a
  // stick spring ks d (below mu_s times the normal force kn press), on top of the repulsion
  fx.set(fx.u, 1, 0.0, press);
  ct::crack_open_close<double, true>(fx.pairs, fx.st, fx.u, fx.p);
  ct::crack_slip<double, true>(fx.pairs, fx.st, fx.u, fx.v, fx.p);
  fx.set(fx.u, 1, d, press);
  ct::crack_open_close<double, true>(fx.pairs, fx.st, fx.u, fx.p);
  ct::crack_slip<double, true>(fx.pairs, fx.st, fx.u, fx.v, fx.p);
  fx.apply();
  EXPECT_EQ(fx.state(0), ct::pair_stick);
  auto fr = repulsion_on_plus(d, press);
  EXPECT_NEAR(fx.accel(0)[0] * mass, kn * d + fr[0], 1e-9 * kn * d);
  EXPECT_NEAR(fx.accel(0)[1] * mass, fr[1], 1e-9 * fr[1]);
  EXPECT_NEAR(fr[1], kn * press, 1e-5 * kn * press);
  // a shear beyond mu_s times the normal force slips at mu_d times the normal force
  const double shear = 2 * press;
  fx.set(fx.u, 1, shear, press);
  fx.set(fx.v, 1, 1.0, 0.0);
  ct::crack_open_close<double, true>(fx.pairs, fx.st, fx.u, fx.p);
  ct::crack_slip<double, true>(fx.pairs, fx.st, fx.u, fx.v, fx.p);
  fx.apply();
  EXPECT_EQ(fx.state(0), ct::pair_slip);
  fr = repulsion_on_plus(shear, press);
  const double normal = std::hypot(fr[0], fr[1]);
  EXPECT_NEAR(fx.accel(0)[0] * mass, 0.57 * normal + fr[0], 1e-9 * normal);
}

TEST(CrackContact, GatheredForcesObeyNewtonsThirdLaw) {
  Fixture<double> fx(2, true, false, 0.0);
  fx.set(fx.u, 1, 0.0, 1e-10);
  fx.set(fx.u, 2, -2e-10, 3e-10);  // the diagonal pair (0, 2) is pressed too
  ct::crack_open_close<double, false>(fx.pairs, fx.st, fx.u, fx.p);
  fx.apply();
  double sx = 0, sy = 0, scale = 0;
  for (int i = 0; i < 3; ++i) {
    sx += fx.accel(i)[0];
    sy += fx.accel(i)[1];
    scale += std::hypot(fx.accel(i)[0], fx.accel(i)[1]);
  }
  EXPECT_GT(scale, 0.0);
  EXPECT_LT(std::abs(sx), 1e-14 * scale);
  EXPECT_LT(std::abs(sy), 1e-14 * scale);
  const auto counts = ct::crack_state_counts(fx.pairs, fx.st);
  EXPECT_EQ(counts.stick, 2);
  EXPECT_EQ(counts.separation, 0);
}
