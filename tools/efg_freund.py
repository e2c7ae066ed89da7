#!/usr/bin/env python3
"""Freund's onset test of the EFG running crack (issue 14; docs/VALIDATION.md, "Running crack"): reads the
sif_history.csv of a stationary run and of running runs of scenes/efg/chen_centre_crack_freund.toml (same
node set, same dt), prints K_running / K_stationary after the onset against Freund's universal function
k(v), the J' path spread while running and after the arrest, and plots the histories.
  /usr/bin/python3 tools/efg_freund.py STAT_DIR RUN_DIR[:label] ... [--png out.png]
  /usr/bin/python3 tools/efg_freund.py --self-test      (checks of k(v); prints the k(v) table)
  /usr/bin/python3 tools/efg_freund.py --fft-check      (k(v) from a grid solution, numpy + scipy, 2 min)
Each DIR holds summary.json and sif_history.csv (or give DIR/prefix to read prefix_summary.json and
prefix_sif_history.csv).

The exact mode-I universal function (plane strain), slownesses a = 1/c_d, b = 1/c_s, c = 1/c_R:

  k(v) = (1 - v/c_R) / sqrt(1 - v/c_d) * S_-(1/v),   k(0) = 1,

  S_+(w) = exp{ -1/pi int_a^b Theta(eta) d eta / (eta + w) },
  S_-(w) = exp{ -1/pi int_a^b Theta(eta) d eta / (eta - w) },      (so S_-(1/v) = S_+(-1/v) >= 1)
  Theta(eta) = arctan[ 4 eta^2 sqrt(eta^2 - a^2) sqrt(b^2 - eta^2) / (b^2 - 2 eta^2)^2 ]  in [0, pi/2],

the factors of the Rayleigh function R(w) = (b^2 - 2w^2)^2 + 4 w^2 sqrt(a^2 - w^2) sqrt(b^2 - w^2) =
2 (b^2 - a^2)(c^2 - w^2) S_+(w) S_-(w) (S_+ regular off [-b, -a], S_- off [a, b], both -> 1 at infinity).
Source: Freund's Wiener-Hopf route (Freund 1972, J. Mech. Phys. Solids 20, 129: a crack at rest under a
time-independent load starts to run at v; Freund 1990, Dynamic Fracture Mechanics, ch. 7), worked here
for the K-field load (the stationary K-field released on 0 < x < v t): in the tip frame xi = x - v t with
Laplace parameter s and two-sided transform parameter s zeta, the lab slowness is w = zeta / (1 - v zeta);
the kernel (1 - v zeta) R(w) / alpha(w) factorises into K_+(zeta) = (c/(1 - v c) + zeta) S_+(w) /
sqrt(a/(1 - v a) + zeta) times a minus factor; the released load has one pole, at zeta = 1/v (w = oo), and
with K_+(1/v) = sqrt(1 - v/c_d) / (sqrt(v) (1 - v/c_R)) and K_+(zeta)/sqrt(zeta) -> S_+(-1/v) = S_-(1/v) at
the tip (zeta -> oo, w -> -1/v) the tip's K is K_0 k(v) with k(v) above. We did not find the book's
equation text to quote; `--self-test` checks the factorisation identity, k(0) = 1, k(c_R) = 0, monotony,
the quadrature, and the energy identity
  g(v) = A_I(v) k(v)^2 = (1 - v/c_R)/(1 + v/c_R) * sqrt((1 + v/c_d)/(1 - v/c_d)) * S_-(1/v) / S_+(1/v).
With mode III's kernel the same steps give Freund's k_III = sqrt(1 - v/c_s). `--fft-check` solves the same
tip-frame problem on a grid without the factorisation: 0.974 - 0.978 of k(v) at four speeds (0.3 - 0.7 c_R,
nu = 0.25 and 0.394), where k_a is 0.94 - 0.75 of it.
The integrals: eta = a + (b - a)(1 - cos phi)/2 (removes the square-root end points), Gauss-Legendre in phi.
"""
import csv
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from plotting import InputError, guarded, read_json  # noqa: E402


