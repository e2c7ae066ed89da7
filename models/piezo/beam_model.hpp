// The finite-element piezoelectric beam (issue 35; seed 002 paper 1 eqs. (4)-(10)): a layered cantilever or
// free plate of piezoceramic and elastic layers, in 2D (plane stress or plane strain, the (length, thickness)
// plane) or 3D, with displacement and electric potential at the nodes (Lagrange order 1..4), electrodes as
// equipotential surfaces with one unknown each, a conducting grounded host (eq. (7)) and an external circuit.
// The matrices are assembled once (models/piezo/assembly.hpp) and the solvers (static, harmonic, natural
// frequencies here; time domain in models/piezo/transient.hpp) factorise them with the host sparse LU, which is
// the fast choice at these sizes (issue 34 measured the direct solve against CG on the same solid elements).
//
// Unknowns, in this order: the free displacement components (D per node, the clamped ones removed), the free
// potentials of the piezoelectric layers' interior nodes, then one potential per floating or prescribed
// electrode. A node gets no potential unknown when it touches no piezoelectric element, lies in or on the
// conducting host (grounded, eq. (7)), or lies on a grounded electrode.
//
// The pieces, by job:
//   beam_spec.hpp   the description (layers, electrodes, support, laws), Rayleigh damping, HarmonicResponse
//   piezo_beam.hpp  the class PiezoBeam: accessors, assembly, scaling, static / harmonic / natural-frequency solves
//   beam_mesh.hpp   the spec's checks, the mesh, the electrodes and supports, the numbering of the unknowns
// This header includes them all.
#pragma once

#include "piezo/beam_mesh.hpp"
#include "piezo/beam_spec.hpp"
#include "piezo/piezo_beam.hpp"
