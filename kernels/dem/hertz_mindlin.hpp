// The Hertz-Mindlin law lives in the shared contact module (kernels/contact/hertz_mindlin.hpp); the DEM
// kernels and model name it in their own namespace.
#pragma once

#include "contact/hertz_mindlin.hpp"

namespace polymech::dem {
using contact::ContactForce;
using contact::damping_ratio;
using contact::effective_modulus;
using contact::effective_shear_modulus;
using contact::hertz_contact_time;
using contact::hertz_max_force;
using contact::hertz_max_overlap;
using contact::hertz_mindlin_force;
using contact::HertzMindlin;
using contact::kPi;
using contact::rayleigh_time_step;
}  // namespace polymech::dem
