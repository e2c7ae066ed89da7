// Stabilized ISPH operators (seed 002 paper 4, eqs. (9)-(13)) with the IGCB wall contributions
// (eqs. (15)-(24)) as neighbour functors run by neighbors::for_each_row, by stage of the fractional step:
//   sph/fluid.hpp      the fields (Fluid, WallPoints, Params) and AdditiveSum, the join of every sum;
//   sph/density.hpp    density, eqs. (13) + (18), and the free surface;
//   sph/ghosts.hpp     the ghost values at the wall points, eqs. (23)-(30);
//   sph/laplacian.hpp  the viscous predictor, eqs. (3), (11), (21), and the PPE operator, eqs. (10), (20);
//   sph/gradient.hpp   the PPE right-hand side, eqs. (4), (12), (22), the projection, eqs. (5), (9), (19),
//                      and the wall reactions, eqs. (38)-(43).
// Each operator is two passes: the fluid sum over the fluid-fluid list (into a scratch View), then the wall
// sum over the fluid -> wall integration point list, whose finish() writes the result. Wall values at the
// integration points come from ghost points mirrored into the fluid, computed over the ghost -> fluid list.
#pragma once

#include "sph/density.hpp"
#include "sph/fluid.hpp"
#include "sph/ghosts.hpp"
#include "sph/gradient.hpp"
#include "sph/laplacian.hpp"
