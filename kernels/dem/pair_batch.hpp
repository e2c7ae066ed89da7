// The contact law over a batch of sphere pairs, for the host's sphere-sphere rows (kernels/dem/contact_forces.hpp,
// sphere_sphere_rows): the touching pairs of a block of spheres, gathered into contiguous arrays, go through
// contact::hertz_mindlin_force (seed 002 paper 2, eqs. (11)-(14)) as one vector loop. Compiled once, in
// pair_batch.cpp, without errno for sqrt (-fno-math-errno): with it, each square root is a call behind a branch
// and the loop does not vectorise. Host builds only (a CUDA build runs a thread per sphere and never calls it).
#pragma once

#include "dem/hertz_mindlin.hpp"

namespace polymech::dem::detail {

template <class T>
struct PairBatch {
  static constexpr int capacity = 64;
  int count = 0;
  Offset k[capacity];  // the pair's slot in the list
  int row[capacity];   // which sphere of the block is its first member
  // in: d = x_i - x_j, |d|^2, the radii, masses, velocities and spins, the spring xi (zero without friction)
  T d[3][capacity], dist2[capacity], ri[capacity], rj[capacity], mi[capacity], mj[capacity];
  T vi[3][capacity], wi[3][capacity], vj[3][capacity], wj[3][capacity], xi[3][capacity];
  // out: the force on i, n x f, the levers l_i, l_j (to the middle of the overlap); xi updated
  T f[3][capacity], nxf[3][capacity], li[capacity], lj[capacity];
};

// The contact law for the batch's b.count pairs: per pair the arithmetic of sphere_sphere_rows' one-sphere body
// (contact_forces.hpp), written out again in pair_batch.cpp: GCC 12 does not vectorise the loop when that
// arithmetic is an inline function taking the pair's vectors ("no vectype" for their loads), so the two copies
// must be changed together.
template <bool Friction, class T>
void batch_contacts(PairBatch<T>& b, const HertzMindlin<T>& law, T root_ratio, T dt);

}  // namespace polymech::dem::detail
