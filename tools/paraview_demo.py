#!/usr/bin/env pvpython
"""The demo's fields in ParaView: |u|/u0 of out/mps_point_source/fields.xdmf on the particles, drawn with
the Point Gaussian representation, at the last snapshot (docs/PARAVIEW.md).

  pvpython tools/paraview_demo.py [out/mps_point_source] [--step last|first|N] [--png FILE] [--field NAME]
  paraview --script=tools/paraview_demo.py        (the same in the ParaView window, on out/mps_point_source)

It saves a screenshot, <run>/paraview_abs_u.png unless --png names another file (in the ParaView window
the view stays open to turn, play the snapshots, or change). Run `bash ci/demo.sh` first (it writes out/mps_point_source/). Written against the
paraview.simple API of ParaView 5.9-5.13 (Xdmf3ReaderS, Point Gaussian, ColorBy, SaveScreenshot); not run
on the project's machines, which have no ParaView.
"""
import argparse
import json
import os
import sys


def parse():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("run", nargs="?", default="out/mps_point_source", help="the run folder (default: out/mps_point_source)")
    ap.add_argument("--step", default="last", help="snapshot to show: last, first or an index 0, 1, ... (default: last)")
    ap.add_argument("--field", default="abs_u_over_u0", help="point field to colour by (default: abs_u_over_u0)")
    ap.add_argument("--png", help="screenshot file (default: <run>/paraview_abs_u.png)")
    ap.add_argument("--size", default="1200x1000", help="screenshot size WxH in pixels (default: 1200x1000)")
    # `paraview --script` passes no arguments; ignore what ParaView's own command line leaves in sys.argv
    args, _ = ap.parse_known_args()
    return args


def fail(message):
    print(f"paraview_demo.py: error: {message}", file=sys.stderr)
    sys.exit(2)


def open_xdmf(path):
    """The XDMF file with the Xdmf3 reader, or the older XDMF reader where that one is missing or reads
    no points."""
    import paraview.simple as pv

    reader = None
    if hasattr(pv, "Xdmf3ReaderS"):
        try:
            reader = pv.Xdmf3ReaderS(FileName=[path])
            reader.UpdatePipeline()
            if reader.GetDataInformation().GetNumberOfPoints() == 0:
                pv.Delete(reader)
                reader = None
        except Exception:  # noqa: BLE001 - fall back to the XDMF 2 reader
            reader = None
    if reader is None:
        reader = pv.XDMFReader(FileNames=[path])
        reader.UpdatePipeline()
    pv.RenameSource(os.path.basename(path), reader)
    return reader


def main():
    args = parse()
    run = os.path.abspath(args.run)
    xdmf = os.path.join(run, "fields.xdmf")
    if not os.path.isdir(run):
        fail(f"{run}: no such folder (run `bash ci/demo.sh` first, or give the run's --out folder)")
    if not os.path.isfile(xdmf):
        fail(f"{xdmf}: not found (a run of mps_point_source writes it; fields.h5 must be next to it)")
    try:
        import paraview.simple as pv
    except ImportError:
        fail("needs ParaView's Python: run it with pvpython (or paraview --script=tools/paraview_demo.py), not python3")

    # spacing of the particles: the disc radius of the Point Gaussian representation
    spacing = None
    try:
        with open(os.path.join(run, "summary.json")) as f:
            spacing = float(json.load(f)["spacing"])
    except (OSError, ValueError, KeyError, TypeError):
        pass

    reader = open_xdmf(xdmf)
    tv = reader.TimestepValues  # one snapshot: some versions give a number, not a list
    times = [float(tv)] if isinstance(tv, (int, float)) else [float(x) for x in (tv or [])]
    scene = pv.GetAnimationScene()
    scene.UpdateAnimationUsingDataTimeSteps()
    if times:
        if args.step == "last":
            t = times[-1]
        elif args.step == "first":
            t = times[0]
        else:
            try:
                t = times[int(args.step)]
            except (ValueError, IndexError):
                fail(f"--step {args.step}: give last, first or 0..{len(times) - 1} ({len(times)} snapshots)")
        scene.AnimationTime = t
    else:
        t = 0.0

    view = pv.GetActiveViewOrCreate("RenderView")
    display = pv.Show(reader, view)
    display.SetRepresentationType("Point Gaussian")
    display.ShaderPreset = "Plain circle"  # flat discs: a 2D lattice of particles
    if spacing is None:  # from the points' extent: about a particle per spacing along x
        b = reader.GetDataInformation().GetBounds()
        spacing = (b[1] - b[0]) / max(1.0, reader.GetDataInformation().GetNumberOfPoints() ** 0.5)
    display.GaussianRadius = 0.5 * spacing

    reader.UpdatePipeline(t)
    arrays = reader.PointData
    if args.field not in arrays.keys():
        fail(f"{xdmf}: no point field '{args.field}' (it has: {', '.join(arrays.keys())})")
    pv.ColorBy(display, ("POINTS", args.field))
    lut = pv.GetColorTransferFunction(args.field)
    try:
        lut.ApplyPreset("Jet", True)  # the paper's Fig. 4 colours (plot_mps_point_source.py uses jet too)
    except Exception:  # noqa: BLE001 - a ParaView without that preset keeps its default map
        pass
    lo, hi = arrays[args.field].GetRange()
    lut.RescaleTransferFunction(0.0 if lo >= 0 else lo, hi if hi > 0 else 1.0)
    display.SetScalarBarVisibility(view, True)
    bar = pv.GetScalarBar(lut, view)
    bar.Title = "|u| / u0" if args.field == "abs_u_over_u0" else args.field
    bar.ComponentTitle = ""

    view.InteractionMode = "2D"  # the plate lies in x-y: look at it from +z
    view.OrientationAxesVisibility = 0
    view.ResetCamera()
    view.ViewTime = t
    pv.Render(view)

    png = args.png or os.path.join(run, "paraview_abs_u.png")
    try:
        w, h = (int(v) for v in args.size.lower().split("x"))
    except ValueError:
        fail(f"--size {args.size}: give WIDTHxHEIGHT in pixels, e.g. 1200x1000")
    pv.SaveScreenshot(png, view, ImageResolution=[w, h])
    print(f"paraview_demo.py: {png} (t = {t * 1e6:.3g} us, snapshot {times.index(t) + 1 if t in times else 0} of {len(times)})")
    return 0


if __name__ == "__main__":
    sys.exit(main())
