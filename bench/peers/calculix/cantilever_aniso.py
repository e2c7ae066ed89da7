"""The 3D anisotropic cantilever, CalculiX against polymech side by side (the issue-34 peer on a 3D case).

  /usr/bin/python3 bench/peers/calculix/cantilever_aniso.py [--exe build/ci/bench/peer_solid_cantilever]
        [--theta 30] [--meshes 16x2x2 32x4x4 64x8x8] [--repeat 2] [--out DIR]

The beam of bench/peer_solid_cantilever.cpp: [0, 12] x [-1.25, 1.25] x [-1.5, 0] (um), cubic 8YSZ (C11, C12,
C44 = 401, 96, 56 GPa) rotated to a beam axis at theta from [001] in the (110) top face, clamped at x = 0, a
uniform traction of total force 0.1 mN along -z on x = 12; units GPa = mN/um^2, um, mN. Output: the vertical
displacement of the end face's centre node (12, 0, -0.75).

CalculiX (Debian calculix-ccx 2.20): 20-node hexahedra (C3D20 and C3D20R) on the same box lattices,
*ELASTIC, TYPE=ANISO with the 21 rotated constants (tensor components, equal to the Voigt entries with
engineering shears), the end-face traction as consistent nodal loads of the 8-node faces (corners -A/12,
mid-sides A/3). polymech: order 2 (27-node) and 3 elements, CG with the two-level p-multigrid (`mg`) and with
Jacobi (`cg`). Each code runs single-threaded (OMP_NUM_THREADS=1, CCX_NPROC_EQUATION_SOLVER=1), the two
alternating, `--repeat` times; reported: CPU time of the process (user + system, from the OS), the best of
the repeats, and the error of the tip displacement against the Richardson limit of polymech's order-3
results on the three meshes.
"""
import argparse
import math
import os
import resource
import subprocess
import tempfile
import time

L, W, H, F = 12.0, 2.5, 1.5, 0.1
C11, C12, C44 = 401.0, 96.0, 56.0
VOIGT = [(0, 0), (1, 1), (2, 2), (1, 2), (0, 2), (0, 1)]  # polymech's order: 11, 22, 33, 23, 13, 12


def rotation(theta):
    """Rows: beam axis, width, top normal, in crystal coordinates (kernels/materials/cubic_elastic.hpp)."""
    c, s, r = math.cos(theta), math.sin(theta), 1.0 / math.sqrt(2.0)
    return [[s * r, -s * r, c], [c * r, -c * r, -s], [r, r, 0.0]]


def rotated_stiffness(theta):
    R3 = range(3)

    def crystal(a, b, c, d):
        if a == b and c == d:
            return C11 if a == c else C12
        return C44 if (a == c and b == d) or (a == d and b == c) else 0.0

    Q = rotation(theta)
    nonzero = [(a, b, c, d, crystal(a, b, c, d)) for a in R3 for b in R3 for c in R3 for d in R3
               if crystal(a, b, c, d) != 0.0]
    return {(i, j, k, l): sum(Q[i][a] * Q[j][b] * Q[k][c] * Q[l][d] * v for a, b, c, d, v in nonzero)
            for i in R3 for j in R3 for k in R3 for l in R3}


def aniso_constants(Ct):
    names = ["1111", "1122", "2222", "1133", "2233", "3333", "1112", "2212", "3312", "1212", "1113", "2213",
             "3313", "1213", "1313", "1123", "2223", "3323", "1223", "1323", "2323"]
    return [Ct[(int(n[0]) - 1, int(n[1]) - 1, int(n[2]) - 1, int(n[3]) - 1)] for n in names]


