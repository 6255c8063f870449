"""What the regression scripts share: run a case, read the line `SUMMARY key=value ...` that
an analysis prints, and check its numbers against validation targets [LO, HI] and regression references REF +- TOL
(surface_tension/check_drop.py,
axisymmetric/check_axi.py); for the scripts that run sphjet themselves, a run that must
succeed (run_or_exit) and a run of a case with overrides, fresh or resumed (sphjet_run); and,
for the scripts that read HDF5 themselves, getting an interpreter with numpy and h5py
(with_h5py), a file's /particles (h5_particles) and the final ones of a run stopped and
resumed (resumed_particles), compared bitwise (same_particles); for the tests of an analysis
on synthetic data, its numbers against the known answers (known_answers).

Every function prints what it does; a failure prints `0 passed, N failed` and returns None or
exit status 1, so that the caller's last line is always `N passed, M failed`."""
import math
import os
import subprocess
import sys
import time


def run_or_exit(cmd):
    """Runs cmd (output captured); if it fails, exits with FAIL, the command, its exit code
    and the end of its stderr. -> the CompletedProcess."""
    r = subprocess.run([str(c) for c in cmd], capture_output=True, text=True)
    if r.returncode != 0:
        sys.exit(f"FAIL: {' '.join(map(str, cmd))} exited {r.returncode}\n{r.stderr[-3000:]}")
    return r


def with_h5py(required=True):
    """Makes sure numpy and h5py can be imported: they come with Debian's /usr/bin/python3
    (tools/install_deps.sh), while ctest may start another interpreter, so the script is
    started again under /usr/bin/python3 when they are missing. When that interpreter lacks
    them too: exits with a FAIL line if required, else returns False (True when present)."""
    try:
        import h5py  # noqa: F401
        import numpy  # noqa: F401
        return True
    except ImportError:
        if os.path.exists("/usr/bin/python3") and os.path.realpath(sys.executable) != "/usr/bin/python3":
            os.execv("/usr/bin/python3", ["/usr/bin/python3", *sys.argv])
        if required:
            sys.exit("FAIL: numpy and h5py are needed (Debian python3-numpy, python3-h5py)")
        return False


def summary(text):
    """`SUMMARY key=value ...` -> dict, numbers as floats; None when there is no such line."""
    for line in text.splitlines():
        if line.startswith("SUMMARY "):
            out = {}
            for item in line.split()[1:]:
                k, _, v = item.partition("=")
                try:
                    out[k] = float(v)
                except ValueError:
                    out[k] = v
            return out
    return None


def run_case(sphjet, case, out, sets, n_expect):
    """`SPHJET run CASE --out OUT --force -q -j THREADS --set ...` (THREADS from
    SPHJET_TEST_THREADS, default 1) -> True when it exited 0."""
    threads = os.environ.get("SPHJET_TEST_THREADS", "1")
    cmd = [sphjet, "run", case, "--out", out, "--force", "-q", "-j", threads]
    for s in sets:
        cmd += ["--set", s]
    print("$ " + " ".join(cmd), flush=True)
    t0 = time.time()
    r = subprocess.run(cmd, capture_output=True, text=True)
    print(f"run: exit {r.returncode}, {time.time() - t0:.1f} s wall", flush=True)
    if r.returncode != 0:
        print(r.stdout[-3000:])
        print(r.stderr[-3000:])
        print(f"0 passed, {n_expect} failed")
        return False
    return True


