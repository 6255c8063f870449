#!/usr/bin/python3
"""Figure 3 of the paper (section 3-1): the dam break with an obstacle, particle snapshots at
t = 0.1 ... 0.6 s (rows), one column per run (sphjet Wendland, sphjet cubic spline, legacy
SPHysics), fluid coloured by pressure, boundary particles grey.

Usage (Debian's python3 has matplotlib):
  /usr/bin/python3 tools/plot_obstacle_figure.py --wendland RUN --cubic RUN \
      --legacy ../shared/legacy/obstacle_wendland -o cases/dambreak_obstacle/figure3.png

Each RUN is a run directory (legacy PART files, or sphjet PART or HDF5 output; see
tools/sphjet_runs.py). The output nearest each time is used (within --tol); its time is printed
in the panel. Exits with status 1 and a message naming the directory when an input is missing.
"""
import argparse
import io
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from sphjet_runs import Run, RunError  # noqa: E402


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--wendland", required=True, help="sphjet run directory, Wendland kernel")
    ap.add_argument("--cubic", required=True, help="sphjet run directory, cubic spline kernel")
    ap.add_argument("--legacy", required=True, help="legacy SPHysics run (shared/legacy/obstacle_wendland)")
    ap.add_argument("-o", "--output", required=True, help="PNG to write")
    ap.add_argument("--times", default="0.1,0.2,0.3,0.4,0.5,0.6", help="times [s], comma separated")
    ap.add_argument("--tol", type=float, default=0.01, help="largest |t_output - t| accepted [s]")
    ap.add_argument("--pmax", type=float, default=3000.0, help="top of the pressure colour scale [Pa]")
    ap.add_argument("--dpi", type=int, default=80)
    ap.add_argument("--obstacle", default="0.292,0.316,0.048", help="x0,x1,height of the obstacle [m] (outline)")
    args = ap.parse_args()

    for opt in ("wendland", "cubic", "legacy"):
        d = getattr(args, opt)
        if not os.path.isdir(d):
            sys.exit(f"plot_obstacle_figure: --{opt} {d}: no such run directory")
    try:
        runs = [Run(args.wendland, "sphjet, Wendland"), Run(args.cubic, "sphjet, cubic spline"),
                Run(args.legacy, "legacy SPHysics (Wendland)")]
    except RunError as e:
        sys.exit(f"plot_obstacle_figure: {e}")
    times = [float(t) for t in args.times.split(",")]

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.patches import Rectangle
    import numpy as np

    ncol, nrow = len(runs), len(times)
    fig, axes = plt.subplots(nrow, ncol, figsize=(2.3 * ncol + 0.7, 2.2 * nrow), squeeze=False,
                             gridspec_kw=dict(wspace=0.04, hspace=0.06))
    sc = None
    missing = []
    ox0, ox1, oh = (float(v) for v in args.obstacle.split(","))
    for j, run in enumerate(runs):
        for i, t in enumerate(times):
            ax = axes[i][j]
            ax.set_xlim(0, 0.584)
            ax.set_ylim(0, 0.584)
            ax.set_aspect("equal")
            ax.set_xticks([])
            ax.set_yticks([])
            if i == 0:
                ax.set_title(run.label, fontsize=9)
            if j == 0:
                ax.set_ylabel(f"t = {t:.1f} s", fontsize=9)
            fr = run.nearest(t, args.tol)
            if fr is None:
                missing.append(f"{run.dir} has no output within {args.tol} s of t = {t}")
                ax.text(0.5, 0.5, "no output", transform=ax.transAxes, ha="center", va="center")
                continue
            try:
                d = run.load(fr)
            except RunError as e:
                sys.exit(f"plot_obstacle_figure: {e}")
            b = d["boundary"]
            f = (~b) & d["active"]
            ax.scatter(d["x"][b], d["z"][b], s=0.5, c="0.45", marker=".", linewidths=0, rasterized=True)
            sc = ax.scatter(d["x"][f], d["z"][f], s=0.6, c=np.clip(d["p"][f], 0, args.pmax), cmap="jet",
                            vmin=0, vmax=args.pmax, marker=".", linewidths=0, rasterized=True)
            ax.add_patch(Rectangle((ox0, 0), ox1 - ox0, oh, fill=False, lw=0.4, ec="k"))
            nout = int(((~b) & ~d["active"]).sum())
            ax.text(0.98, 0.97, f"{fr[1]:.3f} s" + (f", {nout} out" if nout else ""), transform=ax.transAxes,
                    ha="right", va="top", fontsize=6)
    if sc is not None:
        cax = fig.add_axes([0.92, 0.3, 0.015, 0.4])
        cb = fig.colorbar(sc, cax=cax)
        cb.set_label("pressure [Pa]", fontsize=8)
        cb.ax.tick_params(labelsize=7)
    fig.subplots_adjust(left=0.06, right=0.9, top=0.96, bottom=0.01)

    # A palette PNG keeps the file small (commit-sized); plain PNG when Pillow is missing.
    buf = io.BytesIO()
    fig.savefig(buf, format="png", dpi=args.dpi)
    try:
        from PIL import Image
        buf.seek(0)
        Image.open(buf).convert("RGB").quantize(colors=256).save(args.output, optimize=True)
    except ImportError:
        with open(args.output, "wb") as fo:
            fo.write(buf.getvalue())
    print(f"wrote {args.output} ({os.path.getsize(args.output) / 1024:.0f} KB)")
    for m in missing:
        print("warning:", m, file=sys.stderr)
    return 1 if missing else 0


if __name__ == "__main__":
    sys.exit(main())