def write_ccx(path, nx, ny, nz, element, theta):
    mx, my, mz = 2 * nx + 1, 2 * ny + 1, 2 * nz + 1  # lattice of corner, edge and (unused) face/centre nodes
    ids = {}

    def node(i, j, k):
        return ids[(i, j, k)]

    lines = ["*NODE"]
    for k in range(mz):
        for j in range(my):
            for i in range(mx):
                if (i % 2) + (j % 2) + (k % 2) >= 2:
                    continue  # serendipity: no face or centre nodes
                ids[(i, j, k)] = len(ids) + 1
                x, y, z = L * i / (mx - 1), -0.5 * W + W * j / (my - 1), -H + H * k / (mz - 1)
                lines.append(f"{ids[(i, j, k)]}, {x:.17g}, {y:.17g}, {z:.17g}")
    lines.append(f"*ELEMENT, TYPE={element}, ELSET=EALL")
    e = 0
    for ck in range(nz):
        for cj in range(ny):
            for ci in range(nx):
                i, j, k = 2 * ci, 2 * cj, 2 * ck
                corners = [(i, j, k), (i + 2, j, k), (i + 2, j + 2, k), (i, j + 2, k),
                           (i, j, k + 2), (i + 2, j, k + 2), (i + 2, j + 2, k + 2), (i, j + 2, k + 2)]
                mids = [(i + 1, j, k), (i + 2, j + 1, k), (i + 1, j + 2, k), (i, j + 1, k),
                        (i + 1, j, k + 2), (i + 2, j + 1, k + 2), (i + 1, j + 2, k + 2), (i, j + 1, k + 2),
                        (i, j, k + 1), (i + 2, j, k + 1), (i + 2, j + 2, k + 1), (i, j + 2, k + 1)]
                nodes = [node(*c) for c in corners + mids]
                e += 1
                lines.append(f"{e}, " + ", ".join(map(str, nodes[:15])) + ",")
                lines.append(", ".join(map(str, nodes[15:])))
    lines.append("*NSET, NSET=CLAMPED")
    lines += [str(v) for (i, j, k), v in ids.items() if i == 0]
    d = aniso_constants(rotated_stiffness(theta))
    lines += ["*BOUNDARY", "CLAMPED, 1, 3", "*MATERIAL, NAME=YSZ", "*ELASTIC, TYPE=ANISO"]
    d = [v if abs(v) > 1e-12 * C11 else 0.0 for v in d] + [0.0]  # the 22nd value: the temperature
    for s in range(0, 22, 8):
        lines.append(", ".join(f"{v:.12e}" for v in d[s:s + 8]))
    lines += ["*SOLID SECTION, ELSET=EALL, MATERIAL=YSZ", "*STEP", "*STATIC", "*CLOAD"]
    loads = {}
    area = (W / ny) * (H / nz)
    t = -F / (W * H)
    for ck in range(nz):
        for cj in range(ny):
            j, k = 2 * cj, 2 * ck
            for (a, b), w in [((0, 0), -1 / 12), ((2, 0), -1 / 12), ((2, 2), -1 / 12), ((0, 2), -1 / 12),
                              ((1, 0), 1 / 3), ((2, 1), 1 / 3), ((1, 2), 1 / 3), ((0, 1), 1 / 3)]:
                v = node(mx - 1, j + a, k + b)
                loads[v] = loads.get(v, 0.0) + w * area * t
    lines += [f"{v}, 3, {f:.17g}" for v, f in sorted(loads.items())]
    tip = node(mx - 1, ny, nz)  # (12, 0, -0.75)
    lines += ["*NSET, NSET=TIP", str(tip), "*NODE PRINT, NSET=TIP", "U", "*END STEP"]
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")
    return 3 * len(ids)


def child_cpu():
    r = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r.ru_utime + r.ru_stime


def run_ccx(work, nx, ny, nz, element, theta):
    job = os.path.join(work, f"cant_{element}_{nx}_{ny}_{nz}")
    dofs = write_ccx(job + ".inp", nx, ny, nz, element, theta)
    env = dict(os.environ, OMP_NUM_THREADS="1", CCX_NPROC_EQUATION_SOLVER="1", CCX_NPROC_STIFFNESS="1")
    c0, t0 = child_cpu(), time.perf_counter()
    subprocess.run(["ccx", "-i", job], cwd=work, env=env, check=True, stdout=subprocess.DEVNULL)
    cpu, wall = child_cpu() - c0, time.perf_counter() - t0
    with open(job + ".dat") as f:
        rows = [l.split() for l in f if l.strip() and l.split()[0].isdigit()]
    return float(rows[-1][3]), dofs, cpu, wall


