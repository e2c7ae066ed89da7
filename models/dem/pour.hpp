// A pour of gravel into a bin (seed 002 paper 2, sec. 2 and Fig. 6: the soil bin filled with
// multi-sphere gravel particles of radii 5-7 mm), Kokkos-free: the configuration of the pour and the
// packing fraction of a settled bed.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "dem/config.hpp"

namespace polymech::dem {

struct PourSpec {
  std::array<double, 3> bin{};         // the bin's size: floor z = 0, walls at x = 0, lx and y = 0, ly
  int count = 0;                       // particles
  std::vector<std::string> shapes;     // names of gravel_shapes() ("cylinder", "cone", "cube") or "sphere"
  double radius_min = 0.0, radius_max = 0.0;  // a particle's bounding radius, uniform in [min, max]
  std::uint64_t seed = 1;
  double release_at = 0.0;             // > 0: the wall x = lx (plane 2) opens at this time: a heap forms
};

// The plane index of the wall x = lx in pour_config's bin (the wall a heap's release opens).
inline constexpr std::size_t kReleaseWall = 2;

// The angle of repose of a heap against the wall x = 0: the surface height h(x) (highest sphere top
// in bins of width 2 radius_max, over the middle half of the bin in y), a least-squares line through
// the slope: the bins from the first past the highest below 80 % of its height to the toe (the first
// below 30 %), so the layer of grains that ran out beyond the toe is left out; angle = atan(-slope) in
// degrees. profile gets the (x, h) rows. NaN when fewer than three bins are on the slope.
double repose_angle(const std::vector<std::array<double, 4>>& spheres, const PourSpec& spec,
                    std::vector<std::array<double, 2>>* profile = nullptr);

// The five planes of an open box [0, lx] x [0, ly] above the floor z = 0 (normals inwards): floor,
// x = 0, x = lx (index kReleaseWall), y = 0, y = ly.
std::vector<PlaneInit> box_planes(double lx, double ly);

// `base` (materials, contact, gravity, effects, dt) with the bin's five planes and `count` particles on
// a lattice above the floor (spacing 2.2 radius_max, layer after layer), each of a shape drawn in turn
// from `shapes`, a uniform random radius and a uniform random orientation. Spheres are free spheres,
// the rest clumps (Config::clump_shapes = the named gravel shapes). Throws std::invalid_argument for an
// unknown shape name or a bin too small for one particle per layer.
Config pour_config(const Config& base, const PourSpec& spec);

// The height of the lattice's top layer (the drop height of the last particle) for a spec.
double pour_top(const PourSpec& spec);

// The solid fraction of the box [lo, hi] covered by spheres (x, y, z, r rows): the fraction of a
// regular grid of samples^3 points inside at least one sphere.
double packing_fraction(const std::vector<std::array<double, 4>>& spheres, const std::array<double, 3>& lo,
                        const std::array<double, 3>& hi, int samples = 60);

// The measuring box of a settled bed: the bin less radius_max at the walls and floor, up to the height
// below which 90 % of the spheres' centres lie, less radius_max (empty when the bed is thinner).
void bed_box(const std::vector<std::array<double, 4>>& spheres, const PourSpec& spec, std::array<double, 3>& lo,
             std::array<double, 3>& hi);

}  // namespace polymech::dem
