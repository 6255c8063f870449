#!/usr/bin/env python3
"""Kill -9 a run mid-way, resume it, and the final state equals the uninterrupted run.

Both runs write on SPHysics' clock (--legacy-clock), which the resumed run, started without
the flag, must take from its checkpoint: every snapshot's time is compared too. A --set, a case
or a --format with --resume is refused, naming it, and leaves the run directory as it was; so is
a --legacy-clock where the run writes on the simulated time (a short run of 40 steps).

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

    # a run on the simulated time (no --legacy-clock) resumed with --legacy-clock
    plain = os.path.join(work, "plain")
    subprocess.run([sphjet, "run", dambreak, "--tmax", TMAX, "-q", "--max-steps", "40", "--out", plain]
                   + SETS, check=True, capture_output=True)
    ok = ok and refused(sphjet, plain, ["--legacy-clock"], "--legacy-clock")
    print("1 passed, 0 failed" if ok else "0 passed, 1 failed")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
