"""Small helpers shared by the plot scripts in tools/."""
import numpy as np


def load_csv(path):
    """Columns of a CSV written by io::write_csv, by header name (numpy arrays)."""
    with open(path) as f:
        header = f.readline().strip().split(",")
    data = np.loadtxt(path, delimiter=",", skiprows=1, ndmin=2)
    return {name: data[:, k] for k, name in enumerate(header)}
