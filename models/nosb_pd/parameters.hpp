// The constants a NosbPd model derives from its Config, in the kernels' precision: the constitutive
// law (chosen by type), the bond weights of eq. (2), the micromodulus that scales the hourglass and
// short-range forces, the critical stretch, and the parameter structs each kernel takes.
#pragma once

#include <variant>

#include "contact/pd_short_range.hpp"
#include "nosb_pd/config.hpp"
#include "nosb_pd/lattice_sums.hpp"
#include "pd/deformation.hpp"
#include "pd/forces.hpp"
#include "pd/stress.hpp"
#include "pd/viscosity.hpp"

namespace polymech::nosb_pd {

template <class T>
using MaterialLaw = std::variant<materials::StVenantKirchhoff<T>, materials::J2JohnsonCook<T>>;

template <class T>
MaterialLaw<T> material_law(const Material& m) {
  materials::ElasticConstants<T> elastic;
  elastic.lambda = static_cast<T>(m.lambda());
  elastic.mu = static_cast<T>(m.mu());
  if (m.law == Law::elastic) return materials::StVenantKirchhoff<T>{elastic};
  materials::JohnsonCook<T> jc;
  jc.A = static_cast<T>(m.jc_a);
  jc.B = static_cast<T>(m.jc_b);
  jc.n = static_cast<T>(m.jc_n);
  jc.C = static_cast<T>(m.jc_c);
  jc.rate0 = static_cast<T>(m.jc_reference_rate);
  jc.m = static_cast<T>(m.jc_m);
  jc.T_room = static_cast<T>(m.room_temperature);
  jc.T_melt = static_cast<T>(m.melting_temperature);
  jc.rho_cp = static_cast<T>(m.density * m.specific_heat);
  jc.chi = static_cast<T>(m.taylor_quinney);
  return materials::J2JohnsonCook<T>{elastic, jc};
}

template <class T, int D>
struct Parameters {
  double beta = 1.0, micromodulus = 0.0, critical_stretch = 0.0;
  MaterialLaw<T> law;
  pd::CrushLimits<T> crush;
  pd::BondWeight<T> weight;
  pd::DeformationParams<T> deformation;
  pd::ForceParams<T> force;
  pd::ViscosityParams<T> viscosity;
  contact::ShortRangeParams<T> short_range;

  bool plastic() const { return std::holds_alternative<materials::J2JohnsonCook<T>>(law); }

  explicit Parameters(const Config& c) : law(material_law<T>(c.material)) {
    const bool weighted = c.effects.has("weighted_function"), damage = c.effects.has("damage");
    const double delta = c.horizon();
    beta = weighted ? weighted_function_beta(D, c.horizon_ratio) : 1.0;
    const LatticeFamily lf = lattice_family(D, c.spacing, c.horizon_ratio, weighted, beta);
    // bond-based micromodulus c = 18 K / sum_j |xi| W_ij (3D; 2D plane strain: 2 (lambda + mu) ... with
    // the 2D bulk modulus of plane strain, K_2D = lambda + mu, c = 8 K_2D / sum |xi| W)
    const double K = D == 3 ? c.material.bulk() : c.material.lambda() + c.material.mu();
    micromodulus = (D == 3 ? 18.0 : 8.0) * K / lf.length_weighted;
    critical_stretch = damage ? nosb_pd::critical_stretch(c) : 0.0;
    if (damage) crush.j_min = static_cast<T>(c.damage.crush_volume_ratio);
    weight.delta2 = static_cast<T>(delta * delta);
    weight.beta = static_cast<T>(beta);
    weight.weighted = weighted;
    deformation.damage = damage;
    deformation.critical_stretch = static_cast<T>(critical_stretch);
    if (damage) deformation.min_shape_quality = static_cast<T>(c.damage.min_shape_quality);
    deformation.rate = plastic();
    deformation.mean_velocity = c.effects.has("velocity_viscosity");
    force.density = static_cast<T>(c.material.density);
    force.damage = damage;
    force.hourglass_c = static_cast<T>(c.effects.has("hourglass") ? c.stabilization.hourglass * micromodulus : 0.0);
    viscosity.c_v = static_cast<T>(c.stabilization.c_v);
    viscosity.omega_v = static_cast<T>(c.stabilization.omega_v);
    viscosity.density = static_cast<T>(c.material.density);
    short_range.distance = static_cast<T>(c.contact.short_range_distance * c.spacing);
    short_range.coefficient = static_cast<T>(c.contact.short_range_factor * micromodulus);
    short_range.density = static_cast<T>(c.material.density);
  }
};

}  // namespace polymech::nosb_pd
