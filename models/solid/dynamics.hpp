// Structural dynamics of the linear elastic solid (issue 34): the shared part (solid_dynamics.hpp: options,
// masses, prescribed motion, energies) and the two integrators, implicit Newmark (newmark.hpp) and explicit
// central differences with the lumped mass (central_difference.hpp).
#pragma once

#include "solid/central_difference.hpp"
#include "solid/newmark.hpp"
#include "solid/solid_dynamics.hpp"
