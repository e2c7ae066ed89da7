// A rigid sphere pressed into an elastic FE block through the DEM-to-FE coupling against Hertz (issue 37;
// models/dem/hertz_block.hpp): F / F_Hertz and a / a_Hertz against the indentation d at several mesh resolutions
// (cells across the largest contact radius), with the CPU time of each press (accuracy against cost).
//   OMP_NUM_THREADS=1 build/ci/bench/sweep_hertz [key=value ...]
// keys: res=2,3,4 (cells_per_contact list), depth=0.02 (d_max / R), extent=8 (W = H in a_max), stiff=30 (DEM E* /
// block E*), press=40 (press time in H / c_s), damping=1 (alpha in c_s / H), restitution=0.3 (the DEM contact's), penalty=2 (case=plate: PlateContact's beta),
// step=0.5 (dt / the smaller of the solid's and the contact's step), ratio=1.3, order=1, rows=8,
// case=sphere (the rigid sphere into the block through the DEM coupling) or plate (the block's paraboloidal tip on
// a rigid plate, FE contact only: dem::hertz_plate_press), out=sweep_hertz.csv. Writes CSV: res,cells_x,cells_z,dofs,steps,cpu_s,time,travel,depth,overlap,force,hertz,ratio,
// contact_radius,hertz_radius,node_sum,kinetic,contacts.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/kokkos_shim.hpp"
#include "dem/hertz_block.hpp"

namespace dm = polymech::dem;

int main(int argc, char** argv) {
  dm::HertzBlockSpec base;
  std::vector<double> res{2.0, 3.0, 4.0};
  std::string path = "sweep_hertz.csv";
  bool plate = false;
  for (int k = 1; k < argc; ++k) {
    const std::string a = argv[k];
    const auto eq = a.find('=');
    const std::string key = a.substr(0, eq == std::string::npos ? 0 : eq), value = eq == std::string::npos ? "" : a.substr(eq + 1);
    char* end = nullptr;
    const double x = std::strtod(value.c_str(), &end);
    const bool number = !value.empty() && end && *end == '\0';
    if (key == "res") {
      res.clear();
      std::stringstream ss(value);
      std::string item;
      while (std::getline(ss, item, ',')) res.push_back(std::atof(item.c_str()));
    } else if (key == "case" && (value == "sphere" || value == "plate")) {
      plate = value == "plate";
    } else if (key == "out") {
      path = value;
    } else if (number && key == "depth") {
      base.depth_max = x;
    } else if (number && key == "extent") {
      base.extent = x;
    } else if (number && key == "stiff") {
      base.contact_stiffness = x;
    } else if (number && key == "press") {
      base.press_time = x;
    } else if (number && key == "damping") {
      base.damping = x;
    } else if (number && key == "restitution") {
      base.restitution = x;
    } else if (number && key == "penalty") {
      base.plate_penalty = x;
    } else if (number && key == "step") {
      base.step_fraction = x;
    } else if (number && key == "ratio") {
      base.ratio = x;
    } else if (number && key == "order") {
      base.order = static_cast<int>(x);
    } else if (number && key == "rows") {
      base.rows = static_cast<int>(x);
    } else {
      std::fprintf(stderr, "sweep_hertz: argument %d '%s': allowed res=a,b,.. depth= extent= stiff= press= damping= restitution= penalty= step= ratio= order= rows= "
                           "(numbers) case=sphere|plate out=path\n", k, a.c_str());
      return 2;
    }
  }
  polymech::kx::initialize();
  int rc = 0;
  {
    std::ostringstream out;  // written to path at the end, only when every press ran (no half-written result)
    out << "res,cells_x,cells_z,dofs,steps,cpu_s,time,travel,depth,overlap,force,hertz,ratio,hertz_far,ratio_far,contact_radius,hertz_radius,node_sum,kinetic,contacts\n";
    for (const double r : res) {
      dm::HertzBlockSpec spec = base;
      spec.cells_per_contact = r;
      try {
        const auto h = plate ? dm::hertz_plate_press(spec) : dm::hertz_block_press(spec);
        std::printf("res %.3g: cells %d x %d x %d, %lld DoFs, first cell %.4g (a_max %.4g), dt %.4g (contact estimate %.4g), %lld steps, %d facets listed at most, "
                    "%.2f s CPU\n",
                    r, h.cells[0], h.cells[1], h.cells[2], static_cast<long long>(h.dofs), h.first_cell, h.a_max, h.dt, h.contact_step,
                    static_cast<long long>(h.steps), h.most_facets, h.cpu_seconds);
        std::printf("  %10s %10s %10s %10s %10s %8s %8s %8s %10s %10s %4s\n", "d/R", "travel/R", "overlap/R", "F", "F_Hertz", "F/F_H",
                    "F/F_H,far", "a/a_H", "node+F", "kinetic", "n");
        for (const auto& w : h.rows) {
          std::printf("  %10.4g %10.4g %10.4g %10.4g %10.4g %8.4f %8.4f %8.4f %10.3g %10.3g %4d\n", w.depth, w.travel, w.overlap, w.force, w.hertz,
                      w.hertz > 0 ? w.force / w.hertz : 0.0, w.hertz_far > 0 ? w.force / w.hertz_far : 0.0, w.hertz_radius > 0 ? w.contact_radius / w.hertz_radius : 0.0, w.node_sum + w.force,
                      w.kinetic, w.contacts);
          out << r << "," << h.cells[0] << "," << h.cells[2] << "," << h.dofs << "," << h.steps << "," << h.cpu_seconds << "," << w.time << ","
              << w.travel << "," << w.depth << "," << w.overlap << "," << w.force << "," << w.hertz << "," << (w.hertz > 0 ? w.force / w.hertz : 0.0) << "," << w.hertz_far << ","
              << (w.hertz_far > 0 ? w.force / w.hertz_far : 0.0) << ","
              << w.contact_radius << "," << w.hertz_radius << "," << w.node_sum << "," << w.kinetic << "," << w.contacts << "\n";
        }
      } catch (const std::invalid_argument& e) {  // a bad key's value: exit code 2
        std::fprintf(stderr, "sweep_hertz: res %g: %s\n", r, e.what());
        rc = 2;
      } catch (const std::exception& e) {
        std::fprintf(stderr, "sweep_hertz: res %g: %s\n", r, e.what());
        rc = rc == 0 ? 1 : rc;
      }
    }
    if (rc == 0)
      std::ofstream(path) << out.str();
    else
      std::fprintf(stderr, "sweep_hertz: nothing written to %s\n", path.c_str());
  }
  Kokkos::finalize();
  return rc;
}
