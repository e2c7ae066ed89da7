// What io/ needs of the MPS elastic-wave model without compiling it (this header is free of Kokkos):
// the effects, the lattice and the excitation's source, the crack's cut bonds, and the stable time step
// of a configuration (defined in setup.cpp, compiled with the model); the crop and the burst's timing.
#pragma once

#include "mps_elastic/burst.hpp"
#include "mps_elastic/config.hpp"
#include "mps_elastic/crack_bonds.hpp"
#include "mps_elastic/effect_table.hpp"
#include "mps_elastic/lattice.hpp"

namespace polymech::mps_elastic {

// Largest stable dt of symplectic Euler for this discretisation (MpsElastic<double>::stable_time_step:
// power iteration on a small patch of the same lattice). Needs Kokkos initialised.
double stable_time_step(const Config& c);

}  // namespace polymech::mps_elastic
