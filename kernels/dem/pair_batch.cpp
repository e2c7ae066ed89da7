#include "dem/pair_batch.hpp"

namespace polymech::dem::detail {

template <bool Friction, class T>
void batch_contacts(PairBatch<T>& b, const HertzMindlin<T>& law, T root_ratio, T dt) {
  const int n_pairs = b.count;
  constexpr bool friction = Friction;  // a constant: no branch left in the loop (hertz_mindlin_force has selects)
#pragma omp simd
  for (int c = 0; c < n_pairs; ++c) {
    const Vec3<T> d{{b.d[0][c], b.d[1][c], b.d[2][c]}};
    const T ri = b.ri[c], rj = b.rj[c];
    const T reach = ri + rj;
    const T dist = kx::sqrt(b.dist2[c]);
    const T delta = reach - dist;
    const Vec3<T> n = (T(1) / dist) * d;  // from j to i
    const T li = ri - T(0.5) * delta, lj = rj - T(0.5) * delta;  // both ends at the middle of the overlap
    const Vec3<T> vi{{b.vi[0][c], b.vi[1][c], b.vi[2][c]}}, wi{{b.wi[0][c], b.wi[1][c], b.wi[2][c]}};
    const Vec3<T> vj{{b.vj[0][c], b.vj[1][c], b.vj[2][c]}}, wj{{b.wj[0][c], b.wj[1][c], b.wj[2][c]}};
    const Vec3<T> v_rel = vi + cross(wi, (-li) * n) - vj - cross(wj, lj * n);
    const T mi = b.mi[c], mj = b.mj[c];
    Vec3<T> xi{{b.xi[0][c], b.xi[1][c], b.xi[2][c]}};
    const auto cf = hertz_mindlin_force(law, root_ratio, ri * rj / reach, mi * mj / (mi + mj), delta, n, v_rel, friction, dt, xi);
    const Vec3<T> nxf = cross(n, cf.force);
    for (int q = 0; q < 3; ++q) {
      b.xi[q][c] = xi[q];
      b.f[q][c] = cf.force[q];
      b.nxf[q][c] = nxf[q];
    }
    b.li[c] = li;
    b.lj[c] = lj;
  }
}

template void batch_contacts<true, double>(PairBatch<double>&, const HertzMindlin<double>&, double, double);
template void batch_contacts<false, double>(PairBatch<double>&, const HertzMindlin<double>&, double, double);
template void batch_contacts<true, float>(PairBatch<float>&, const HertzMindlin<float>&, float, float);
template void batch_contacts<false, float>(PairBatch<float>&, const HertzMindlin<float>&, float, float);

}  // namespace polymech::dem::detail