def paths(d):
    if os.path.isdir(d):
        return os.path.join(d, "summary.json"), os.path.join(d, "sif_history.csv")
    return d + "_summary.json", d + "_sif_history.csv"


def read(d):
    js, cs = paths(d)
    for p in (cs, js):
        if not os.path.isfile(p):
            raise InputError(f"{p}: not found (give an efg dynamic run's --out folder, or DIR/prefix of stored runs)")
    with open(cs) as f:
        rows = list(csv.DictReader(f))
    if not rows or "t_us" not in rows[0] or "K_factor_mean" not in rows[0]:
        raise InputError(f"{cs}: not a sif_history.csv of the efg app (columns t_us, K_factor_mean, ...)")
    h = {k: [float(r[k]) for r in rows] for k in rows[0]}
    s = read_json(js)
    return h, s


def wave_speeds(E, nu, rho, plane_strain=True):
    mu = E / (2 * (1 + nu))
    lam = E * nu / ((1 + nu) * (1 - 2 * nu))
    if not plane_strain:
        lam = 2 * lam * mu / (lam + 2 * mu)
    cs = math.sqrt(mu / rho)
    cd = math.sqrt((lam + 2 * mu) / rho)
    k = (cs / cd) ** 2
    # Rayleigh: (2 - x)^2 = 4 sqrt(1 - k x) sqrt(1 - x), x = (c_R / c_s)^2, by bisection
    f = lambda x: (2 - x) ** 2 - 4 * math.sqrt(1 - k * x) * math.sqrt(1 - x)
    lo, hi = 0.5, 1 - 1e-12
    for _ in range(200):
        m = 0.5 * (lo + hi)
        if f(lo) * f(m) <= 0:
            hi = m
        else:
            lo = m
    return cd, cs, cs * math.sqrt(lo)


def velocity_factor(v, cd, cs, nu):
    # Freund's A_I(v): J' = A_I K^2 / E' (plane strain nu)
    ad = math.sqrt(1 - v * v / cd ** 2)
    a_s = math.sqrt(1 - v * v / cs ** 2)
    D = 4 * ad * a_s - (1 + a_s * a_s) ** 2
    return v * v * ad / ((1 - nu) * cs * cs * D)


def gauss_legendre(n):
    # nodes and weights on [-1, 1]: Newton on the Legendre recurrence
    xs, ws = [], []
    for i in range(1, n + 1):
        x = math.cos(math.pi * (i - 0.25) / (n + 0.5))
        for _ in range(100):
            p0, p1 = 1.0, x
            for k in range(2, n + 1):
                p0, p1 = p1, ((2 * k - 1) * x * p1 - (k - 1) * p0) / k
            dp = n * (x * p1 - p0) / (x * x - 1)
            dx = p1 / dp
            x -= dx
            if abs(dx) < 1e-16:
                break
        xs.append(x)
        ws.append(2 / ((1 - x * x) * dp * dp))
    return xs, ws


_GL = {}


def theta(eta, a, b):
    # arg of the Rayleigh function on the slowness band a < eta < b (in [0, pi/2])
    q = 4 * eta * eta * math.sqrt(max(eta * eta - a * a, 0.0)) * math.sqrt(max(b * b - eta * eta, 0.0))
    return math.atan2(q, (b * b - 2 * eta * eta) ** 2)


def band_integral(f, a, b, n=64):
    # int_a^b f(eta) d eta with eta = a + (b - a)(1 - cos phi)/2, Gauss-Legendre in phi on [0, pi]
    if n not in _GL:
        _GL[n] = gauss_legendre(n)
    xs, ws = _GL[n]
    tot = 0.0
    for x, w in zip(xs, ws):
        phi = 0.5 * math.pi * (x + 1)
        eta = a + 0.5 * (b - a) * (1 - math.cos(phi))
        tot += w * f(eta) * 0.5 * (b - a) * math.sin(phi)
    return 0.5 * math.pi * tot


def log_s_plus(w, cd, cs, n=64):
    a, b = 1 / cd, 1 / cs
    return -band_integral(lambda e: theta(e, a, b) / (e + w), a, b, n) / math.pi


