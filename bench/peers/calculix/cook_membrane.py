"""Cook's membrane with CalculiX (the issue-34 peer): the reference of models/solid/cases.hpp.

  /usr/bin/python3 bench/peers/calculix/cook_membrane.py [--sizes 8 16 32 64] [--out DIR]

Debian's calculix-ccx (ccx 2.20). The panel (0, 0), (48, 44), (48, 60), (0, 44) as the bilinear image of the
unit square in n x n eight-node quadrilaterals (CPS8 plane stress, CPE8 plane strain), the edge x = 0
clamped, a uniform shear load of total F = 1 on x = 48 as consistent nodal loads (1/6, 4/6, 1/6 of each
edge's share), E = 1, nu = 1/3, unit thickness: the top-right vertical displacement is u E / F, which the
issue's case (E = 70, traction 6250, F = 1e5) multiplies by 1e5 / 70. Prints one line per element type and
size with the displacement and ccx's wall time, and the Richardson limit of the last three sizes.
"""
import argparse
import os
import subprocess
import time

CORNERS = [(0.0, 0.0), (48.0, 44.0), (48.0, 60.0), (0.0, 44.0)]


def write_input(path, n, element):
    m = 2 * n + 1  # lattice of corner and mid-side nodes

    def node(i, j):
        return 1 + i + m * j

    def position(i, j):
        s, t = i / (m - 1), j / (m - 1)
        w = [(1 - s) * (1 - t), s * (1 - t), s * t, (1 - s) * t]
        return sum(w[k] * CORNERS[k][0] for k in range(4)), sum(w[k] * CORNERS[k][1] for k in range(4))

    lines = ["*NODE"]
    for j in range(m):
        for i in range(m):
            if i % 2 == 1 and j % 2 == 1:
                continue  # the serendipity element has no centre node
            x, y = position(i, j)
            lines.append(f"{node(i, j)}, {x:.17g}, {y:.17g}")
    lines.append(f"*ELEMENT, TYPE={element}, ELSET=EALL")
    for cj in range(n):
        for ci in range(n):
            i, j = 2 * ci, 2 * cj
            c = [node(i, j), node(i + 2, j), node(i + 2, j + 2), node(i, j + 2),
                 node(i + 1, j), node(i + 2, j + 1), node(i + 1, j + 2), node(i, j + 1)]
            lines.append(f"{1 + ci + n * cj}, " + ", ".join(map(str, c)))
    lines += ["*NSET, NSET=CLAMPED"] + [str(node(0, j)) for j in range(m)]
    lines += ["*BOUNDARY", "CLAMPED, 1, 2",
              "*MATERIAL, NAME=M", "*ELASTIC", "1., 0.33333333333333333",
              "*SOLID SECTION, ELSET=EALL, MATERIAL=M", "1.",
              "*STEP", "*STATIC", "*CLOAD"]
    loads = {}
    share = 1.0 / n  # F = 1 spread uniformly over the n edges of x = 48
    for cj in range(n):
        for k, w in ((0, 1 / 6), (1, 4 / 6), (2, 1 / 6)):
            key = node(m - 1, 2 * cj + k)
            loads[key] = loads.get(key, 0.0) + w * share
    lines += [f"{k}, 2, {v:.17g}" for k, v in sorted(loads.items())]
    lines += ["*NSET, NSET=TIP", str(node(m - 1, m - 1)), "*NODE PRINT, NSET=TIP", "U", "*END STEP"]
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")


def tip_displacement(dat):
    with open(dat) as f:
        rows = [l.split() for l in f if l.strip()]
    for k, r in enumerate(rows):
        if r[:1] == ["displacements"]:
            return float(rows[k + 1][2])
    raise RuntimeError(f"{dat}: no displacement block")


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--sizes", type=int, nargs="+", default=[8, 16, 32, 64])
    p.add_argument("--out", default="out/peers/calculix_cook")
    a = p.parse_args()
    os.makedirs(a.out, exist_ok=True)
    for element in ("CPS8", "CPE8"):
        values = []
        for n in a.sizes:
            stem = os.path.join(a.out, f"cook_{element}_{n}")
            write_input(stem + ".inp", n, element)
            t0 = time.perf_counter()
            # in the output folder: ccx leaves spooles.out in its working folder
            subprocess.run(["ccx", "-i", os.path.basename(stem)], check=True, stdout=subprocess.DEVNULL, cwd=a.out,
                           env={**os.environ, "OMP_NUM_THREADS": "1"})
            seconds = time.perf_counter() - t0
            u = tip_displacement(stem + ".dat")
            values.append(u)
            print(f"{element} n={n:3d}: u E / F = {u:.6f}  ccx {seconds:.2f} s")
        if len(values) >= 3:
            x, y, z = values[-3:]
            print(f"{element} Richardson limit of the last three: {z + (z - y) ** 2 / ((y - x) - (z - y)):.4f}")


if __name__ == "__main__":
    main()
