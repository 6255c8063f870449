#!/usr/bin/env python3
"""A run whose disk fills up stops cleanly, and resumes to the same result once there is room.

The Laplace drop (cases/laplace_disc, 1321 particles) runs with both output formats, an
output every 1 ms and a checkpoint every 20 steps, to t = 0.01 s, with its run directory on a
tmpfs of SIZE bytes (a real file system that really fills: ENOSPC from the kernel, no fault
injection). Each SIZE makes a different write the one that does not fit (checked). For each:

  1. the run exits with status 1 (an error, not a crash), and stderr says
     "No space left on device", names a file of the run directory, and gives the resume
     command `sphjet run --resume DIR` (or, when the disk filled before the first
     checkpoint, says so and that the case must be run again);
  2. no temporary file (*.tmp, *.tmp-sphjet) is left in the run directory;
  3. everything written is whole: every snapshot the XDMF index lists and the checkpoint read
     back in full with h5dump (checksums included), every PART file steps.txt lists has one
     line of 7 numbers per particle, DT and steps.txt hold the same number of whole rows;
  4. (when a checkpoint was written) after the file system is grown (the user frees space),
     `sphjet run --resume DIR`
     finishes, and its final checkpoint, last snapshot (/particles, h5diff with no tolerance),
     EPART, DT and steps.txt (byte for byte) equal those of an uninterrupted run on the
     ordinary disk. Bitwise, because the pair traversal gives results independent of
     scheduling and a checkpoint holds all the state a step reads (as in
     regression.kill9_resume_bitwise); both runs use one thread.

Making the tmpfs needs root (mount) or an unprivileged user namespace (unshare -rm, which
this script tries next); where neither works the test exits with status 77, which CTest
reports as skipped, and says why.

usage: check_disk_full.py SPHJET SOURCE_DIR WORK_DIR
"""
import os
import re
import shutil
import subprocess
import sys

SKIP = 77
# tmpfs sizes: with the outputs below (HDF5 1.10.8, Debian 12), the first write that does not
# fit is the start's snapshot (300k: up to 340k), the first checkpoint (430k: 355k-500k), a
# later snapshot (750k: 680k-824k), the XDMF index after a checkpoint (828k: 825k-832k) and a
# later checkpoint (900k: 834k-966k); measured at 8716f3a by stepping the size from 300k to
# 1000k (at 345k-350k the start's XDMF index, between 560k and 650k the second checkpoint). No
# size of that scan stopped at a PART file, so the PART writer's disk-full path is checked by
# the unit tests DiskFull.* only. The test checks that the sizes stop the run at as many
# different writes (which file each is, and whether a checkpoint was written before it, is
# printed: another HDF5, or a new attribute in the files, may shift them, and then SIZES must
# be chosen again, or the test would cover fewer ways to fail), and that at least one stopped
# before and one after the first checkpoint (so that both the "run the case again" and the
# resume paths are checked).
SIZES = ["300k", "430k", "750k", "828k", "900k"]
TMAX = "0.01"
SETS = ["--format", "both", "-j", "1", "-q",
        "--set", "time.out=0.001", "--set", "output.checkpoint_every_steps=20",
        "--set", "output.checkpoint_every_minutes=0"]
NS_ENV = "SPHJET_DISK_FULL_IN_NAMESPACE"


def run(cmd, **kw):
    return subprocess.run(cmd, capture_output=True, text=True, **kw)


def mount_tmpfs(mnt, size):
    os.makedirs(mnt, exist_ok=True)
    if os.path.ismount(mnt):
        run(["umount", "-l", mnt])
    r = run(["mount", "-t", "tmpfs", "-o", f"size={size}", "tmpfs", mnt])
    return r.returncode == 0, (r.stderr or r.stdout).strip()


def umount(mnt):
    if os.path.ismount(mnt):
        run(["umount", "-l", mnt])


def ensure_mountable(work):
    """Returns None when a tmpfs can be mounted here; else re-runs this script in a user and
    mount namespace (returning its exit status), or SKIP."""
    probe = os.path.join(work, "probe")
    ok, why = mount_tmpfs(probe, "64k")
    umount(probe)
    if ok:
        return None
    if os.environ.get(NS_ENV) or shutil.which("unshare") is None:
        print(f"SKIP: cannot mount a tmpfs ({why}) and no user namespace to do it in; "
              "the unit tests DiskFull.* cover the writers without one")
        return SKIP
    print(f"mount failed ({why}); trying again in a user namespace (unshare -rm)")
    env = dict(os.environ, **{NS_ENV: "1"})
    r = subprocess.run(["unshare", "--user", "--map-root-user", "--mount", sys.executable]
                       + sys.argv, env=env)
    if r.returncode not in (0, 1, SKIP):
        print(f"SKIP: unshare -rm failed (status {r.returncode}): no user namespaces here")
        return SKIP
    return r.returncode


