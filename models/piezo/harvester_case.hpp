// A harvester case (issue 35; seed 002 paper 1) from its description (models/piezo/harvester_setup.hpp): the
// finite-element beam, its circuit and damping, and the three analyses apps/piezo_harvester runs, with the
// closed forms each is compared against. No I/O: the results come back as summary values and tables.
//
//   static     the prescribed electrodes at their potentials: the tip deflection and the electrode charges
//              against the laminated bender (harvester_analyses.hpp, closed form in harvester_closed_forms.hpp)
//   harmonic   the steady response per load and frequency, the Erturk-Inman bimorph (harvester_analyses.hpp)
//   transient  a_b(t) = A sin(w t) from rest as a model of the run driver (harvester_transient.hpp)
// The beam, circuit, damping, summary and tables of a case: harvester_beam.hpp. This header includes them all.
#pragma once

#include "piezo/harvester_analyses.hpp"
#include "piezo/harvester_beam.hpp"
#include "piezo/harvester_closed_forms.hpp"
#include "piezo/harvester_transient.hpp"
