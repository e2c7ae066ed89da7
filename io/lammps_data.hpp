// A pour's initial spheres as a LAMMPS/LIGGGHTS data file (atom_style sphere: id type diameter density
// x y z), for the side-by-side run of bench/peers/liggghts (dem_pour --lammps-data). The box is the bin,
// up to the lattice's top layer plus one particle. Spheres only: the peer run takes no clumps.
#pragma once

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

#include "dem/pour.hpp"

namespace polymech::io {

inline void write_lammps_data(const std::filesystem::path& file, const dem::Config& c, const dem::PourSpec& p) {
  if (!c.clumps.empty()) throw std::invalid_argument("--lammps-data: the scene has clumps; the peer run takes spheres only");
  std::ofstream out(file);
  if (!out) throw std::runtime_error("cannot write " + file.string());
  out.precision(17);
  out << "polymech dem_pour initial particles (atom_style sphere: id type diameter density x y z)\n\n"
      << c.spheres.size() << " atoms\n1 atom types\n\n0 " << p.bin[0] << " xlo xhi\n0 " << p.bin[1] << " ylo yhi\n0 "
      << std::max(p.bin[2], dem::pour_top(p) + 2 * p.radius_max) << " zlo zhi\n\nAtoms\n\n";
  for (std::size_t i = 0; i < c.spheres.size(); ++i) {
    const auto& s = c.spheres[i];
    out << i + 1 << " 1 " << 2 * s.radius << " " << c.particle.density << " " << s.position[0] << " " << s.position[1] << " "
        << s.position[2] << "\n";
  }
}

}  // namespace polymech::io
