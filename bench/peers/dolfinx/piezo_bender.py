"""The PVDF bimorph bender with FEniCSx (the issue-35 peer): the same case as polymech's static bender.

  /usr/bin/python3 bench/peers/dolfinx/piezo_bender.py [--cells 10 20 40 80] [--order 2] [--polymech BIN]
                                                       [--repetitions 3]

Debian's python3-dolfinx (0.5.2). Hwang & Park's bimorph: L = 100 mm, two 0.5 mm PVDF layers poled oppositely
(E 2 GPa, nu 0.29, d31 = d32 = 2.2e-11 C/N, eps_r 12), 2D plane stress in the (length, thickness) plane,
n x 2 quadrilaterals of order p (one cell per layer, as polymech's models/piezo/cases.hpp), the root clamped,
the bottom face at 0 V and the top at 100 V, the interface free. The plane-stress law is the 3D one with the
width stress condensed out (as models/piezo/fe_law.hpp derives it, here in numpy from the same engineering
data). Unknowns (u, phi) in one mixed Lagrange space, a direct solve (PETSc LU, MUMPS when present). Prints,
per size, the tip deflection (mean of u_y over the tip face's nodes, like polymech) against the closed form
3 d31 V L^2 / (2 t^2) = 3.30e-5 m and the wall time of assembly + factorisation + solve, best of the
repetitions; with --polymech (build/ci/bench/sweep_piezo_fe) the same for polymech, run alternately.
"""
import argparse
import json
import logging
import subprocess
import sys
import time

import numpy as np

L, T, B = 0.1, 1e-3, 5e-3
E, NU, D31, EPS_R, V = 2e9, 0.29, 2.2e-11, 12.0, 100.0
EPS0 = 8.8541878128e-12


def plane_stress_law(poling):
    """C (3x3), e (2x3), eps (2x2) of the model plane (x = material 1, y = material 3), as fe_law.hpp."""
    s = np.zeros((6, 6))
    s[0, 0] = s[1, 1] = s[2, 2] = 1 / E
    s[0, 1] = s[1, 0] = s[0, 2] = s[2, 0] = s[1, 2] = s[2, 1] = -NU / E
    s[3, 3] = s[4, 4] = s[5, 5] = 2 * (1 + NU) / E
    C = np.linalg.inv(s)
    d = np.zeros((3, 6))
    d[2, 0] = d[2, 1] = D31
    e = d @ C
    eps = np.diag([EPS_R * EPS0] * 3) - d @ C @ d.T
    H = np.zeros((9, 9))
    H[:6, :6] = C
    H[:6, 6:] = -poling * e.T
    H[6:, :6] = poling * e
    H[6:, 6:] = eps
    H = H - np.outer(H[:, 1], H[1, :]) / H[1, 1]  # T2 = 0
    strain, field = [0, 2, 4], [6 + 0, 6 + 2]
    return H[np.ix_(strain, strain)], H[np.ix_(field, strain)], H[np.ix_(field, field)]


