// The consistent mass matrix factorised on the host for a start from rest: a_0 = (rho M)^-1 (f_ext - f_int(u_0))
// on the free DoFs. Identity rows on the constrained DoFs keep the matrix regular (their a_0 is set to zero by
// the caller). Used by the implicit finite-strain dynamics (finite_strain_dynamics.hpp) and the FSI flag
// (models/fsi/turek_hron_fsi_transient.hpp).
#pragma once

#include <cstdint>
#include <vector>

#include "solid/assembly.hpp"
#include "solid/mass.hpp"
#include "solvers/host_sparse_lu.hpp"

namespace polymech::solid {

inline void factor_start_mass(solvers::HostSparseLU& lu, const AssemblyInput& in, double rho, const std::vector<char>& constrained) {
  Triplets m = assemble_mass(in, rho);
  for (std::size_t i = 0; i < constrained.size(); ++i)
    if (constrained[i]) {
      m.rows.push_back(static_cast<std::int64_t>(i));
      m.cols.push_back(static_cast<std::int64_t>(i));
      m.values.push_back(1.0);
    }
  lu.factor(m.n, m.rows, m.cols, m.values);
}

}  // namespace polymech::solid
