#!/usr/bin/python3
"""The peer side by side on Turek-Hron CFD2 (issue 36): FEniCSx (DOLFINx 0.5, Debian's python3-dolfinx) with the
same discretisation as models/flow -- Taylor-Hood P2/P1 (here on triangles from Gmsh), steady Newton with MUMPS's
direct LU -- on the channel with the cylinder and the rigid flag: parabolic inflow of mean 1 m/s, rho 1000,
nu 1e-3, no slip, do-nothing outflow. Drag and lift on cylinder + flag by the surface integral of the stress
(-p I + mu (grad u + grad u^T)) n. One process, one thread; CPU time of mesh generation, set-up and solve.

  OMP_NUM_THREADS=1 python3 bench/peers/dolfinx/turek_hron_cfd2.py --h 0.02 --h-body 0.004 [--test 1|2]

Reference (Turek & Hron 2006, Table 12): CFD1 drag 14.29, lift 1.119; CFD2 drag 136.7, lift 10.53 (N/m).
Written for this comparison from the DOLFINx documentation; not derived from any other code.
"""
import argparse
import time

t_wall0 = time.perf_counter()
t_cpu0 = time.process_time()

import gmsh  # noqa: E402
import numpy as np  # noqa: E402
import ufl  # noqa: E402
from dolfinx import fem, nls  # noqa: E402
from dolfinx.io import gmshio  # noqa: E402
import dolfinx.fem.petsc  # noqa: E402,F401
import dolfinx.nls.petsc  # noqa: E402,F401
from mpi4py import MPI  # noqa: E402
from petsc4py import PETSc  # noqa: E402

ap = argparse.ArgumentParser()
ap.add_argument("--test", type=int, default=2)
ap.add_argument("--h", type=float, default=0.02, help="mesh size away from the body (m)")
ap.add_argument("--h-body", type=float, default=0.004, help="mesh size on the cylinder and flag (m)")
a = ap.parse_args()
t_import = time.process_time() - t_cpu0

L, H, cx, cy, r = 2.5, 0.41, 0.2, 0.2, 0.05
ubar = {1: 0.2, 2: 1.0}[a.test]
ref = {1: (14.29, 1.119), 2: (136.7, 10.53)}[a.test]
rho, nu = 1000.0, 1e-3
mu = rho * nu
INFLOW, OUTFLOW, WALL, BODY = 1, 2, 3, 4

c0 = time.process_time()
gmsh.initialize()
gmsh.option.setNumber("General.Terminal", 0)
gmsh.model.add("turek_hron")
occ = gmsh.model.occ
channel = occ.addRectangle(0, 0, 0, L, H)
circle = occ.addDisk(cx, cy, 0, r, r)
flag = occ.addRectangle(cx, 0.19, 0, 0.6 - cx, 0.02)
body, _ = occ.fuse([(2, circle)], [(2, flag)])
fluid, _ = occ.cut([(2, channel)], body)
occ.synchronize()
gmsh.model.addPhysicalGroup(2, [fluid[0][1]], 1)
marks = {INFLOW: [], OUTFLOW: [], WALL: [], BODY: []}
for dim, tag in gmsh.model.getBoundary(fluid, oriented=False):
    x, y, _ = occ.getCenterOfMass(dim, tag)
    if np.isclose(x, 0.0):
        marks[INFLOW].append(tag)
    elif np.isclose(x, L):
        marks[OUTFLOW].append(tag)
    elif np.isclose(y, 0.0) or np.isclose(y, H):
        marks[WALL].append(tag)
    else:
        marks[BODY].append(tag)
for k, v in marks.items():
    gmsh.model.addPhysicalGroup(1, v, k)
# size: h_body on the body, growing linearly to h over 0.1 m (Gmsh's distance/threshold fields)
fd = gmsh.model.mesh.field.add("Distance")
gmsh.model.mesh.field.setNumbers(fd, "CurvesList", marks[BODY])
gmsh.model.mesh.field.setNumber(fd, "NumPointsPerCurve", 200)
ft = gmsh.model.mesh.field.add("Threshold")
gmsh.model.mesh.field.setNumber(ft, "InField", fd)
gmsh.model.mesh.field.setNumber(ft, "SizeMin", a.h_body)
gmsh.model.mesh.field.setNumber(ft, "SizeMax", a.h)
gmsh.model.mesh.field.setNumber(ft, "DistMin", 0.0)
gmsh.model.mesh.field.setNumber(ft, "DistMax", 0.1)
gmsh.model.mesh.field.setAsBackgroundMesh(ft)
gmsh.option.setNumber("Mesh.MeshSizeExtendFromBoundary", 0)
gmsh.option.setNumber("Mesh.MeshSizeFromPoints", 0)
gmsh.option.setNumber("Mesh.MeshSizeFromCurvature", 0)
gmsh.model.mesh.generate(2)
gmsh.model.mesh.setOrder(2)  # curved (quadratic) triangles on the circle, as models/flow's isoparametric Q2
mesh, _, facets = gmshio.model_to_mesh(gmsh.model, MPI.COMM_WORLD, 0, gdim=2)
gmsh.finalize()
t_mesh = time.process_time() - c0