def solve(n, p):
    from mpi4py import MPI
    from petsc4py import PETSc
    import dolfinx
    import dolfinx.fem.petsc
    import ufl

    t0 = time.perf_counter()
    mesh = dolfinx.mesh.create_rectangle(MPI.COMM_SELF, [np.array([0.0, 0.0]), np.array([L, T])], [n, 2],
                                         dolfinx.mesh.CellType.quadrilateral)
    cell = mesh.ufl_cell()
    W = dolfinx.fem.FunctionSpace(mesh, ufl.MixedElement([ufl.VectorElement("Lagrange", cell, p),
                                                          ufl.FiniteElement("Lagrange", cell, p)]))
    (u, phi), (v, w) = ufl.TrialFunctions(W), ufl.TestFunctions(W)
    # poling: +1 in the lower layer, -1 in the upper (a DG0 sign)
    Q = dolfinx.fem.FunctionSpace(mesh, ("DG", 0))
    sign = dolfinx.fem.Function(Q)
    mid = dolfinx.mesh.compute_midpoints(mesh, mesh.topology.dim, np.arange(mesh.topology.index_map(mesh.topology.dim).size_local, dtype=np.int32))
    sign.x.array[:] = np.where(mid[:, 1] < 0.5 * T, 1.0, -1.0)
    Cm, em, epsm = plane_stress_law(1)
    C = ufl.as_matrix(Cm.tolist())
    e = ufl.as_matrix(em.tolist())
    eps = ufl.as_matrix(epsm.tolist())

    def strain(x):
        g = ufl.grad(x)
        return ufl.as_vector([g[0, 0], g[1, 1], g[0, 1] + g[1, 0]])

    # [Kuu Kuphi; Kuphi^T -Kpp] (assembly.hpp's signs), times the width
    a = B * (ufl.dot(strain(v), C * strain(u)) + sign * ufl.dot(strain(v), e.T * ufl.grad(phi))
             + sign * ufl.dot(ufl.grad(w), e * strain(u)) - ufl.dot(ufl.grad(w), eps * ufl.grad(phi))) * ufl.dx
    zero = dolfinx.fem.Constant(mesh, PETSc.ScalarType(0.0))
    rhs = zero * w * ufl.dx
    fdim = mesh.topology.dim - 1
    Wu, _ = W.sub(0).collapse()
    Wp, _ = W.sub(1).collapse()
    root = dolfinx.mesh.locate_entities_boundary(mesh, fdim, lambda x: np.isclose(x[0], 0.0))
    bottom = dolfinx.mesh.locate_entities_boundary(mesh, fdim, lambda x: np.isclose(x[1], 0.0))
    top = dolfinx.mesh.locate_entities_boundary(mesh, fdim, lambda x: np.isclose(x[1], T))
    u0 = dolfinx.fem.Function(Wu)
    p0 = dolfinx.fem.Function(Wp)
    pV = dolfinx.fem.Function(Wp)
    pV.x.array[:] = V
    bcs = [dolfinx.fem.dirichletbc(u0, dolfinx.fem.locate_dofs_topological((W.sub(0), Wu), fdim, root), W.sub(0)),
           dolfinx.fem.dirichletbc(p0, dolfinx.fem.locate_dofs_topological((W.sub(1), Wp), fdim, bottom), W.sub(1)),
           dolfinx.fem.dirichletbc(pV, dolfinx.fem.locate_dofs_topological((W.sub(1), Wp), fdim, top), W.sub(1))]
    problem = dolfinx.fem.petsc.LinearProblem(a, rhs, bcs=bcs, petsc_options={"ksp_type": "preonly", "pc_type": "lu"})
    x = problem.solve()
    seconds = time.perf_counter() - t0
    uh = x.sub(0).collapse()
    Vu = uh.function_space
    coords = Vu.tabulate_dof_coordinates()
    tip = np.where(np.isclose(coords[:, 0], L))[0]
    uy = uh.x.array.reshape(-1, 2)[tip, 1]
    return float(np.mean(uy)), seconds, W.dofmap.index_map.size_global * W.dofmap.index_map_bs


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--cells", type=int, nargs="+", default=[10, 20, 40, 80])
    ap.add_argument("--order", type=int, default=2)
    ap.add_argument("--repetitions", type=int, default=3)
    ap.add_argument("--polymech", default="", help="build/ci/bench/sweep_piezo_fe (runs its --bender mode)")
    args = ap.parse_args()
    logging.basicConfig(level=logging.WARNING)
    logging.getLogger().setLevel(logging.WARNING)  # FFCx's JIT logs its compiler lines at INFO
    try:
        import dolfinx  # noqa: F401
    except ImportError:
        print("piezo_bender.py: FEniCSx is not installed (apt-get install python3-dolfinx)", file=sys.stderr)
        return 2
    closed = 3 * D31 * V * L * L / (2 * T * T)
    print(f"closed form (beam): {closed:.6e} m")
    print("code      order cells unknowns  tip [m]       vs closed form  seconds (best of %d)" % args.repetitions)
    for n in args.cells:
        best = {}
        for _ in range(args.repetitions):
            tip, sec, dofs = solve(n, args.order)
            if "fenicsx" not in best or sec < best["fenicsx"][1]:
                best["fenicsx"] = (tip, sec, dofs)
            if args.polymech:
                out = subprocess.run([args.polymech, "--bender", str(args.order), str(n)], check=True,
                                     capture_output=True, text=True).stdout
                r = json.loads(out)
                if "polymech" not in best or r["seconds"] < best["polymech"][1]:
                    best["polymech"] = (r["tip"], r["seconds"], r["unknowns"])
        for code, (tip, sec, dofs) in best.items():
            print(f"{code:9s} {args.order:5d} {n:5d} {dofs:8d}  {abs(tip):.6e}  {abs(tip) / closed - 1:+.4%}  {sec:.4f}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