def log_s_minus(w, cd, cs, n=64):
    a, b = 1 / cd, 1 / cs
    return -band_integral(lambda e: theta(e, a, b) / (e - w), a, b, n) / math.pi


def k_exact(v, cd, cs, cR, n=64):
    # Freund's universal function, mode I (module docstring)
    if v < 0 or v > cR:
        raise ValueError("k(v) needs 0 <= v <= c_R")
    if v == 0:
        return 1.0
    if v == cR:
        return 0.0
    return (1 - v / cR) / math.sqrt(1 - v / cd) * math.exp(log_s_minus(1 / v, cd, cs, n))


def k_approx(v, cd, cR):
    return (1 - v / cR) / math.sqrt(1 - v / cd)


def k_energy(v, cd, cs, cR, nu):
    return math.sqrt((1 - v / cR) / velocity_factor(v, cd, cs, nu)) if v > 0 else 1.0


def speeds_from_nu(nu):
    # plane strain, c_s = 1 (E, rho chosen so)
    E = 2 * (1 + nu)
    return wave_speeds(E, nu, 1.0)


def self_test():
    fails = []

    def check(ok, what):
        print(("ok   " if ok else "FAIL ") + what)
        if not ok:
            fails.append(what)

    xs, ws = gauss_legendre(20)
    check(abs(sum(ws) - 2) < 1e-13 and abs(sum(w * x ** 4 for x, w in zip(xs, ws)) - 0.4) < 1e-13,
          "Gauss-Legendre n = 20 integrates 1 and x^4 on [-1, 1]")
    q = band_integral(lambda e: math.sqrt(e - 1) * math.sqrt(3 - e), 1.0, 3.0, 32)
    check(abs(q - math.pi / 2) < 1e-12, f"band integral of sqrt((e-1)(3-e)) on [1, 3] = {q:.15f} (pi/2)")
    for nu in (0.25, 0.3, 0.394):
        cd, cs, cR = speeds_from_nu(nu)
        a, b, c = 1 / cd, 1 / cs, 1 / cR
        # quadrature convergence and cross-check with scipy where present
        w = 1 / (0.7 * cR)
        l64, l256 = log_s_minus(w, cd, cs, 64), log_s_minus(w, cd, cs, 256)
        check(abs(l64 - l256) < 1e-12, f"nu = {nu}: log S_-(1/0.7c_R) n = 64 vs 256: {l64:.15f} {l256:.15f}")
        try:
            from scipy.integrate import quad

            ref = -quad(lambda e: theta(e, a, b) / (e - w), a, b, limit=200, epsabs=1e-14)[0] / math.pi
            check(abs(l64 - ref) < 1e-10, f"nu = {nu}: ... against scipy quad {ref:.15f}")
        except ImportError:
            print("     (scipy not present: no second quadrature)")
        # factorisation identity at w = 1/v > c: S_+ S_- = R / (2 (b^2 - a^2)(c^2 - w^2))
        worst = 0.0
        for f in (0.05, 0.2, 0.4, 0.6, 0.8, 0.95, 0.999):
            v = f * cR
            w = 1 / v
            R = (b * b - 2 * w * w) ** 2 - 4 * w * w * math.sqrt(w * w - a * a) * math.sqrt(w * w - b * b)
            S = R / (2 * (b * b - a * a) * (c * c - w * w))
            worst = max(worst, abs(math.exp(log_s_plus(w, cd, cs) + log_s_minus(w, cd, cs)) / S - 1))
        check(worst < 1e-10, f"nu = {nu}: S_+(1/v) S_-(1/v) = S(1/v) to {worst:.1e} (0.05 - 0.999 c_R)")
        # limits and monotony
        e0 = abs(k_exact(1e-7 * cR, cd, cs, cR) - 1)
        check(e0 < 1e-6, f"nu = {nu}: k(1e-7 c_R) = 1 - {e0:.1e}")
        kR = k_exact((1 - 1e-7) * cR, cd, cs, cR)
        check(kR < 1e-6 and k_exact(cR, cd, cs, cR) == 0.0, f"nu = {nu}: k((1 - 1e-7) c_R) = {kR:.1e}, k(c_R) = 0")
        ks = [k_exact(cR * i / 200, cd, cs, cR) for i in range(201)]
        check(all(ks[i + 1] < ks[i] for i in range(200)), f"nu = {nu}: k decreasing on 201 points of [0, c_R]")
        # slope at 0: log k ~ -v (c - h/2), h = a + (2/pi) int Theta
        h = a + 2 / math.pi * band_integral(lambda e: theta(e, a, b), a, b)
        v = 1e-4 * cR
        slope = -math.log(k_exact(v, cd, cs, cR)) / v
        check(abs(slope / (c - h / 2) - 1) < 1e-3, f"nu = {nu}: -d log k/dv at 0 = {slope * cR:.5f}/c_R, c - h/2 = {(c - h / 2) * cR:.5f}/c_R")
        # energy identity: A_I k^2 against the closed form of the factors
        worst = 0.0
        for f in (0.1, 0.3, 0.5, 0.7, 0.9, 0.99):
            v = f * cR
            g = velocity_factor(v, cd, cs, nu) * k_exact(v, cd, cs, cR) ** 2
            gf = (1 - v / cR) / (1 + v / cR) * math.sqrt((1 + v / cd) / (1 - v / cd)) * math.exp(
                log_s_minus(1 / v, cd, cs) - log_s_plus(1 / v, cd, cs))
            worst = max(worst, abs(g / gf - 1))
        check(worst < 1e-10, f"nu = {nu}: A_I k^2 = (1-v/c_R)/(1+v/c_R) sqrt((1+v/c_d)/(1-v/c_d)) S_-/S_+ to {worst:.1e}")
        # the two approximations (reported, not asserted)
        print(f"     nu = {nu}: c_d/c_s = {cd / cs:.4f}, c_R/c_s = {cR / cs:.4f}, h c_d = {h * cd:.4f}")
        print("     v/c_R:               " + " ".join(f"{f:7.2f}" for f in (0.1, 0.3, 0.5, 0.7, 0.9)))
        rows = {"k exact": [], "k_a / k - 1": [], "k_h / k - 1": [], "g = A_I k^2": [], "g/(1-v/c_R) - 1": []}
        for f in (0.1, 0.3, 0.5, 0.7, 0.9):
            v = f * cR
            k = k_exact(v, cd, cs, cR)
            g = velocity_factor(v, cd, cs, nu) * k * k
            rows["k exact"].append(k)
            rows["k_a / k - 1"].append(k_approx(v, cd, cR) / k - 1)
            rows["k_h / k - 1"].append((1 - v / cR) / math.sqrt(1 - h * v) / k - 1)
            rows["g = A_I k^2"].append(g)
            rows["g/(1-v/c_R) - 1"].append(g / (1 - f) - 1)
        for key, vals in rows.items():
            print(f"     {key:21s}" + " ".join(f"{x:7.3f}" for x in vals))
    E, nu, rho = 7.562e9, 0.394, 1191.0
    cd, cs, cR = wave_speeds(E, nu, rho)
    print(f"\nthe paper's material, plane strain: c_d = {cd:.1f}, c_s = {cs:.1f}, c_R = {cR:.1f} m/s")
    print("| v [m/s] | v/c_R | k exact | k_a | k_g | A_I | g = A_I k^2 | 1 - v/c_R |")
    print("|---|---|---|---|---|---|---|---|")
    for v in (0.0, 250.0, 500.0, 750.0, 1000.0, 1250.0):
        k = k_exact(v, cd, cs, cR)
        A = velocity_factor(v, cd, cs, nu) if v > 0 else 1.0
        print(f"| {v:.0f} | {v / cR:.3f} | {k:.4f} | {k_approx(v, cd, cR):.4f} | {k_energy(v, cd, cs, cR, nu):.4f} | {A:.4f} | {A * k * k:.4f} | {1 - v / cR:.4f} |")
    print("self-test: " + ("all checks passed" if not fails else f"{len(fails)} FAILED"))
    return 1 if fails else 0


