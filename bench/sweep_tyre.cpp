// The tyre 37x12.5R16.5 of seed 002 paper 2 alone (issue 37; models/solid/tyre.hpp): inflation to 0.35 MPa
// (follower pressure on the inner surface ramped over 10 ms as in paper 2 §4 a), then held with mass-proportional
// damping), the inflated shape and the rim's reaction against the membrane closed form; then a rigid plate
// raised against the tyre at a constant speed (the rim held): load against deflection and the contact patch.
//   OMP_NUM_THREADS=1 build/ci/bench/sweep_tyre [n_theta n_section n_wall order damping_inflate damping_plate
//                                               plate_speed max_deflection out.csv wall crown_radius]
// wall: smeared (default, the one law), layered (TyreSpec::layered: rubber / cord layer / rubber through the
// wall, n_wall odd >= 3), belted (layered plus the steel belt layer over the crown, TyreSpec::belted: the +-20 deg
// plies read as their circumferential modulus with the lateral strain held) or belted_free (the same belt read as
// the free laminate's E_x, TyreSpec::belt_laterally_free) or belted_rebar (the belt layer keeps the rubber and
// carries the two +-20 deg steel-cord families as rebar, TyreSpec::belt_rebar: stiff round the wheel, soft across).
// crown_radius: the inner tread arc's transverse radius R_t (default TyreSpec's 0.35 m, assumed; a flatter crown to
// see what the belt does to the patch when the tread's camber is smaller).
// Prints the set-up (DoFs, the critical step, the law), the inflation history and the plate's load-deflection
// rows; writes them as CSV (phase,t,deflection,plate_force,rim_force_z,patch_length,patch_width,nodes_in_contact,
// outer_radius,width,bead_axial).
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <fstream>
#include <stdexcept>
#include <string>

#include "core/kokkos_shim.hpp"
#include "solid/tyre.hpp"

namespace so = polymech::solid;

namespace {

double cpu_seconds() { return static_cast<double>(std::clock()) / CLOCKS_PER_SEC; }

struct Shape {
  double outer_radius = 0.0, width = 0.0, widest_inner_r = 0.0, lowest_z = 0.0;
};

Shape shape(const so::Discretization<3>& d, const std::vector<double>& u) {
  Shape s;
  double ymin = 1e300, ymax = -1e300, rsum = 0.0, rn = 0.0, widest = -1e300;
  s.lowest_z = 1e300;
  const auto outer = so::side_nodes(d, "zmax"), inner = so::side_nodes(d, "zmin");
  const int crown = d.lattice[1] / 2;  // the section's centre line (n_section even)
  for (const auto n : outer) {
    const std::size_t i = static_cast<std::size_t>(3 * n);
    const double x = d.coordinates[i] + u[i], y = d.coordinates[i + 1] + u[i + 1], z = d.coordinates[i + 2] + u[i + 2];
    ymin = std::fmin(ymin, y);
    ymax = std::fmax(ymax, y);
    s.lowest_z = std::fmin(s.lowest_z, z);
    if (d.lattice_index(n)[1] == crown) {
      rsum += std::sqrt(x * x + z * z);
      rn += 1.0;
    }
  }
  for (const auto n : inner) {  // the inner surface's widest point on the y > 0 side (its radius)
    const std::size_t i = static_cast<std::size_t>(3 * n);
    const double x = d.coordinates[i] + u[i], y = d.coordinates[i + 1] + u[i + 1], z = d.coordinates[i + 2] + u[i + 2];
    if (y > widest) {
      widest = y;
      s.widest_inner_r = std::sqrt(x * x + z * z);
    }
  }
  s.outer_radius = rsum / rn;
  s.width = ymax - ymin;
  return s;
}

}  // namespace

