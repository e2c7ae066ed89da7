// Subnormal numbers on the host (core/float_env.hpp): kx::initialize flushes them to zero in every host
// thread unless POLYMECH_SUBNORMALS=keep; the mode can be switched for the whole pool; bad values are
// refused with the allowed ones.
#include <gtest/gtest.h>

#include <limits>
#include <string>

#include "core/kokkos_shim.hpp"
#include "core/types.hpp"

namespace kx = polymech::kx;

namespace {

using Host = Kokkos::DefaultHostExecutionSpace;

// Threads of the host pool whose mode is not `want`, over a static schedule that hands every thread
// the same share of iterations (so every thread of the pool reports).
int threads_not_in(kx::Subnormals want) {
  const int n = 64 * kx::concurrency<Host>();
  int wrong = 0;
  Kokkos::parallel_reduce(
      "polymech::test::subnormal_mode", Kokkos::RangePolicy<Host, Kokkos::Schedule<Kokkos::Static>>(0, n),
      [=](int, int& w) { w += kx::thread_subnormals() == want ? 0 : 1; }, wrong);
  return wrong;
}

// Half the smallest normal double, computed in every thread of the pool from a value the compiler cannot
// see: 0 where subnormals are flushed, 1.1e-308 where they are kept. Returns how many results were 0.
template <class T>
int halves_flushed_to_zero() {
  const int n = 64 * kx::concurrency<Host>();
  Kokkos::View<T*, Kokkos::HostSpace> x("x", n);
  Kokkos::deep_copy(x, std::numeric_limits<T>::min());
  int zeros = 0;
  Kokkos::parallel_reduce(
      "polymech::test::subnormal_halves", Kokkos::RangePolicy<Host, Kokkos::Schedule<Kokkos::Static>>(0, n),
      [=](int i, int& z) {
        const T h = x(i) * T(0.5);
        z += h == T(0) ? 1 : 0;
      },
      zeros);
  return zeros;
}

}  // namespace

TEST(FloatEnv, InitializeSetsTheModeOnEveryHostThread) {
  if (!kx::subnormal_control_available()) GTEST_SKIP() << "this CPU's floating-point environment has no flush bits";
  const kx::Subnormals want = kx::subnormals_from_environment();  // flush unless POLYMECH_SUBNORMALS=keep
  EXPECT_EQ(kx::thread_subnormals(), want);
  EXPECT_EQ(threads_not_in(want), 0);
}

TEST(FloatEnv, FlushedSubnormalsAreZeroAndKeptOnesAreNot) {
  if (!kx::subnormal_control_available()) GTEST_SKIP() << "this CPU's floating-point environment has no flush bits";
  const kx::Subnormals before = kx::thread_subnormals();
  const int n = 64 * kx::concurrency<Host>();

  kx::set_host_subnormals(kx::Subnormals::keep);
  EXPECT_EQ(threads_not_in(kx::Subnormals::keep), 0);
  EXPECT_EQ(halves_flushed_to_zero<double>(), 0);
  EXPECT_EQ(halves_flushed_to_zero<float>(), 0);

  kx::set_host_subnormals(kx::Subnormals::flush);
  EXPECT_EQ(threads_not_in(kx::Subnormals::flush), 0);
  EXPECT_EQ(halves_flushed_to_zero<double>(), n);
  EXPECT_EQ(halves_flushed_to_zero<float>(), n);

  kx::set_host_subnormals(before);
  EXPECT_EQ(threads_not_in(before), 0);
}

TEST(FloatEnv, BadValuesAreRefusedWithTheAllowedOnes) {
  EXPECT_EQ(kx::parse_subnormals("flush", "x"), kx::Subnormals::flush);
  EXPECT_EQ(kx::parse_subnormals("keep", "x"), kx::Subnormals::keep);
  try {
    kx::parse_subnormals("off", "POLYMECH_SUBNORMALS");
    FAIL() << "'off' was accepted";
  } catch (const std::invalid_argument& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("POLYMECH_SUBNORMALS = 'off'"), std::string::npos) << m;
    EXPECT_NE(m.find("'flush'"), std::string::npos) << m;
    EXPECT_NE(m.find("'keep'"), std::string::npos) << m;
  }
}
