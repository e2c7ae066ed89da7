// Crack-face contact kernels (seed 000 eqs. (17)-(21)): crack pairs per second for the open/close
// model, the slip model, both, and the per-particle gather, for 1e4 .. 1e6 pairs. The pairs join two
// rows of particles (S+ above S-, one opposite partner each) with small random displacements, so about
// half the pairs are in contact and the branches of the state machine are all taken.
#include <benchmark/benchmark.h>

#include <random>

#include "contact/crack_faces.hpp"

namespace pm = polymech;
namespace ct = polymech::contact;

namespace {

template <class T>
struct Crack {
  ct::CrackPairs<T> pairs;
  ct::CrackContactState<T> st;
  ct::CrackContactParams<T> p;
  pm::VecView<T, 2> u, v, a;

  Crack(std::int64_t n, bool open_close, bool slip) {
    const double l0 = 5e-5, mass = 7850 * l0 * l0, dt = 2e-9;
    u = pm::VecView<T, 2>("u", 2 * n);
    v = pm::VecView<T, 2>("v", 2 * n);
    a = pm::VecView<T, 2>("a", 2 * n);
    pairs.plus = pm::View1<pm::Index>("plus", n);
    pairs.minus = pm::View1<pm::Index>("minus", n);
    pairs.r0 = pm::VecView<T, 2>("r0", n);
    pairs.d0 = pm::View1<T>("d0", n);
    pairs.face_particles = pm::View1<pm::Index>("faces", 2 * n);
    pairs.face_offsets = Kokkos::View<pm::Offset*, pm::MemSpace>("foff", 2 * n + 1);
    pairs.face_pairs = pm::View1<pm::Index>("fpairs", 2 * n);
    auto hp = Kokkos::create_mirror_view(pairs.plus);
    auto hm = Kokkos::create_mirror_view(pairs.minus);
    auto hr = Kokkos::create_mirror_view(pairs.r0);
    auto hd = Kokkos::create_mirror_view(pairs.d0);
    auto hf = Kokkos::create_mirror_view(pairs.face_particles);
    auto ho = Kokkos::create_mirror_view(pairs.face_offsets);
    auto hfp = Kokkos::create_mirror_view(pairs.face_pairs);
    auto hu = Kokkos::create_mirror_view(u);
    auto hv = Kokkos::create_mirror_view(v);
    std::mt19937 g(7);
    std::normal_distribution<double> d(0.0, 1e-10);
    for (std::int64_t k = 0; k < n; ++k) {
      hp(k) = static_cast<pm::Index>(k);
      hm(k) = static_cast<pm::Index>(n + k);
      hr(k, 0) = T(0);
      hr(k, 1) = T(-l0);
      hd(k) = T(l0);
    }
    for (std::int64_t i = 0; i < 2 * n; ++i) {
      hf(i) = static_cast<pm::Index>(i);
      ho(i) = i;
      hfp(i) = static_cast<pm::Index>(i % n);
      hu(i, 0) = T(d(g));
      hu(i, 1) = T(d(g));
      hv(i, 0) = T(1e3 * d(g));
      hv(i, 1) = T(1e3 * d(g));
    }
    ho(2 * n) = 2 * n;
    Kokkos::deep_copy(pairs.plus, hp);
    Kokkos::deep_copy(pairs.minus, hm);
    Kokkos::deep_copy(pairs.r0, hr);
    Kokkos::deep_copy(pairs.d0, hd);
    Kokkos::deep_copy(pairs.face_particles, hf);
    Kokkos::deep_copy(pairs.face_offsets, ho);
    Kokkos::deep_copy(pairs.face_pairs, hfp);
    Kokkos::deep_copy(u, hu);
    Kokkos::deep_copy(v, hv);
    st.state = Kokkos::View<int*, pm::MemSpace>("state", n);
    st.force = pm::VecView<T, 2>("force", n);
    if (open_close && slip) st.normal_force = pm::View1<T>("fn", n);
    if (slip) {
      st.du_anchor = pm::VecView<T, 2>("anchor", n);
      st.slip_sign = Kokkos::View<int*, pm::MemSpace>("sign", n);
      st.preload = pm::View1<T>("preload", n);
      Kokkos::deep_copy(st.preload, T(1e-3));
    }
    p.kn = T(0.1 * mass / (dt * dt));
    p.ks = p.kn;
    p.mu_s = T(0.74);
    p.mu_d = T(0.57);
    p.s = pm::Vec2<T>{{T(1), T(0)}};
  }
};

template <class T, int Which>  // 0: open/close, 1: slip, 2: both
void BM_CrackContact(benchmark::State& state) {
  const std::int64_t n = state.range(0);
  Crack<T> c(n, Which != 1, Which != 0);
  for (auto _ : state) {
    if (Which == 0) ct::crack_open_close<T, false>(c.pairs, c.st, c.u, c.p);
    if (Which == 1) ct::crack_slip<T, false>(c.pairs, c.st, c.u, c.v, c.p);
    if (Which == 2) {
      ct::crack_open_close<T, true>(c.pairs, c.st, c.u, c.p);
      ct::crack_slip<T, true>(c.pairs, c.st, c.u, c.v, c.p);
    }
    ct::crack_apply_forces(c.pairs, c.st, c.a, T(1));
    Kokkos::fence();
  }
  state.SetItemsProcessed(state.iterations() * n);  // crack pairs
}

}  // namespace

#define POLYMECH_CONTACT_BENCH(T, W, name) \
  BENCHMARK(BM_CrackContact<T, W>)->Name(name)->RangeMultiplier(10)->Range(10000, 1000000)->UseRealTime()

POLYMECH_CONTACT_BENCH(double, 0, "CrackContact/double/open_close");
POLYMECH_CONTACT_BENCH(double, 1, "CrackContact/double/slip");
POLYMECH_CONTACT_BENCH(double, 2, "CrackContact/double/open_close+slip");
POLYMECH_CONTACT_BENCH(float, 2, "CrackContact/float/open_close+slip");