int main(int argc, char** argv) {
  const int n_theta = argc > 1 ? std::atoi(argv[1]) : 48;
  const int n_section = argc > 2 ? std::atoi(argv[2]) : 12;
  const int n_wall = argc > 3 ? std::atoi(argv[3]) : 1;
  const int order = argc > 4 ? std::atoi(argv[4]) : 2;
  const double alpha_inflate = argc > 5 ? std::atof(argv[5]) : 1000.0;
  const double alpha_plate = argc > 6 ? std::atof(argv[6]) : 200.0;
  const double plate_speed = argc > 7 ? std::atof(argv[7]) : 0.5;
  const double max_deflection = argc > 8 ? std::atof(argv[8]) : 0.04;
  const std::string path = argc > 9 ? argv[9] : "sweep_tyre.csv";
  const std::string wall = argc > 10 ? argv[10] : "smeared";
  if (wall != "smeared" && wall != "layered" && wall != "belted" && wall != "belted_free" && wall != "belted_rebar") {
    std::fprintf(stderr, "sweep_tyre: argument 10 (wall) is '%s'; allowed: smeared, layered, belted, belted_free, belted_rebar\n",
                 wall.c_str());
    return 2;
  }
  const double crown_radius = argc > 11 ? std::atof(argv[11]) : so::TyreSpec{}.crown_radius;
  if (!(crown_radius > 0.0)) {
    std::fprintf(stderr, "sweep_tyre: argument 11 (crown_radius) is '%s'; allowed: a radius > 0 in m\n", argv[11]);
    return 2;
  }
  try {
    so::TyreSpec check{};
    check.crown_radius = crown_radius;
    so::tyre_section(check);
  } catch (const std::invalid_argument& e) {
    std::fprintf(stderr, "sweep_tyre: argument 11 (crown_radius) %g m: %s\n", crown_radius, e.what());
    return 2;
  }
  const double p = 0.35e6, t_inflate = 0.010, t_hold = 0.010;
  polymech::kx::initialize();
  {
    so::TyreSpec spec{};
    spec.crown_radius = crown_radius;
    spec.belted = wall == "belted" || wall == "belted_free" || wall == "belted_rebar";
    spec.belt_rebar = wall == "belted_rebar";
    spec.belt_laterally_free = wall == "belted_free";
    spec.layered = wall == "layered" || spec.belted;
    const so::TyreSection sec = so::tyre_section(spec);
    const so::TyreLaw law = so::tyre_equivalent_law(spec);
    std::printf("section: inner crown r %.4f, arcs R = %.4f %.4f %.4f m, angles %.3f %.3f %.3f rad, half contour %.4f m, "
                "widest inner point r %.4f a %.4f\n",
                sec.r_top, sec.radius[0], sec.radius[1], sec.radius[2], sec.angle[0], sec.angle[1], sec.angle[2],
                sec.half_length, sec.widest_r, sec.widest_a);
    std::printf("law: ply E1 %.4g E2 %.4g, quasi-isotropic %.4g, equivalent E %.4g Pa, mu %.4g, C10 %.4g C01 %.4g kappa %.4g; "
                "volume %.5f m^3, density %.1f kg/m^3\n",
                law.E_ply_along, law.E_ply_across, law.E_quasi_isotropic, law.E_equivalent, law.mu, law.law.C10, law.law.C01,
                law.law.kappa, so::tyre_volume(spec), law.density);
    so::Config<3> c;
    c.mesh = so::make_tyre(spec, n_theta, n_section, n_wall);
    c.order = order;
    std::array<so::RigidTie<3>, 2> beads;
    for (int k = 0; k < 2; ++k) {  // both beads on one rim: two bodies with the same prescribed (zero) motion
      beads[k].boundary = k == 0 ? "ymin" : "ymax";
      beads[k].axis = {0.0, 1.0, 0.0};
      for (int q = 0; q < 4; ++q) beads[k].velocity[q] = [](double) { return 0.0; };
    }
    so::ExplicitFiniteStrainOptions eo;
    eo.density = law.density;
    eo.damping = alpha_inflate;
    eo.load_factor = [t_inflate](double t) { return std::fmin(t / t_inflate, 1.0); };
    if (spec.layered) {
      const so::TyreLayers lay = so::tyre_layers(spec, n_theta, n_section, n_wall);
      eo.cell_scale = lay.cell_scale;
      std::printf("layered wall: rubber E %.4g Pa (scale %.4g), cord layer E %.4g..%.4g Pa (scale up to %.4g) in the middle of %d "
                  "cells through the wall\n",
                  lay.E_rubber, lay.scale_min, lay.E_cord_min, lay.E_cord_max, lay.scale_max, n_wall);
      if (spec.belt_rebar) {
        eo.fibre_stiffness = lay.fibre_stiffness;
        eo.fibre_angle_deg = spec.belt_angle_deg;
        eo.fibre_tension_only = spec.belt_tension_only;
        const double cb = std::cos(spec.belt_angle_deg * 3.14159265358979 / 180.0), sb = std::sin(spec.belt_angle_deg * 3.14159265358979 / 180.0);
        std::printf("belt (rebar): %d plies x %.4g m at +-%.4g deg, steel %.4g Pa, V_f %.3g, as two cord families in the rubber of layer "
                    "k = %d over %d contour cells (half width %.4g m): k per family up to %.4g Pa; small-strain layer stiffness "
                    "round the wheel 2 k cos^4 = %.4g Pa, across 2 k sin^4 = %.4g Pa\n",
                    spec.belt_plies, spec.belt_ply_thickness, spec.belt_angle_deg, spec.belt_modulus, spec.belt_fraction, lay.belt_layer,
                    lay.belt_cells, spec.belt_half_width, lay.fibre_k_max, 2.0 * lay.fibre_k_max * cb * cb * cb * cb,
                    2.0 * lay.fibre_k_max * sb * sb * sb * sb);
      } else if (spec.belted)
        std::printf("belt: %d plies x %.4g m at +-%.4g deg, steel %.4g Pa, V_f %.3g; laminate A11/t %.4g Pa%s, A22/t %.4g Pa, "
                    "free E_x %.4g Pa%s; belt layer k = %d over %d contour cells (half width %.4g m), E up to %.4g Pa (scale %.4g)\n",
                    spec.belt_plies, spec.belt_ply_thickness, spec.belt_angle_deg, spec.belt_modulus, spec.belt_fraction, lay.E_belt_held,
                    spec.belt_laterally_free ? "" : " (used)", lay.E_belt_across, lay.E_belt_free, spec.belt_laterally_free ? " (used)" : "",
                    lay.belt_layer, lay.belt_cells, spec.belt_half_width, lay.E_belt_layer_max, lay.E_belt_layer_max / law.E_equivalent);
    }
    double t0 = cpu_seconds();
    so::HyperelasticExplicit<double, 3> m(c, so::HyperelasticLaw(law.law), eo, {{"zmin", p}}, {beads[0], beads[1]});
    const double setup = cpu_seconds() - t0;
    const auto& d = m.solid().discretization();
    std::printf("mesh %d x %d x %d cells, order %d: %lld nodes, %lld DoFs; dt_crit %.4g s (omega_max %.4g, %d power "
                "iterations), dt %.4g s; set-up %.2f s CPU\n",
                n_theta, n_section, n_wall, order, static_cast<long long>(d.nodes), static_cast<long long>(m.solid().dof_count()),
                m.critical_time_step(), m.omega_max(), m.power_iterations_used(), m.time_step(), setup);
    std::ofstream out(path);
    out << "phase,t,deflection,plate_force,rim_force_z,patch_length,patch_width,nodes_in_contact,outer_radius,width,bead_axial\n";
    const Shape s0 = shape(d, std::vector<double>(static_cast<std::size_t>(m.solid().dof_count()), 0.0));
    std::printf("reference: outer radius %.4f, width %.4f, widest inner r %.4f\n", s0.outer_radius, s0.width, s0.widest_inner_r);
    // inflation
    const std::int64_t every = std::max<std::int64_t>(1, static_cast<std::int64_t>(std::llround(1e-3 / m.time_step())));
    t0 = cpu_seconds();
    std::int64_t steps = 0;
    Shape s = s0;
    while (m.time() < t_inflate + t_hold) {
      m.advance(every);
      steps += every;
      s = shape(d, polymech::models::to_host(m.displacement()));
      const auto& A = m.ties()[0];
      const auto& B = m.ties()[1];
      std::printf("inflate t %.4f s: outer radius %.5f (%+.3f %%), width %.5f (%+.3f %%), bead forces (y) %.5g / %.5g N, net "
                  "rim force %.3g %.3g %.3g N, kinetic %.4g J\n",
                  m.time(), s.outer_radius, 100.0 * (s.outer_radius / s0.outer_radius - 1.0), s.width,
                  100.0 * (s.width / s0.width - 1.0), A.force[1], B.force[1], A.force[0] + B.force[0], A.force[1] + B.force[1],
                  A.force[2] + B.force[2], m.kinetic_energy());
      out << "inflate," << m.time() << ",0,0," << A.force[2] + B.force[2] << ",0,0,0," << s.outer_radius << "," << s.width << ","
          << B.force[1] << "\n";
    }
    const double cpu_inflate = cpu_seconds() - t0;
    const double rb = spec.rim_radius, rm = so::widest_inner_point(d, polymech::models::to_host(m.displacement()))[1];
    const double closed = p * 3.14159265358979 * (rm * rm - rb * rb);
    std::printf("inflated: %lld steps in %.2f s CPU (%.1f steps/s, %.3g DoF-steps/s); bead axial force %.5g N vs membrane "
                "p pi (r_m^2 - r_b^2) = %.5g N (r_m = %.4f, the widest inner point; ratio %.4f); per unit bead length %.5g N/m\n",
                static_cast<long long>(steps), cpu_inflate, steps / cpu_inflate, steps * double(m.solid().dof_count()) / cpu_inflate,
                m.ties()[1].force[1], closed, rm, m.ties()[1].force[1] / closed, m.ties()[1].force[1] / (6.28318530718 * rb));
    {  // the crown's transverse profile on the meridian theta = 0 (outer surface): how flat the tread is across
      const std::vector<double> uh = polymech::models::to_host(m.displacement());
      std::printf("inflated outer profile (theta = 0; y, r - r_crown, reference y, r - r_crown), |y| < 0.16 m:");
      const auto outer = so::side_nodes(d, "zmax");
      double rc = 0.0, rc0 = 0.0;
      for (const auto n : outer) {
        const auto I = d.lattice_index(n);
        if (I[0] != 0 || I[1] != d.lattice[1] / 2) continue;
        const std::size_t i = static_cast<std::size_t>(3 * n);
        rc = std::sqrt((d.coordinates[i] + uh[i]) * (d.coordinates[i] + uh[i]) + (d.coordinates[i + 2] + uh[i + 2]) * (d.coordinates[i + 2] + uh[i + 2]));
        rc0 = std::sqrt(d.coordinates[i] * d.coordinates[i] + d.coordinates[i + 2] * d.coordinates[i + 2]);
      }
      for (int j = 0; j < d.lattice[1]; ++j)
        for (const auto n : outer) {
          const auto I = d.lattice_index(n);
          if (I[0] != 0 || I[1] != j) continue;
          const std::size_t i = static_cast<std::size_t>(3 * n);
          const double y = d.coordinates[i + 1] + uh[i + 1];
          if (std::fabs(y) > 0.16) continue;
          const double r = std::sqrt((d.coordinates[i] + uh[i]) * (d.coordinates[i] + uh[i]) + (d.coordinates[i + 2] + uh[i + 2]) * (d.coordinates[i + 2] + uh[i + 2]));
          const double r0 = std::sqrt(d.coordinates[i] * d.coordinates[i] + d.coordinates[i + 2] * d.coordinates[i + 2]);
          std::printf(" (%.4f, %.5f; %.4f, %.5f)", y, r - rc, d.coordinates[i + 1], r0 - rc0);
        }
      std::printf("\n");
    }
    const double dt_inflated = m.estimate_critical_step();
    std::printf("critical step inflated %.4g s (omega_max %.4g)\n", dt_inflated, m.omega_max());
    // plate: from the inflated lowest point up at plate_speed
    const double t1 = m.time(), z0 = s.lowest_z;
    so::PlateContact<double> plate(
        d, m.lumped_mass(), m.omega_max(), 0.1, 0.3, [t1, z0, plate_speed](double t) { return z0 + plate_speed * std::fmax(0.0, t - t1); },
        [plate_speed](double) { return plate_speed; });
    m.set_external_force([&plate](double t, const polymech::View1<double>& u, const polymech::View1<double>& v,
                                  const polymech::View1<double>& r) { plate.apply(t, u, v, r); });
    m.set_damping(alpha_plate);
    const std::int64_t every2 = std::max<std::int64_t>(1, static_cast<std::int64_t>(std::llround(1e-3 / plate_speed / m.time_step())));
    t0 = cpu_seconds();
    steps = 0;
    while (plate.height(m.time()) - z0 < max_deflection) {
      m.advance(every2);
      steps += every2;
      const double defl = plate.height(m.time()) - z0;
      const auto patch = plate.patch(d, m.displacement(), m.time());
      const double rim_z = m.ties()[0].drive_force[2] + m.ties()[1].drive_force[2];
      std::printf("plate: deflection %.4f m, plate force %.5g N, rim's drive force (z) %.5g N, patch %.4f x %.4f m, %d nodes\n", defl,
                  plate.force(), rim_z, patch[0], patch[1], plate.nodes_in_contact());
      out << "plate," << m.time() << "," << defl << "," << plate.force() << "," << rim_z << "," << patch[0] << "," << patch[1] << ","
          << plate.nodes_in_contact() << ",0,0,0\n";
    }
    const double cpu_plate = cpu_seconds() - t0;
    std::printf("plate: %lld steps in %.2f s CPU (%.1f steps/s)\n", static_cast<long long>(steps), cpu_plate, steps / cpu_plate);
  }
  Kokkos::finalize();
  return 0;
}
