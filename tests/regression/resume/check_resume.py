#!/usr/bin/env python3
"""Kill -9 a run mid-way, resume it, and the final state equals the uninterrupted run.

Both runs write on SPHysics' clock (--legacy-clock), which the resumed run, started without
the flag, must take from its checkpoint: every snapshot's time is compared too. A case, a
--format or a --set of a key that built the particles (fluid.c0) with --resume is refused, naming
it, and leaves the run directory as it was; so is a --legacy-clock where the run writes on the
simulated time (a short run of 40 steps).

A --set of a key a resumed run may change: with the value the run already has (time.out=0.01) the
resumed run is the uninterrupted one bit for bit; with time.out=0.02 and numerics.xsph_eps=0.25 the
snapshots up to the checkpoint stay as they were, the later ones hold the new xsph_eps and follow
the last output at 0.02 s on the run's clock, and the case copy holds the new values with the old
copy kept beside it.

Both runs use the same thread count; the core's pair traversal gives every particle its
contributions in a fixed order (bitwise independent of the thread count), and a checkpoint
holds every array that the next step reads, so the comparison is bitwise: h5diff with no
tolerance on the /particles group of the final checkpoints, and the last HDF5 snapshots.

usage: check_resume.py SPHJET SOURCE_DIR WORK_DIR
"""
import os
import shutil
import signal
import subprocess
import sys
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from summary_checks import with_h5py  # noqa: E402  (tests/regression/)

SETS = ["--set", "resolution.dx=0.025", "--set", "resolution.dz=0.025",
        "--set", "output.checkpoint_every_steps=40", "--set", "output.format=\"hdf5\"",
        "--set", "time.out=0.01"]
TMAX = "0.12"


def refused(sphjet, run, extra, named):
    """Whether `sphjet run --resume RUN EXTRA` is refused, naming `named`, and leaves RUN as it was."""
    def sizes():
        return {f: os.path.getsize(os.path.join(run, f)) for f in os.listdir(run)}
    before = sizes()
    bad = subprocess.run([sphjet, "run", "--resume", run, "-q"] + extra, capture_output=True, text=True)
    print(f"{' '.join(extra)} with --resume: exit {bad.returncode}: {bad.stderr.strip()[:200]}")
    return bad.returncode != 0 and named in bad.stderr and sizes() == before


