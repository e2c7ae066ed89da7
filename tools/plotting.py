"""Small helpers shared by the plot scripts in tools/.

Every plot tool takes a result folder (the --out of an app run), writes its PNGs into it, and turns a
missing or wrong input into one line on stderr naming the file, with exit code 2 (never a traceback):

    from plotting import InputError, guarded, load_csv, read_summary, run_folder

    def main():
        args = parser().parse_args()
        run = run_folder(args.run)                       # InputError unless a folder with summary.json
        s = read_summary(run, cases=("pd_tension",))     # InputError for another app's folder
        ...

    if __name__ == "__main__":
        guarded(main)

Set POLYMECH_TRACEBACK=1 to see the Python traceback of an unexpected failure (exit code 1).
"""
import json
import os
import sys

# Which tool plots the results of which app (summary.json "case"; the isph app writes its tank case).
CASE_TOOLS = {
    "mps_point_source": "plot_mps_point_source.py",
    "mps_harmonics": "plot_mps_harmonics.py",
    "pd_penetration": "plot_pd_penetration.py",
    "pd_tension": "plot_pd_tension.py",
    "dem_benchmark": "plot_dem_benchmark.py",
    "dem_pour": "plot_dem_pour.py",
    "efg": "plot_efg.py",
    "helmholtz": "plot_helmholtz_run.py",
    "hydrostatic": "plot_isph.py",
    "dam_break": "plot_isph.py",
    "micro_cantilever": "plot_micro_cantilever_run.py",
    "turek_hron": "plot_turek_hron.py",
}


class InputError(Exception):
    """A missing or wrong input file: reported as one line, exit code 2."""


def tool_name():
    return os.path.basename(sys.argv[0]) or "plot"


def guarded(main):
    """Runs main() and exits: 0 (or main's return value), 2 with one line for an InputError, 1 with one
    line for anything else (POLYMECH_TRACEBACK=1 re-raises it)."""
    try:
        rc = main()
    except InputError as e:
        print(f"{tool_name()}: error: {e}", file=sys.stderr)
        sys.exit(2)
    except KeyboardInterrupt:
        sys.exit(130)
    except Exception as e:  # noqa: BLE001 - one line, not a traceback, for users
        if os.environ.get("POLYMECH_TRACEBACK"):
            raise
        print(f"{tool_name()}: failed: {type(e).__name__}: {e} (POLYMECH_TRACEBACK=1 shows where)", file=sys.stderr)
        sys.exit(1)
    sys.exit(rc or 0)


class Record(dict):
    """A dict read from a file whose missing keys raise an InputError naming the file."""

    def __init__(self, path, data, what="key"):
        super().__init__(data)
        self.path = path
        self.what = what

    def __missing__(self, key):
        raise InputError(f"{self.path}: no {self.what} '{key}' (not the output this tool plots, or an older app)")


def run_folder(path, need=("summary.json",), what="an app's output folder"):
    """Checks that `path` is a folder holding the files in `need`; returns it."""
    if not os.path.exists(path):
        raise InputError(f"{path}: no such folder (give {what}, e.g. the --out of the run)")
    if not os.path.isdir(path):
        raise InputError(f"{path}: not a folder (give {what}, which holds summary.json)")
    for name in need:
        p = os.path.join(path, name)
        if not os.path.isfile(p):
            raise InputError(f"{p}: not found ({path} is not {what}, or the run did not finish)")
    return path


def read_json(path):
    if not os.path.isfile(path):
        raise InputError(f"{path}: not found")
    try:
        with open(path) as f:
            data = json.load(f)
    except (OSError, UnicodeDecodeError, json.JSONDecodeError) as e:
        raise InputError(f"{path}: not a JSON file ({e})") from None
    if not isinstance(data, dict):
        raise InputError(f"{path}: not a summary (a JSON object)")
    return Record(path, data)


def read_summary(run, cases=None):
    """summary.json of a run folder; with `cases`, an InputError unless its "case" is one of them (the
    message names the tool that plots what it is)."""
    path = os.path.join(run, "summary.json")
    s = read_json(path)
    if cases is not None and s.get("case") not in cases:
        case = s.get("case")
        hint = f"; plot it with tools/{CASE_TOOLS[case]}" if case in CASE_TOOLS else ""
        raise InputError(f"{path}: a '{case}' run, not {' or '.join(repr(c) for c in cases)}{hint}")
    return s


def load_csv(path, required=()):
    """Columns of a CSV written by io::write_csv, by header name (numpy arrays; empty when the file has
    no rows). A missing file, a file that is not such a CSV, or a missing column is an InputError."""
    import numpy as np  # here, not at the top: a tool refusing its input answers before numpy loads

    if not os.path.isfile(path):
        raise InputError(f"{path}: not found")
    try:
        with open(path) as f:
            header = f.readline().strip().split(",")
            rows = [line for line in f if line.strip()]
        data = (np.loadtxt(rows, delimiter=",", ndmin=2) if rows else np.zeros((0, len(header))))
    except (OSError, UnicodeDecodeError, ValueError) as e:
        raise InputError(f"{path}: not a CSV of numbers with a header line ({e})") from None
    if data.shape[1] != len(header):
        raise InputError(f"{path}: {data.shape[1]} columns but {len(header)} names in the header")
    cols = Record(path, {name: data[:, k] for k, name in enumerate(header)}, what="column")
    for name in required:
        cols[name]  # noqa: B018 - raises the InputError
    return cols


def snapshot_steps(h5):
    """The snapshot groups (step_NNNNNNNN) of an open SnapshotWriter HDF5 file, in step order."""
    return sorted((k for k in h5.keys() if k.startswith("step_")), key=lambda s: int(s.split("_")[1]))


def open_h5(path):
    """An HDF5 file of the apps (SnapshotWriter), opened read-only; InputError if missing or unreadable."""
    if not os.path.isfile(path):
        raise InputError(f"{path}: not found")
    try:
        import h5py
    except ImportError:
        raise InputError(f"{path}: reading it needs h5py (Debian: apt-get install python3-h5py; "
                         "run the tools with /usr/bin/python3)") from None
    try:
        return h5py.File(path, "r")
    except OSError as e:
        raise InputError(f"{path}: not a readable HDF5 file ({e})") from None


def pyplot():
    """matplotlib.pyplot with the file-only Agg backend."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    return plt


def run_parser(doc, default=None):
    """An argparse parser for a tool that takes one result folder (`run`), with the module docstring as
    its --help."""
    import argparse

    p = argparse.ArgumentParser(description=doc, formatter_class=argparse.RawDescriptionHelpFormatter)
    if default is None:
        p.add_argument("run", help="the run's output folder (the app's --out)")
    else:
        p.add_argument("run", nargs="?", default=default, help=f"the run's output folder (default: {default})")
    return p
