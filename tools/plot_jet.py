#!/usr/bin/env python3
"""Draw a jet run's particles at a few times side by side, as a small PNG.

Usage (Debian's python3 has numpy, matplotlib and h5py):
    /usr/bin/python3 tools/plot_jet.py RUN [-o RUN/jet.png] [--times T1 T2 ...] [--panels N]
                                           [--window X0 X1 Z0 Z1]

RUN is a run directory with HDF5 snapshots (snap_*.h5, `[output] format = "hdf5"` or
"both"). Each panel is the snapshot nearest a time: fluid coloured by speed |u|, boundary
particles grey, each particle a dot one spacing across. Without --times the panels are N
snapshots spread evenly from the first output to the last; without --window each panel shows
the box the particles of all panels span. An axisymmetric run is drawn mirrored about its
axis (x = r and -r), so a round jet looks like one. The figure of README.md is
    build/cpp_driver/sphjet run cases/jet/jet.toml --out runs/jet
    /usr/bin/python3 tools/plot_jet.py runs/jet --times 0.06 0.09 0.11 0.14 \\
        --window 0.02 0.06 0.28 0.43 --dpi 100 -o docs/images/jet_breakup.png
"""
import argparse
import os
import sys


def h5py_file(path):
    import h5py
    return h5py.File(path, "r")


def snapshots(run):
    """[(time, path)] of the run's snapshots, in time order (the jet study's reader)."""
    sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
    from jet_study import snapshot_frames
    return snapshot_frames(run)


def read(path):
    """x, z, speed, fluid mask, axisymmetric flag of one snapshot (active particles only)."""
    import h5py
    import numpy as np
    with h5py.File(path, "r") as f:
        p = f["particles"]
        active = p["active"][()] == 1
        x, z = p["x"][()][active], p["z"][()][active]
        speed = np.hypot(p["u"][()], p["w"][()])[active]
        fluid = np.arange(len(active))[active] >= int(f.attrs["nb"])
        # Geometry in params.hpp: 0 planar, 1 axisymmetric
        axisymmetric = int(f["parameters"].attrs.get("geometry", 0)) == 1
    return x, z, speed, fluid, axisymmetric


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("run", help="run directory with snap_*.h5")
    ap.add_argument("-o", "--out", default=None, help="PNG to write (default RUN/jet.png)")
    ap.add_argument("--times", type=float, nargs="+", default=None, help="times of the panels [s]")
    ap.add_argument("--panels", type=int, default=4, help="panels without --times (default 4)")
    ap.add_argument("--window", type=float, nargs=4, metavar=("X0", "X1", "Z0", "Z1"),
                    default=None, help="the region drawn [m] (default: all particles)")
    ap.add_argument("--height", type=float, default=4.5, help="figure height [in] (default 4.5)")
    ap.add_argument("--dpi", type=int, default=80)
    a = ap.parse_args(argv)

    snaps = snapshots(a.run)
    if not snaps:
        sys.exit(f"plot_jet.py: {a.run}: no snap_*.h5 (run with [output] format = \"hdf5\" or \"both\")")
    if a.times:
        chosen = [min(snaps, key=lambda s: abs(s[0] - t)) for t in a.times]
    else:
        n = max(1, min(a.panels, len(snaps)))
        chosen = [snaps[round(i * (len(snaps) - 1) / max(1, n - 1))] for i in range(n)]

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np

    frames = [(t,) + read(path) for t, path in chosen]
    if a.window:
        x0, x1, z0, z1 = a.window
    else:
        xs = np.concatenate([np.concatenate([f[1], -f[1]]) if f[5] else f[1] for f in frames])
        zs = np.concatenate([f[2] for f in frames])
        x0, x1, z0, z1 = xs.min(), xs.max(), zs.min(), zs.max()
        pad = 0.02 * max(x1 - x0, z1 - z0)
        x0, x1, z0, z1 = x0 - pad, x1 + pad, z0 - pad, z1 + pad
    # Spacing: the median distance between neighbours along x of the first frame's fluid.
    with h5py_file(chosen[0][1]) as f:
        dx = float(f["parameters"].attrs.get("dx", 0.0)) or 0.01 * (x1 - x0)
    in_window = lambda f: (f[1] >= x0) & (f[1] <= x1) & (f[2] >= z0) & (f[2] <= z1)
    vmax = max([float(np.max(f[3][f[4] & in_window(f)])) for f in frames
                if np.any(f[4] & in_window(f))] or [1.0])
    panel_w = a.height * 0.8 * (x1 - x0) / (z1 - z0)
    fig, axes = plt.subplots(1, len(frames), figsize=(len(frames) * (panel_w + 0.25) + 1.0, a.height),
                             sharey=True, squeeze=False)
    # a dot one spacing across: points per metre from the panel's height
    dot = (0.8 * a.height * 72.0 / (z1 - z0) * dx) ** 2
    for ax, (t, x, z, speed, fluid, axi) in zip(axes[0], frames):
        if axi:  # the meridian plane mirrored: both sides of the axis
            x, z, speed, fluid = (np.concatenate([x, -x]), np.concatenate([z, z]),
                                  np.concatenate([speed, speed]), np.concatenate([fluid, fluid]))
        ax.scatter(x[~fluid], z[~fluid], s=dot, c="0.6", linewidths=0)
        sc = ax.scatter(x[fluid], z[fluid], s=dot, c=speed[fluid], cmap="viridis",
                        vmin=0.0, vmax=vmax, linewidths=0)
        ax.set_xlim(x0, x1)
        ax.set_ylim(z0, z1)
        ax.set_aspect("equal")
        ax.set_title(f"t = {t:.2f} s", fontsize=9)
        ax.tick_params(labelsize=7)
        ax.set_xticks([])
    axes[0][0].set_ylabel("z [m]", fontsize=8)
    cb = fig.colorbar(sc, ax=axes[0].tolist(), shrink=0.7, pad=0.02)
    cb.set_label("|u| [m/s]", fontsize=8)
    cb.ax.tick_params(labelsize=7)
    out = a.out or os.path.join(a.run, "jet.png")
    fig.savefig(out, dpi=a.dpi, bbox_inches="tight")
    print(f"wrote {out} ({len(frames)} panels: t = " +
          ", ".join(f"{f[0]:.3f}" for f in frames) + " s)")


if __name__ == "__main__":
    main()
