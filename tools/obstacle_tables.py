#!/usr/bin/python3
"""Markdown tables comparing `sphjet analyse` CSVs of the dam break with an obstacle, output by
output (matched by time): surge front, highest fluid point over the obstacle, particles out,
and the grid overlap column when the test CSV has one (sphjet analyse --overlap-with REF).

Usage:
  python3 tools/obstacle_tables.py --ref LABEL:REF.csv --test LABEL:TEST.csv [--tmax 0.6]
Deviations are (test - ref) / ref.
"""
import argparse
import csv
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from sphjet_runs import RunError, label_and_file  # noqa: E402


def load(spec):
    try:
        label, path = label_and_file(spec)
    except RunError as e:
        sys.exit(f"obstacle_tables: {e} (write it with sphjet analyse)")
    with open(path) as f:
        return label, [r for r in csv.DictReader(f) if r["time"]]


def num(r, k):
    return float(r[k]) if r and r.get(k) not in (None, "") else None


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--ref", required=True)
    ap.add_argument("--test", required=True)
    ap.add_argument("--tmax", type=float, default=0.61)
    ap.add_argument("--tol", type=float, default=0.01, help="largest time difference of matched outputs [s]")
    args = ap.parse_args()
    lr, ref = load(args.ref)
    lt, test = load(args.test)
    has_ov = "overlap" in test[0]
    head = (f"| t [s] | front {lr} [m] | front {lt} [m] | dev. | top over obstacle {lr} [m] | "
            f"top {lt} [m] | dev. | out {lr} | out {lt} |" + (" overlap |" if has_ov else ""))
    print(head)
    print("|" + "---|" * (head.count("|") - 1))
    seen = set()
    for r in ref:
        t = float(r["time"])
        if t > args.tmax or round(t, 3) in seen:
            continue
        seen.add(round(t, 3))
        cands = [x for x in test if abs(float(x["time"]) - t) <= args.tol]
        if not cands:
            continue
        x = min(cands, key=lambda x: abs(float(x["time"]) - t))
        fr, ft = num(r, "xfront_all"), num(x, "xfront_all")
        zr, zt = num(r, "zmax_obst"), num(x, "zmax_obst")
        dev_f = f"{100 * (ft - fr) / fr:+.2f}%" if fr and ft else ""
        dev_z = f"{100 * (zt - zr) / zr:+.2f}%" if zr and zt else ""
        cell = lambda v: f"{v:.4f}" if v is not None else "-"
        row = (f"| {t:.3f} | {cell(fr)} | {cell(ft)} | {dev_f} | {cell(zr)} | {cell(zt)} | {dev_z} | "
               f"{r['n_out']} | {x['n_out']} |")
        if has_ov:
            row += f" {x['overlap'] or '-'} |"
        print(row)


if __name__ == "__main__":
    main()
