// Physically plausible ranges for scene values, shared by every loader. They are wide (from aerogels
// to diamond, from nanometres to kilometres) but finite, so that a typo such as 1e300 or 1e-300 is
// refused with the key and the range instead of running into NaN or an enormous allocation. A model
// that needs a value outside one of them changes the bound here, with the reason, not in its loader.
// Host-only, like the rest of io/.
#pragma once

#include "io/scene.hpp"

namespace polymech::io::plausible {

inline Range make(double lo, double hi, bool lo_open, const char* note) { return Range{lo, hi, lo_open, false, note}; }

// mass density [kg/m^3]: aerogels, gases (air 1.2) up to osmium (22 590)
inline Range density() { return make(1e-3, 1e5, false, "kg/m^3 (a plausible density)"); }
// an elastic modulus or stiffness constant [Pa]: gels (kPa) up to diamond (~1.2e12 Pa)
inline Range modulus() { return make(1e3, 1e13, false, "Pa (a plausible elastic modulus)"); }
// a stress (yield stress, hardening modulus) [Pa]
inline Range stress() { return make(0.0, 1e12, false, "Pa (a plausible stress)"); }
// a wave speed [m/s]: slower than sound in gases at low pressure up to 100 km/s
inline Range wave_speed() { return make(1.0, 1e5, false, "m/s (a plausible wave speed)"); }
// a body's velocity [m/s]: up to hypervelocity impact
inline Range velocity() { return make(0.0, 2e4, true, "m/s (up to hypervelocity impact, 20 km/s)"); }
// a signed velocity amplitude [m/s] (vibrating boundaries)
inline Range signed_velocity() { return Range{-1e4, 1e4, false, false, "m/s (a plausible velocity amplitude)"}; }
// a frequency [Hz]: up to 10 GHz (ultrasonics stop well below)
inline Range frequency() { return make(1e-3, 1e10, false, "Hz (a plausible frequency)"); }
// a size of a body or domain [m]: from a micrometre to 10 km
inline Range length() { return make(1e-6, 1e4, false, "m (a plausible size: 1 um to 10 km)"); }
// a particle or lattice spacing [m]
inline Range spacing() { return make(1e-9, 1e2, false, "m (a plausible spacing: 1 nm to 100 m)"); }
// a position [m] (probes, origins, crack centres are also checked against the domain)
inline Range coordinate() { return Range{-1e4, 1e4, false, false, "m (a plausible coordinate)"}; }
// a small length that may be zero (stand-off, driven width) [m]
inline Range gap() { return make(0.0, 1e4, false, "m"); }
// a displacement amplitude [m]
inline Range amplitude() { return make(1e-15, 1.0, false, "m (a plausible displacement amplitude)"); }
// a time step [s]
inline Range time_step() { return make(1e-15, 1e3, false, "s (a plausible time step)"); }
// a time span: a period, a simulated duration [s]
inline Range duration() { return make(1e-12, 1e6, false, "s (a plausible duration)"); }
// a mass [kg]
inline Range mass() { return make(1e-9, 1e6, false, "kg (a plausible mass)"); }
// an absolute temperature [K]
inline Range temperature() { return make(1.0, 1e5, false, "K (a plausible temperature)"); }
// a specific heat [J/(kg K)]
inline Range specific_heat() { return make(1.0, 1e6, false, "J/(kg K) (a plausible specific heat)"); }
// a strain rate [1/s]
inline Range strain_rate() { return make(1e-12, 1e12, false, "1/s (a plausible strain rate)"); }
// an acoustic impedance [kg/(m^2 s)]: air (415) up to tungsten (1e8)
inline Range impedance() { return make(1e-3, 1e12, false, "kg/(m^2 s) (a plausible impedance)"); }
// a rate, a frequency in rad/s or a damping coefficient [1/s]; 0 allowed
inline Range rate() { return make(0.0, 1e15, false, "1/s (a plausible rate)"); }
// a dimensionless factor, exponent or ratio that is normally of order 1: [lo, hi]; a factor that scales
// something takes lo = 1e-6 rather than > 0, so that 1e-300 is refused
inline Range factor(double lo, double hi) { return Range{lo, hi, false, false, ""}; }

}  // namespace polymech::io::plausible