def readable_h5(path):
    r = subprocess.run(["h5dump", path], stdout=subprocess.DEVNULL, stderr=subprocess.PIPE,
                       text=True)
    return r.returncode == 0, r.stderr.strip()[-300:]


def data_rows(path, header):
    """Rows of DT or steps.txt after the header; each must parse fully."""
    rows = []
    with open(path) as f:
        text = f.read()
    if text and not text.endswith("\n"):
        raise ValueError(f"{path}: the last row has no newline (half-written)")
    for line in text.splitlines():
        if not line.strip() or line.lstrip().startswith(header):
            continue
        fields = line.split()
        [float(x) for x in fields]  # raises on a partial number
        rows.append(fields)
    return rows


def check_whole(run_dir, n_particles, want_checkpoint, fails):
    """Check 3: everything on disk is whole. Returns the number of snapshots indexed."""
    xmf = os.path.join(run_dir, "sphjet.xmf")
    snaps = []
    if os.path.exists(xmf):
        snaps = sorted(set(re.findall(r"(snap_\d+\.h5):", open(xmf).read())))
    for s in snaps:
        ok, err = readable_h5(os.path.join(run_dir, s))
        if not ok:
            fails.append(f"{s} (listed in sphjet.xmf) does not read: {err}")
    cp = os.path.join(run_dir, "checkpoint.h5")
    if os.path.exists(cp):
        ok, err = readable_h5(cp)
        if not ok:
            fails.append(f"checkpoint.h5 does not read: {err}")
    elif want_checkpoint:
        fails.append("no checkpoint.h5")
    try:
        steps = data_rows(os.path.join(run_dir, "steps.txt"), "#")
        dt = data_rows(os.path.join(run_dir, "DT"), "time")
    except (OSError, ValueError) as e:
        fails.append(f"DT / steps.txt: {e}")
        return len(snaps)
    if len(dt) != len(steps):
        fails.append(f"DT has {len(dt)} rows, steps.txt {len(steps)}")
    for row in steps:
        k = int(row[0])
        part = os.path.join(run_dir, f"PART_{k:04d}")
        if not os.path.exists(part):
            fails.append(f"steps.txt lists output {k} but {os.path.basename(part)} is missing")
            continue
        lines = open(part).read().splitlines()
        if len(lines) != n_particles or any(len(l.split()) != 7 for l in lines):
            fails.append(f"{os.path.basename(part)} is not {n_particles} lines of 7 numbers")
    print(f"  on disk: {len(snaps)} snapshots indexed, {len(steps)} PART files in steps.txt, "
          "all readable" if not fails else "  on disk: see failures")
    return len(snaps)


def same_as_reference(ref, run_dir, fails):
    """Check 4: the resumed run equals the uninterrupted one."""
    for name in ["DT", "steps.txt", "EPART"]:
        a, b = os.path.join(ref, name), os.path.join(run_dir, name)
        if open(a, "rb").read() != open(b, "rb").read():
            fails.append(f"{name} differs from the uninterrupted run")
    snaps_ref = sorted(f for f in os.listdir(ref) if re.fullmatch(r"snap_\d+\.h5", f))
    snaps = sorted(f for f in os.listdir(run_dir) if re.fullmatch(r"snap_\d+\.h5", f))
    if snaps != snaps_ref:
        fails.append(f"snapshots: {len(snaps)} after resume, {len(snaps_ref)} uninterrupted")
    for a, b in [(os.path.join(ref, "checkpoint.h5"), os.path.join(run_dir, "checkpoint.h5")),
                 (os.path.join(ref, snaps_ref[-1]), os.path.join(run_dir, snaps_ref[-1]))]:
        r = run(["h5diff", "-r", a, b, "/particles", "/particles"])
        if r.returncode != 0:
            fails.append(f"h5diff /particles of {os.path.basename(b)}: {r.stdout.strip()[:300]}")