def main():
    with_h5py()
    import h5py
    sphjet, src, work = sys.argv[1:4]
    dambreak = os.path.join(src, "cases", "quickstart", "dambreak.toml")
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    ref, killed = os.path.join(work, "ref"), os.path.join(work, "killed")
    base = [sphjet, "run", dambreak, "--tmax", TMAX, "-q", "--legacy-clock"] + SETS

    subprocess.run(base + ["--out", ref], check=True)

    proc = subprocess.Popen(base + ["--out", killed], stdout=subprocess.DEVNULL,
                            stderr=subprocess.DEVNULL)
    cp = os.path.join(killed, "checkpoint.h5")
    deadline = time.time() + 300
    # wait for the second checkpoint (40 steps, then 80), then kill without warning
    first = None
    while time.time() < deadline and proc.poll() is None:
        if os.path.exists(cp):
            m = os.path.getmtime(cp)
            if first is None:
                first = m
            elif m != first:
                break
        time.sleep(0.02)
    if proc.poll() is not None:
        print("the run finished before it could be killed; the machine is faster than this "
              "test assumes")
        print("0 passed, 1 failed")
        return 1
    os.kill(proc.pid, signal.SIGKILL)
    proc.wait()
    log = open(os.path.join(killed, "run.log")).read()
    print("killed with SIGKILL; run.log ends:", log.strip().splitlines()[-1][:120])
    same, changed = os.path.join(work, "same"), os.path.join(work, "changed")
    shutil.copytree(killed, same)
    shutil.copytree(killed, changed)

    # a resumed run keeps its checkpoint's case, parameters and format: the options that would
    # change them are refused, naming them, and the run directory left as it was
    case = os.path.join(killed, "case.toml")
    for extra, named in ((["--set", "fluid.c0=20"], "--set fluid.c0=20"), ([case], case),
                         (["--format", "both"], "--format both")):
        if not refused(sphjet, killed, ["--tmax", TMAX] + extra, named):
            print("0 passed, 1 failed")
            return 1

    out = subprocess.run([sphjet, "run", "--resume", killed, "--tmax", TMAX, "-q"],
                         check=True, capture_output=True, text=True)
    print(out.stdout.strip())

    ok = True
    for a, b, what in [(os.path.join(ref, "checkpoint.h5"), cp, "/particles"),
                       ]:
        r = subprocess.run(["h5diff", "-r", a, b, what, what], capture_output=True, text=True)
        print(f"h5diff {what} of final checkpoints: exit {r.returncode}",
              r.stdout.strip()[:400])
        ok = ok and r.returncode == 0
    snaps = sorted(f for f in os.listdir(ref) if f.startswith("snap_"))
    snaps_k = sorted(f for f in os.listdir(killed) if f.startswith("snap_"))
    print(f"snapshots: uninterrupted {len(snaps)}, killed+resumed {len(snaps_k)}")
    ok = ok and snaps == snaps_k
    last = snaps[-1]
    r = subprocess.run(["h5diff", "-r", os.path.join(ref, last), os.path.join(killed, last),
                        "/particles", "/particles"], capture_output=True, text=True)
    print(f"h5diff /particles of {last}: exit {r.returncode}", r.stdout.strip()[:400])
    ok = ok and r.returncode == 0
    times = []
    for d in (ref, killed):
        times.append([])
        for f in snaps:
            with h5py.File(os.path.join(d, f), "r") as h:
                times[-1].append(h.attrs["time"])
    print(f"snapshot times equal: {times[0] == times[1]} (last {times[0][-1]!r} s)")
    ok = ok and times[0] == times[1]

    # --set on resume: the value the run has changes nothing; new values apply from the checkpoint
    subprocess.run([sphjet, "run", "--resume", same, "--tmax", TMAX, "-q", "--set", "time.out=0.01"],
                   check=True, capture_output=True)
    r = subprocess.run(["h5diff", "-r", os.path.join(ref, "checkpoint.h5"), os.path.join(same, "checkpoint.h5"),
                        "/particles", "/particles"], capture_output=True, text=True)
    snaps_s = sorted(f for f in os.listdir(same) if f.startswith("snap_"))
    print(f"resumed with --set time.out=0.01 (its own value): h5diff /particles of final "
          f"checkpoints: exit {r.returncode}; snapshots {len(snaps_s)}")
    ok = ok and r.returncode == 0 and snaps_s == snaps
    with h5py.File(os.path.join(changed, "checkpoint.h5"), "r") as h:
        n_cp = int(h["run_state"].attrs["n_outputs"])
    subprocess.run([sphjet, "run", "--resume", changed, "--tmax", TMAX, "-q", "--set", "time.out=0.02",
                    "--set", "numerics.xsph_eps=0.25"], check=True, capture_output=True)
    rows = []
    for f in sorted(f for f in os.listdir(changed) if f.startswith("snap_")):
        with h5py.File(os.path.join(changed, f), "r") as h:
            rows.append((f, h.attrs["legacy_time"], h["parameters"].attrs["xsph_eps"]))
    kept = [f for f, _t, _x in rows[:n_cp + 1]]
    new = rows[n_cp + 1:]
    gaps = [b[1] - a[1] for a, b in zip(rows[n_cp:], new)]
    print(f"resumed with --set time.out=0.02 numerics.xsph_eps=0.25 after output {n_cp}: "
          f"{len(new)} new snapshots, xsph_eps {sorted(set(x for _f, _t, x in new))}, gaps on the "
          f"run's clock {min(gaps, default=0):.4g}-{max(gaps, default=0):.4g} s")
    ok = ok and kept == snaps[:n_cp + 1] and new and all(x == 0.25 for _f, _t, x in new)
    ok = ok and all(abs(g - 0.02) < 0.002 for g in gaps)   # an output on the first step past it
    for f in kept[1:]:
        r = subprocess.run(["h5diff", os.path.join(ref, f), os.path.join(changed, f), "/particles",
                            "/particles"], capture_output=True)
        ok = ok and r.returncode == 0
    olds = [f for f in os.listdir(changed) if f.startswith("case.to_step")]
    text_new = open(os.path.join(changed, "case.toml")).read()
    text_old = open(os.path.join(changed, olds[0])).read() if olds else ""
    print(f"case copies: {olds} and case.toml")
    ok = ok and len(olds) == 1 and "xsph_eps = 0.25" in text_new and "xsph_eps = 0.25" not in text_old

    # a run on the simulated time (no --legacy-clock) resumed with --legacy-clock
    plain = os.path.join(work, "plain")
    subprocess.run([sphjet, "run", dambreak, "--tmax", TMAX, "-q", "--max-steps", "40", "--out", plain]
                   + SETS, check=True, capture_output=True)
    ok = ok and refused(sphjet, plain, ["--legacy-clock"], "--legacy-clock")
    print("1 passed, 0 failed" if ok else "0 passed, 1 failed")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