def check(s, expect, show, regress=()):
    """Two kinds of check on the SUMMARY numbers, a missing or nan value failing either:
    expect, KEY:LO:HI, the validation target (LO <= s[KEY] <= HI: the physics' or the paper's
    answer with the accuracy the case is meant to reach); regress, KEY:REF:TOL, the regression
    check (|s[KEY] - REF| <= TOL: REF measured by this test, TOL a small multiple of how far a
    rounding-level change moves it, so that a change of the results is seen). The values named
    in show are printed. -> exit status (0 when every check passed)."""
    ok = bad = 0

    def one(key, good, v, what):
        nonlocal ok, bad
        print(f"{'PASS' if good else 'FAIL'} {key} = {v} ({what})")
        ok += good
        bad += not good

    def number(v):
        return isinstance(v, float) and not math.isnan(v)

    for e in expect:
        key, lo, hi = e.rsplit(":", 2)
        v = s.get(key, float("nan"))
        one(key, number(v) and float(lo) <= v <= float(hi), v, f"target [{lo}, {hi}]")
    for e in regress:
        key, ref, tol = e.rsplit(":", 2)
        v = s.get(key, float("nan"))
        one(key, number(v) and abs(v - float(ref)) <= float(tol), v,
            f"regression: measured {ref} +- {tol}")
    for k in show:
        print(f"  {k} = {s.get(k)}")
    print(f"{ok} passed, {bad} failed")
    return 0 if bad == 0 else 1


def summary_of(cmd):
    """Runs cmd (run_or_exit), prints its SUMMARY line -> that line's numbers (summary); exits
    with FAIL when there is none."""
    r = run_or_exit(cmd)
    s = summary(r.stdout)
    if s is None:
        sys.exit(f"FAIL: {' '.join(map(str, cmd))} printed no SUMMARY line:\n{r.stdout[-3000:]}")
    print(next(line for line in r.stdout.splitlines() if line.startswith("SUMMARY ")))
    return s


def known_answers(checks):
    """For the tests of an analysis on synthetic data: checks is a list of (name, measured,
    known, tolerance); prints one line per check and exits with FAIL naming the ones outside
    their tolerance (a nan is outside), else prints PASS."""
    failures = []
    for name, got, want, tol in checks:
        good = abs(got - want) <= tol
        print(f"{'ok  ' if good else 'FAIL'} {name} = {got:.8g} (expected {want:.8g} +- {tol:.3g})")
        if not good:
            failures.append(name)
    if failures:
        sys.exit(f"FAIL: {', '.join(failures)}")
    print("PASS")


def check_output_of(cmd, expect, show, regress=()):
    """Runs cmd, prints the end of its output and checks the numbers of its SUMMARY line
    (check). -> exit status (1 when cmd fails or prints no SUMMARY line)."""
    print("$ " + " ".join(cmd), flush=True)
    r = subprocess.run(cmd, capture_output=True, text=True)
    print(r.stdout[-3000:], r.stderr[-2000:])
    s = summary(r.stdout)
    if r.returncode != 0 or s is None:
        print(f"0 passed, {len(expect) + len(regress)} failed")
        return 1
    return check(s, expect, show, regress)


def sphjet_run(sphjet, case, out, sets=(), resume=False, max_steps=None, check=True):
    """`sphjet run -j 1 -q` of case into out with each of sets as --set (or --resume out),
    stopped after max_steps if given. check: exit with FAIL if it fails (run_or_exit); else
    -> the CompletedProcess, whatever its exit code."""
    cmd = [str(sphjet), "run", "-j", "1", "-q"]
    cmd += ["--resume", str(out)] if resume else [str(case), "--out", str(out)]
    if not resume:
        for s in sets:
            cmd += ["--set", s]
    if max_steps is not None:
        cmd += ["--max-steps", str(max_steps)]
    if check:
        return run_or_exit(cmd)
    return subprocess.run([str(c) for c in cmd], capture_output=True, text=True)


def h5_particles(path):
    """The /particles datasets of an HDF5 snapshot or checkpoint as numpy arrays, by name
    (call with_h5py first)."""
    import h5py
    import numpy as np
    with h5py.File(path, "r") as f:
        return {k: np.asarray(f["particles"][k]) for k in f["particles"]}


def resumed_particles(sphjet, case, out, sets, stop):
    """The final checkpoint's /particles of case run with sets into out, stopped after step
    stop (--max-steps) and resumed to its end."""
    sphjet_run(sphjet, case, out, sets, max_steps=stop)
    sphjet_run(sphjet, case, out, resume=True)
    return h5_particles(os.path.join(str(out), "checkpoint.h5"))


def same_particles(a, b):
    """Whether two h5_particles dicts hold the same datasets, bitwise."""
    return set(a) == set(b) and all(a[k].tobytes() == b[k].tobytes() for k in a)
