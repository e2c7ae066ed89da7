// What io/ needs of the NOSB peridynamics model without compiling it (this header is free of Kokkos):
// the effects and the stable time step of a configuration (defined in setup.cpp, compiled with the
// model).
#pragma once

#include "nosb_pd/config.hpp"
#include "nosb_pd/effect_table.hpp"

namespace polymech::nosb_pd {

// Largest stable step of velocity Verlet for this configuration (NosbPd<double, D>::stable_time_step,
// D = c.dimension). Needs Kokkos initialised.
double stable_time_step(const Config& c);

}  // namespace polymech::nosb_pd
