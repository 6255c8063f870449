#!/usr/bin/python3
"""Square drop relaxing to a circle (cases/square_drop): particle snapshots of one run and the
outline ratio r_max / r_min against time for any number of runs.

Usage (Debian's python3 has matplotlib and h5py):
  sphjet drop RUN --csv RUN.csv            # per-snapshot table, column r_ratio
  /usr/bin/python3 tools/plot_square_drop.py --snapshots RUN --times 0,0.02,0.05,0.39 \
      --ratio "L/dx = 60, Wendland:RUN.csv" [--ratio LABEL:CSV ...] --target 1.05 \
      -o cases/square_drop/square_drop.png

Top row: the fluid of RUN (HDF5 snapshots) at the output nearest each time, coloured by
pressure, with the circle of the same area as the first snapshot (dashed); a run to 0.4 s
writes its last output at 0.39 s (outputs are written on the legacy schedule). Bottom: r_ratio of
each CSV against time and the target. Exits with status 1 and a message naming the input when
one is missing or has no r_ratio column.
"""
import argparse
import csv
import io
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from sphjet_runs import Run, RunError, label_and_file  # noqa: E402


def die(msg):
    sys.exit(f"plot_square_drop: {msg}")


def read_ratio(path):
    """`sphjet drop --csv` table -> (times, r_ratio) lists."""
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    if not rows or "r_ratio" not in rows[0] or "time" not in rows[0]:
        die(f"--ratio {path}: expected a `sphjet drop --csv` table with "
            f"columns time and r_ratio, found {list(rows[0]) if rows else 'no rows'}")
    return [float(r["time"]) for r in rows], [float(r["r_ratio"]) for r in rows]


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--snapshots", required=True, help="sphjet run directory (HDF5 output)")
    ap.add_argument("--times", default="0,0.02,0.05,0.39", help="snapshot times [s], comma separated")
    ap.add_argument("--tol", type=float, default=0.006, help="largest |t_output - t| accepted [s]")
    ap.add_argument("--ratio", action="append", default=[], metavar="LABEL:CSV",
                    help="outline ratio of a run: label and `sphjet drop --csv` table")
    ap.add_argument("--target", type=float, default=1.05, help="target r_max / r_min (drawn)")
    ap.add_argument("--pmax", type=float, default=120.0, help="top of the pressure colour scale [Pa]")
    ap.add_argument("-o", "--output", required=True, help="PNG to write")
    ap.add_argument("--dpi", type=int, default=100)
    args = ap.parse_args()

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np

    try:
        run = Run(args.snapshots)
        frames = []
        for t in [float(v) for v in args.times.split(",")]:
            fr = run.nearest(t, args.tol)
            if fr is None:
                die(f"--snapshots {args.snapshots}: no output within "
                         f"{args.tol} s of t = {t} s")
            frames.append(run.load(fr))
    except RunError as e:
        die(f"{e}")
    series = []
    for spec in args.ratio:
        try:
            label, path = label_and_file(spec)
        except RunError as e:
            die(f"--ratio {e}")
        series.append((label, *read_ratio(path)))

    first = frames[0]
    fluid0 = first["active"] & ~first["boundary"]
    r_circle = np.sqrt(np.sum(first["m"][fluid0] / first["rho"][fluid0]) / np.pi)
    lim = 1.35 * r_circle * 1e3

    n = len(frames)
    fig = plt.figure(figsize=(3.6 * n, 7.0))
    gs = fig.add_gridspec(2, n, height_ratios=[1.0, 0.9])
    sc = None
    for j, d in enumerate(frames):
        ax = fig.add_subplot(gs[0, j])
        f = d["active"] & ~d["boundary"]
        xc, zc = d["x"][f].mean(), d["z"][f].mean()
        sc = ax.scatter((d["x"][f] - xc) * 1e3, (d["z"][f] - zc) * 1e3, c=d["p"][f], s=1.0,
                        cmap="viridis", vmin=0.0, vmax=args.pmax, linewidths=0)
        th = np.linspace(0.0, 2.0 * np.pi, 256)
        ax.plot(r_circle * 1e3 * np.cos(th), r_circle * 1e3 * np.sin(th), "k--", lw=0.6)
        ax.set_xlim(-lim, lim)
        ax.set_ylim(-lim, lim)
        ax.set_aspect("equal")
        ax.set_title(f"t = {d['time']:.3f} s", fontsize=9)
        ax.tick_params(labelsize=7)
        if j == 0:
            ax.set_ylabel("z - z_c [mm]", fontsize=8)
        ax.set_xlabel("x - x_c [mm]", fontsize=8)
    cb = fig.colorbar(sc, ax=fig.axes[:n], fraction=0.02, pad=0.01)
    cb.set_label("p [Pa]", fontsize=8)
    cb.ax.tick_params(labelsize=7)

    ax = fig.add_subplot(gs[1, :])
    for label, t, r in series:
        ax.plot(t, r, lw=1.2, label=label)
    ax.axhline(args.target, color="k", ls=":", lw=1.0, label=f"target {args.target}")
    ax.set_xlabel("t [s]")
    ax.set_ylabel("outline r_max / r_min")
    ax.set_ylim(1.0, 1.2)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8, loc="upper right")
    fig.suptitle(f"Square drop to circle ({os.path.basename(os.path.normpath(args.snapshots))}, "
                 f"circle of the same area dashed)", fontsize=10)
    # A palette of 128 colours keeps the committed PNG small (the particle scatter is noisy);
    # Pillow comes with Debian's python3-matplotlib.
    buf = io.BytesIO()
    fig.savefig(buf, format="png", dpi=args.dpi)
    from PIL import Image
    Image.open(buf).convert("RGB").quantize(colors=128).save(args.output, optimize=True)
    print(f"plot_square_drop: wrote {args.output}")


if __name__ == "__main__":
    main()