def fft_check(cases=((0.25, 0.3), (0.25, 0.7), (0.394, 0.5), (0.394, 1000.0 / 1420.5935)), n=131072, length=40.0):
    """Independent of the factorisation: solve the tip-frame problem of the released K field (Laplace
    parameter s = 1, c_s = 1, mu = 1, K_0 = 1) on a periodic grid. Kernel on zeta = i k (fields
    exp(s t + s zeta xi)): sigma = -(1/b^2) N / ((1 - v zeta)^2 alpha_v) u, alpha_v = sqrt(a^2 (1 - v zeta)^2
    - zeta^2), N = (b^2 (1 - v zeta)^2 - 2 zeta^2)^2 + 4 zeta^2 alpha_v beta_v; crack faces xi < 0 loaded by
    -exp(xi/v)/sqrt(2 v), u = 0 ahead; GMRES for u; K = the xi^0 term of sigma sqrt(2 pi xi) ahead, fitted as
    a cubic in sqrt(xi) on (30 h, 0.05]. Needs numpy and scipy; about 30 s a case."""
    import numpy as np
    from scipy.sparse.linalg import LinearOperator, gmres

    print("| nu | v/c_R | K from the grid solution | k exact | k_a |")
    print("|---|---|---|---|---|")
    for nu, f in cases:
        cd, cs, cR = speeds_from_nu(nu)
        a, b = 1 / cd, 1 / cs
        v = f * cR
        h = length / n
        xi = (np.arange(n) - n // 2) * h
        z = 1j * 2 * np.pi * np.fft.fftfreq(n, h)
        av = np.sqrt(a * a * (1 - v * z) ** 2 - z * z)
        bv = np.sqrt(b * b * (1 - v * z) ** 2 - z * z)
        ker = -((b * b * (1 - v * z) ** 2 - 2 * z * z) ** 2 + 4 * z * z * av * bv) / ((1 - v * z) ** 2 * av) / b ** 2
        idx = np.where(xi < 0)[0]

        def stress(u):
            full = np.zeros(n)
            full[idx] = u
            return np.real(np.fft.ifft(ker * np.fft.fft(full)))

        load = -np.exp(xi[idx] / v) / math.sqrt(2 * v)
        op = LinearOperator((len(idx), len(idx)), matvec=lambda u: stress(u)[idx], dtype=float)
        try:
            u, info = gmres(op, load, rtol=1e-10, restart=200, maxiter=2000)
        except TypeError:
            u, info = gmres(op, load, tol=1e-10, restart=200, maxiter=2000)
        sig = stress(u)
        m = (xi >= 30 * h) & (xi <= 0.05)
        fit = np.polyfit(np.sqrt(xi[m]), sig[m] * np.sqrt(2 * np.pi * xi[m]), 3)[-1]
        print(f"| {nu} | {f:.3f} | {fit:.4f}{'' if info == 0 else ' (GMRES info %d)' % info} | "
              f"{k_exact(v, cd, cs, cR):.4f} | {k_approx(v, cd, cR):.4f} |")


def spread(h, i):
    ks = [h[k][i] for k in h if k.startswith("K_factor_r")]
    j = [x * x for x in ks]
    return (max(j) - min(j)) / max(j) if max(j) > 0 else 0.0


def main():
    if "-h" in sys.argv[1:] or "--help" in sys.argv[1:]:
        print(__doc__)
        return 0
    if "--self-test" in sys.argv:
        return self_test()
    if "--fft-check" in sys.argv:
        return fft_check() or 0
    args = [a for a in sys.argv[1:] if not a.startswith("--")]
    png = None
    if "--png" in sys.argv:
        png = sys.argv[sys.argv.index("--png") + 1]
        args = [a for a in args if a != png]
    if not args:
        raise InputError("give STAT_DIR RUN_DIR[:label] ... (efg dynamic runs' --out folders; --help for more)")
    if len(args) < 2:
        raise InputError(f"{args[0]}: give a running-crack run after the stationary one (STAT_DIR RUN_DIR[:label] ...)")
    E, nu, rho = 7.562e9, 0.394, 1191.0
    cd, cs, cR = wave_speeds(E, nu, rho)
    print(f"plane strain: c_d = {cd:.1f} m/s, c_s = {cs:.1f} m/s, c_R = {cR:.1f} m/s")
    hs, ss = read(args[0])
    ts = hs["t_us"]
    runs = []
    for a in args[1:]:
        d, _, label = a.partition(":")
        h, s = read(d)
        runs.append((label or os.path.basename(d), h, s))
    print("| run | v [m/s] | k(v) exact | k_a(v) | k_g(v) | K_run/K_stat at t0+dt | mean over (t0, t0+0.5 us] | mean while running | J' spread running (mean / max) | after arrest (mean / max) |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for label, h, s in runs:
        if "growth_speed" not in s:
            raise InputError(f"{s.path}: no growth_speed (not a running-crack efg run)")
        v = s["growth_speed"]
        t0 = s["growth_start_us"]
        a0 = s["j_radii"] and None
        dt = s["dt"] * 1e6
        t_end = t0 + (s["final_crack_length"] - 0.0024) / v * 1e6
        ke = k_exact(v, cd, cs, cR)
        ka = k_approx(v, cd, cR)
        kg = k_energy(v, cd, cs, cR, nu)
        ratio = []
        sp_run, sp_arr = [], []
        for i, t in enumerate(h["t_us"]):
            j = min(range(len(ts)), key=lambda q: abs(ts[q] - t))
            if t0 + 0.5 * dt < t <= t_end + 0.01 * dt and hs["K_factor_mean"][j] != 0:
                ratio.append((t, h["K_factor_mean"][i] / hs["K_factor_mean"][j]))
                sp_run.append(spread(h, i))
            elif t > t_end + 0.5 * dt:
                sp_arr.append(spread(h, i))
        if not ratio:
            print(f"| {label} | {v:.0f} | {ke:.3f} | {ka:.3f} | {kg:.3f} | - | - | - | - | - |  (no sample of both runs while running)")
            continue
        first = ratio[0][1]
        early = [r for t, r in ratio if t <= t0 + 0.5 + 1e-6]
        mean_early = sum(early) / len(early)
        mean_all = sum(r for _, r in ratio) / len(ratio)
        fmt = lambda x: f"{100 * sum(x) / len(x):.1f} % / {100 * max(x):.1f} %" if x else "-"
        print(f"| {label} | {v:.0f} | {ke:.3f} | {ka:.3f} | {kg:.3f} | {first:.3f} | {mean_early:.3f} | {mean_all:.3f} | {fmt(sp_run)} | {fmt(sp_arr)} |")
    if png:
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt

        fig, ax = plt.subplots(figsize=(7, 4.5))
        ax.plot(ts, hs["K_factor_mean"], "k-", label="stationary (same nodes)")
        for label, h, s in runs:
            v = s["growth_speed"]
            ka = k_approx(v, cd, cR)
            ke = k_exact(v, cd, cs, cR)
            line = ax.plot(h["t_us"], h["K_factor_mean"], "o-", ms=3, label=f"running, {label}")[0]
            t0 = s["growth_start_us"]
            tt = [t for t in ts if t >= t0 and t <= t0 + (s["final_crack_length"] - 0.0024) / v * 1e6 + 1e-6]
            ax.plot(tt, [ke * hs["K_factor_mean"][ts.index(t)] for t in tt], "-", lw=2, alpha=0.5, color=line.get_color(),
                    label=f"exact k(v) K_stat = {ke:.3f} K_stat, v = {v:.0f} m/s")
            ax.plot(tt, [ka * hs["K_factor_mean"][ts.index(t)] for t in tt], ":", color=line.get_color(),
                    label=f"k_a(v) K_stat = {ka:.3f} K_stat (approximation)")
        ax.set(xlabel="t [us]", ylabel="K / (sigma sqrt(pi a0))", xlim=(6, max(ts)), title="Chen's plate: onset of growth vs Freund's k(v)")
        ax.grid(alpha=0.3)
        ax.legend(fontsize=7)
        fig.tight_layout()
        fig.savefig(png, dpi=110)
        print(png)


if __name__ == "__main__":
    guarded(main)