c0 = time.process_time()
P2 = ufl.VectorElement("Lagrange", mesh.ufl_cell(), 2)
P1 = ufl.FiniteElement("Lagrange", mesh.ufl_cell(), 1)
W = fem.FunctionSpace(mesh, ufl.MixedElement([P2, P1]))
V, _ = W.sub(0).collapse()
fdim = mesh.topology.dim - 1


def inflow(x):
    return np.stack((1.5 * ubar * x[1] * (H - x[1]) / (H / 2) ** 2, np.zeros(x.shape[1])))


u_in, u_zero = fem.Function(V), fem.Function(V)
u_in.interpolate(inflow)
bcs = []
for mark, g in ((INFLOW, u_in), (WALL, u_zero), (BODY, u_zero)):
    dofs = fem.locate_dofs_topological((W.sub(0), V), fdim, facets.find(mark))
    bcs.append(fem.dirichletbc(g, dofs, W.sub(0)))
w = fem.Function(W)
u, p = ufl.split(w)
v, q = ufl.TestFunctions(W)
F = (rho * ufl.inner(ufl.grad(u) * u, v) + mu * ufl.inner(ufl.grad(u), ufl.grad(v)) - p * ufl.div(v)
     - q * ufl.div(u)) * ufl.dx  # the gradient form: do-nothing outflow, as models/flow
# Oseen steps first (Picard, as models/flow's 3 steps from rest): Newton from zero diverges at Re 100
w_old = fem.Function(W)
u_old, _ = ufl.split(w_old)
du, dp = ufl.TrialFunctions(W)
a_os = (rho * ufl.inner(ufl.grad(du) * u_old, v) + mu * ufl.inner(ufl.grad(du), ufl.grad(v)) - dp * ufl.div(v)
        - q * ufl.div(du)) * ufl.dx
L_os = ufl.inner(fem.Constant(mesh, PETSc.ScalarType((0.0, 0.0))), v) * ufl.dx
oseen = fem.petsc.LinearProblem(a_os, L_os, bcs=bcs, u=w_old,
                                petsc_options={"ksp_type": "preonly", "pc_type": "lu", "pc_factor_mat_solver_type": "mumps"})
n_dofs = W.dofmap.index_map.size_global * W.dofmap.index_map_bs
t_setup = time.process_time() - c0

c0 = time.process_time()
for _ in range(3):
    oseen.solve()
w.x.array[:] = w_old.x.array
problem = fem.petsc.NonlinearProblem(F, w, bcs=bcs)
solver = nls.petsc.NewtonSolver(MPI.COMM_WORLD, problem)
solver.rtol, solver.atol, solver.convergence_criterion = 1e-10, 1e-10, "incremental"
ksp = solver.krylov_solver
opts = PETSc.Options()
pre = ksp.getOptionsPrefix()
opts[f"{pre}ksp_type"] = "preonly"
opts[f"{pre}pc_type"] = "lu"
opts[f"{pre}pc_factor_mat_solver_type"] = "mumps"
ksp.setFromOptions()
its, converged = solver.solve(w)
t_solve = time.process_time() - c0

u_h, p_h = w.split()
n = ufl.FacetNormal(mesh)
ds = ufl.Measure("ds", domain=mesh, subdomain_data=facets)
sigma = -p_h * ufl.Identity(2) + mu * (ufl.grad(u_h) + ufl.grad(u_h).T)
force = [fem.assemble_scalar(fem.form(-ufl.dot(sigma, n)[k] * ds(BODY))) for k in (0, 1)]
drag, lift = force
cpu = time.process_time() - t_cpu0
print(f"dolfinx CFD{a.test} h {a.h} h_body {a.h_body}: {mesh.topology.index_map(2).size_global} triangles, {n_dofs} DoFs; "
      f"3 Oseen + {its} Newton (converged {converged}); drag {drag:.4f} ({100 * (drag / ref[0] - 1):+.3f} %), "
      f"lift {lift:.4f} ({100 * (lift / ref[1] - 1):+.3f} %); CPU: import {t_import:.1f} s, mesh {t_mesh:.2f} s, "
      f"set-up {t_setup:.2f} s, solve {t_solve:.2f} s, total {cpu:.1f} s (wall {time.perf_counter() - t_wall0:.1f} s)")
