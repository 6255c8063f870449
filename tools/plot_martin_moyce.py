#!/usr/bin/python3
"""Surge front of the plain dam break against Martin & Moyce (1952): Z = front / a against
T = t sqrt(2 g / a), our runs as lines, the experiment as points.

Usage (Debian's python3 has matplotlib):
  /usr/bin/python3 tools/plot_martin_moyce.py \
      --data ../shared/data/dambreak_front_martin_moyce_1952.csv \
      --run "a/dx = 25:/tmp/mm25.csv" --run "a/dx = 50:/tmp/mm50.csv" \
      -o cases/dambreak/martin_moyce.png [--table]

Each --run is LABEL:CSV with CSV written by
  sphjet analyse RUN_DIR --front --column-width A --csv CSV
(columns T and Z). --table prints, for every experimental point with T <= --tmax, Z of each run
(interpolated linearly in T) and its deviation from the experiment, as a Markdown table.
--shift DT compares Z(T + DT) of the runs instead (a time shift, stated in the output).
"""
import argparse
import csv
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from sphjet_runs import RunError, label_and_file  # noqa: E402


def read_csv_rows(path):
    with open(path) as f:
        return [r for r in csv.reader(l for l in f if not l.startswith("#"))]


def read_data(path):
    rows = read_csv_rows(path)
    head = rows[0]
    i_s, i_t, i_z = head.index("series"), head.index("T"), head.index("Z")
    out = {}
    for r in rows[1:]:
        out.setdefault(r[i_s], []).append((float(r[i_t]), float(r[i_z])))
    return out


def read_run(path):
    rows = read_csv_rows(path)
    head = rows[0]
    if "T" not in head or "Z" not in head:
        sys.exit(f"plot_martin_moyce: {path}: no T,Z columns (write it with sphjet analyse --front --column-width A)")
    i_t, i_z = head.index("T"), head.index("Z")
    pts = sorted((float(r[i_t]), float(r[i_z])) for r in rows[1:] if r[i_t] and r[i_z])
    return pts


def interp(pts, t):
    for (t0, z0), (t1, z1) in zip(pts, pts[1:]):
        if t0 <= t <= t1:
            return z0 + (z1 - z0) * (t - t0) / (t1 - t0) if t1 > t0 else z0
    return None


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--data", required=True, help="Martin & Moyce CSV (series,T,Z)")
    ap.add_argument("--run", action="append", required=True, help="LABEL:CSV from sphjet analyse --column-width")
    ap.add_argument("-o", "--output", help="PNG to write")
    ap.add_argument("--table", action="store_true", help="print the agreement table (Markdown)")
    ap.add_argument("--tmax", type=float, default=3.0, help="table: experimental points with T <= TMAX")
    ap.add_argument("--shift", type=float, default=0.0, help="compare the runs at T + SHIFT")
    ap.add_argument("--series", help="table: only this series of the data (e.g. mm_a2.25in)")
    ap.add_argument("--fit-shift", action="store_true",
                    help="table: also print, per run, the shift in [-0.6, 0] (step 0.01) that minimises "
                         "the largest |deviation|")
    args = ap.parse_args()

    if not os.path.isfile(args.data):
        sys.exit(f"plot_martin_moyce: --data {args.data}: no such file")
    data = read_data(args.data)
    runs = []
    for spec in args.run:
        try:
            label, path = label_and_file(spec)
        except RunError as e:
            sys.exit(f"plot_martin_moyce: --run {e}")
        runs.append((label, read_run(path)))

    if args.series:
        if args.series not in data:
            sys.exit(f"plot_martin_moyce: --series {args.series}: not in {args.data} ({', '.join(data)})")
        table_data = {args.series: data[args.series]}
    else:
        table_data = data

    def worst_dev(rp, shift):
        w = 0.0
        for s_, pts in table_data.items():
            for t, z in pts:
                if t > args.tmax:
                    continue
                zr = interp(rp, t + shift)
                if zr is None:
                    return None
                w = max(w, abs(zr - z) / z)
        return w

    if args.table and args.fit_shift:
        for l, rp in runs:
            cands = [(worst_dev(rp, -k / 100), -k / 100) for k in range(0, 61)]
            cands = [c for c in cands if c[0] is not None]
            w, sh = min(cands)
            print(f"best shift for {l}: runs read at T {sh:+.2f}: largest |deviation| {100 * w:.1f}%")

    if args.table:
        print("| series | T | Z exp. | " + " | ".join(f"Z {l} | dev." for l, _ in runs) + " |")
        print("|---|---|---|" + "---|---|" * len(runs))
        worst = {l: 0.0 for l, _ in runs}
        for s, pts in table_data.items():
            for t, z in pts:
                if t > args.tmax:
                    continue
                cells = []
                for l, rp in runs:
                    zr = interp(rp, t + args.shift)
                    if zr is None:
                        cells += ["-", "-"]
                        continue
                    dev = (zr - z) / z
                    worst[l] = max(worst[l], abs(dev))
                    cells += [f"{zr:.3f}", f"{100 * dev:+.1f}%"]
                print(f"| {s} | {t:.3f} | {z:.3f} | " + " | ".join(cells) + " |")
        shift = f" (runs read at T + {args.shift:g})" if args.shift else ""
        for l, w in worst.items():
            print(f"largest |deviation| for T <= {args.tmax:g}{shift}, {l}: {100 * w:.1f}%")

    if args.output:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, ax = plt.subplots(figsize=(5.5, 4.0))
        marks = ["o", "s", "^", "v"]
        for k, (s, pts) in enumerate(data.items()):
            ax.plot([p[0] for p in pts], [p[1] for p in pts], marks[k % 4], mfc="none", color="k",
                    label=f"Martin & Moyce 1952, {s.replace('mm_a', 'a = ').replace('in', ' in')}")
        for k, (label, rp) in enumerate(runs):
            col = f"C{k}"
            ax.plot([p[0] for p in rp], [p[1] for p in rp], "-", color=col, label=f"sphjet, {label}")
            if args.shift:
                ax.plot([p[0] - args.shift for p in rp], [p[1] for p in rp], "--", color=col, lw=1,
                        label=f"sphjet, {label}, T + {-args.shift:g}")
        ax.set_xlabel(r"$T = t\,\sqrt{2g/a}$")
        ax.set_ylabel(r"$Z$ = front / $a$")
        tend = max(max(p[0] for p in rp) for _, rp in runs) + 0.2
        ax.set_xlim(0, tend)
        zend = max([p[1] for _, rp in runs for p in rp] +
                   [z for pts in data.values() for t, z in pts if t <= tend])
        ax.set_ylim(0.9, zend + 0.3)
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8)
        fig.tight_layout()
        fig.savefig(args.output, dpi=100)
        print(f"wrote {args.output} ({os.path.getsize(args.output) / 1024:.0f} KB)")


if __name__ == "__main__":
    main()