def main():
    sphjet, src, work = sys.argv[1:4]
    sphjet = os.path.abspath(sphjet)
    case = os.path.join(src, "cases", "laplace_disc", "laplace_disc.toml")
    os.makedirs(work, exist_ok=True)
    mnt = os.path.join(work, "fs")
    umount(mnt)
    status = ensure_mountable(work)
    if status is not None:
        return status
    if shutil.which("h5dump") is None or shutil.which("h5diff") is None:
        print("SKIP: h5dump / h5diff not installed (Debian: hdf5-tools)")
        return SKIP

    ref = os.path.join(work, "ref")
    shutil.rmtree(ref, ignore_errors=True)
    r = run([sphjet, "run", case, "--out", ref, "--tmax", TMAX] + SETS)
    if r.returncode != 0:
        print("the uninterrupted run failed:", r.stderr[-2000:])
        return 1
    n_particles = len(open(os.path.join(ref, "IPART")).read().splitlines())

    passed, failed = 0, 0
    failing_files = set()
    stops = {}  # size -> (the file that did not fit, a checkpoint existed before)
    for size in SIZES:
        fails = []
        ok, why = mount_tmpfs(mnt, size)
        if not ok:
            print(f"SKIP: cannot mount a {size} tmpfs: {why}")
            return SKIP
        try:
            run_dir = os.path.join(mnt, "run")
            r = run([sphjet, "run", case, "--out", run_dir, "--tmax", TMAX] + SETS)
            err = r.stderr
            m = re.search(r"sphjet: error: (\S+): cannot write", err)
            print(f"tmpfs {size}: exit {r.returncode}; "
                  f"{m.group(1) if m else 'no file named'} did not fit")
            # 1. an error exit naming the file and the cause, with the resume command
            if r.returncode != 1:
                fails.append(f"exit status {r.returncode}, expected 1 (an error, not a crash)")
            if "No space left on device" not in err:
                fails.append("stderr does not say 'No space left on device'")
            if not m or not m.group(1).startswith(run_dir + os.sep):
                fails.append("stderr names no file of the run directory")
            no_checkpoint = "no checkpoint was written yet" in err
            if m and m.group(1).startswith(run_dir + os.sep):
                name = re.sub(r"\d{4,}", "N", os.path.basename(m.group(1)))
                failing_files.add(name)
                stops[size] = (name, not no_checkpoint)
            if no_checkpoint:
                if os.path.exists(os.path.join(run_dir, "checkpoint.h5")):
                    fails.append("stderr says no checkpoint, but checkpoint.h5 is there")
                if "run the case again" not in err:
                    fails.append("stderr does not say to run the case again")
            elif f"sphjet run --resume {run_dir}" not in err:
                fails.append("stderr gives no resume command")
            # 2. no temporary file left
            tmps = [f for f in os.listdir(run_dir) if ".tmp" in f]
            if tmps:
                fails.append(f"temporary files left: {tmps}")
            # 3. everything written is whole
            check_whole(run_dir, n_particles, not no_checkpoint, fails)
            # 4. room again (the user frees space): resume to the end, same result
            grow = run(["mount", "-o", "remount,size=64m", "tmpfs", mnt])
            if grow.returncode != 0:
                fails.append(f"cannot grow the tmpfs: {grow.stderr.strip()}")
            if no_checkpoint:
                print("  no checkpoint yet: nothing to resume")
                r2 = None
            else:
                r2 = run([sphjet, "run", "--resume", run_dir, "--tmax", TMAX, "-q", "-j", "1"])
            if r2 is None:
                pass
            elif r2.returncode != 0:
                fails.append(f"resume failed (exit {r2.returncode}): {r2.stderr[-1000:]}")
            else:
                same_as_reference(ref, run_dir, fails)
        finally:
            umount(mnt)
        if fails:
            failed += 1
            print("  FAILED:\n    " + "\n    ".join(fails))
            if err:
                print("  stderr:\n    " + "\n    ".join(err.strip().splitlines()[-6:]))
        elif r2 is None:
            passed += 1
        else:
            passed += 1
            print("  resumed after freeing space: final checkpoint, last snapshot, EPART, DT and "
                  "steps.txt equal the uninterrupted run's")
    print(f"files that did not fit: {', '.join(sorted(failing_files))}")
    kinds = set(stops.values())
    if len(kinds) != len(SIZES):
        failed += 1
        print(f"FAILED: the {len(SIZES)} sizes stopped the run at {len(kinds)} different writes "
              f"({stops}); choose SIZES again so that each fails another write")
    elif not any(k[1] for k in kinds) or all(k[1] for k in kinds):
        failed += 1
        print(f"FAILED: no size stopped the run {'after' if not any(k[1] for k in kinds) else 'before'} "
              f"the first checkpoint ({stops})")
    else:
        passed += 1
        print(f"each size stopped another write: {stops}")
    print(f"{passed} passed, {failed} failed")
    return 0 if failed == 0 else 1


if __name__ == "__main__":
    sys.exit(main())