def run_ours(exe, order, nx, ny, nz, solver, theta_deg):
    env = dict(os.environ, OMP_NUM_THREADS="1", OMP_PROC_BIND="false")
    c0, t0 = child_cpu(), time.perf_counter()
    out = subprocess.run([exe, str(order), str(nx), str(ny), str(nz), str(theta_deg), solver], env=env, check=True,
                         capture_output=True, text=True).stdout.strip().splitlines()[-1].split(",")
    cpu, wall = child_cpu() - c0, time.perf_counter() - t0
    return float(out[8]), int(out[5]), cpu, wall, int(out[7])


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--exe", default="build/ci/bench/peer_solid_cantilever")
    ap.add_argument("--theta", type=float, default=30.0)
    ap.add_argument("--meshes", nargs="+", default=["16x2x2", "32x4x4", "64x8x8"])
    ap.add_argument("--repeat", type=int, default=2)
    ap.add_argument("--out", default=None)
    a = ap.parse_args()
    meshes = [tuple(int(v) for v in m.split("x")) for m in a.meshes]
    theta = math.radians(a.theta)
    work = a.out or tempfile.mkdtemp(prefix="ccx_cantilever_")
    os.makedirs(work, exist_ok=True)
    # reference: Richardson limit of polymech order 3 on the three meshes (refinement ratio 2)
    v = [run_ours(a.exe, 3, *m, "mg", a.theta)[0] for m in meshes[-3:]]
    den = (v[1] - v[0]) - (v[2] - v[1])
    ref = v[2] + (v[2] - v[1]) ** 2 / den if den != 0 else v[2]
    print(f"reference (polymech order 3, Richardson on {a.meshes[-3:]}): {ref:.9g} um  ({v})")
    rows = []
    for m in meshes:
        best = {}
        for _ in range(a.repeat):  # alternate the codes
            for key, fn in [("ccx C3D20", lambda: run_ccx(work, *m, "C3D20", theta)),
                            ("ccx C3D20R", lambda: run_ccx(work, *m, "C3D20R", theta)),
                            ("polymech p=2 mg", lambda: run_ours(a.exe, 2, *m, "mg", a.theta)[:4]),
                            ("polymech p=2 cg", lambda: run_ours(a.exe, 2, *m, "cg", a.theta)[:4]),
                            ("polymech p=3 mg", lambda: run_ours(a.exe, 3, *m, "mg", a.theta)[:4])]:
                tip, dofs, cpu, wall = fn()
                if key not in best or cpu < best[key][2]:
                    best[key] = (tip, dofs, cpu, wall)
        for key, (tip, dofs, cpu, wall) in best.items():
            rows.append((key, m, dofs, tip, abs(tip / ref - 1.0), cpu, wall))
            print(f"{key:18s} {m[0]:3d}x{m[1]}x{m[2]}  DoFs {dofs:7d}  tip {tip:.9g}  error {abs(tip / ref - 1.0):.2e}"
                  f"  CPU {cpu:7.3f} s  wall {wall:7.3f} s", flush=True)
    with open(os.path.join(work, "cantilever_aniso.csv"), "w") as f:
        f.write("code,nx,ny,nz,dofs,tip,error,cpu_seconds,wall_seconds\n")
        for key, m, dofs, tip, err, cpu, wall in rows:
            f.write(f"{key},{m[0]},{m[1]},{m[2]},{dofs},{tip:.10g},{err:.4e},{cpu:.4f},{wall:.4f}\n")
    print("CSV:", os.path.join(work, "cantilever_aniso.csv"))


if __name__ == "__main__":
    main()
