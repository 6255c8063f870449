"""What the studies (tools/jet_study.py, tools/round_jet_study.py) share: running their runs
with sphjet, and reading what a run wrote (run.log, jet.csv, drops.csv) into its summary.

Running: one run at a time (N with --parallel N, each run's output lines then printed after its
name), resumable. A run is finished when the last part of its run.log (the lines from the last
`sphjet ... starting|resuming`) has a `done:` line and no `stopped by signal` line (sphjet
writes `done:` also when interrupted), or when it stopped on a state check (a blow-up is a
result of the study, reported, not retried). An unfinished run resumes from DIR/checkpoint.h5
when there is one, else starts afresh (--force: a directory without a checkpoint holds nothing
to keep). The first failure stops the study with the run's exit code and the end of its log;
runs still going are stopped with a checkpoint. SIGINT/SIGTERM are forwarded to sphjet, which
writes a checkpoint and exits; the study then exits with 128 + signal, and the next `run`
resumes. Several `run`s may work in one study directory (two single runs side by side, say):
each run is made by one of them at a time (a lock file per run, STUDY_DIR/.NAME.lock, held
until that `run` ends), and the others skip it.

Reading: run_summary starts a run's summary from its run.log and hands the rows of its jet.csv
(one row a breakup check: time, step, broken, L_over_d0, ...) to the study's own reduction;
a run without a directory, without jet.csv or with an unreadable one gets a status that says
so. first_breakup, is_broken and drops_at are the row tests both studies use; fmt and md_table
write the report's cells and tables.

tests/unit/python/test_study_runs.py tests this module.
"""
import argparse
import csv
import fcntl
import os
import re
import shlex
import signal
import subprocess
import sys
import threading
import time


class StudyError(Exception):
    pass


# the paper's two kernels (its Table 1), the ones the studies run: jet_study's table1 both,
# round_jet_study's --kernel either
KERNELS = ("wendland", "cubic_spline")


# ---------------------------------------------------------------- run.log
def read_lines(path):
    try:
        with open(path, errors="replace") as f:
            return f.read().splitlines()
    except FileNotFoundError:
        return []


def last_part(lines):
    """The lines from the last `sphjet ... starting|resuming` on (all lines if none)."""
    start = 0
    for i, line in enumerate(lines):
        if line.startswith("sphjet ") and (line.rstrip().endswith("starting") or
                                           line.rstrip().endswith("resuming")):
            start = i
    return lines[start:]


def blew_up(run_dir):
    """The run's last part stopped on a state check (NaN, density band, collapsed step):
    a result of the study, not something a resume would get past. -> the FAILED line or None."""
    part = last_part(read_lines(os.path.join(run_dir, "run.log")))
    return next((l for l in part if l.startswith("FAILED: state check")), None)


def finished(run_dir):
    part = last_part(read_lines(os.path.join(run_dir, "run.log")))
    return ((any(l.startswith("done:") for l in part) and
             not any(l.startswith("stopped by signal") for l in part)) or
            blew_up(run_dir) is not None)


def parse_log(run_dir):
    """run.log -> dict particles, boundary, fluid, wall_s (summed over the parts), steps,
    t_end, particle_steps (summed over the parts), particle_steps_per_s, parts, finished, left_at
    (the time [s] each particle id left the domain at; a resumed part drops the ids logged after
    its checkpoint's time, which it makes again) and left (their number)."""
    lines = read_lines(os.path.join(run_dir, "run.log"))
    out = {"particles": None, "boundary": None, "fluid": None, "wall_s": 0.0, "steps": 0,
           "t_end": None, "particle_steps": 0.0, "particle_steps_per_s": None, "parts": 0,
           "finished": finished(run_dir), "left_at": {}}
    for line in lines:
        m = re.match(r"resuming at step \d+ t = ([-+0-9.eE]+) s", line)
        if m:
            t = float(m.group(1))
            out["left_at"] = {i: ti for i, ti in out["left_at"].items() if ti <= t}
        m = re.match(r"step \d+ t = ([-+0-9.eE]+) s: \d+ particle\(s\) left the domain .*; ids ([0-9 ]+)$", line)
        if m:
            out["left_at"].update((int(i), float(m.group(1))) for i in m.group(2).split())
        m = re.search(r"\| particles (\d+) \(boundary (\d+), fluid (\d+)\)", line)
        if line.startswith("case:") and m and out["particles"] is None:
            out["particles"], out["boundary"], out["fluid"] = map(int, m.groups())
        m = re.match(r"done: (\d+) steps \((\d+) in all\) to t = ([-+0-9.eE]+) s .* in "
                     r"([-+0-9.eE]+) s wall; ([-+0-9.eE]+) particle-steps/s", line)
        if m:
            out["steps"] += int(m.group(1))
            out["t_end"] = float(m.group(3))
            out["wall_s"] += float(m.group(4))
            out["parts"] += 1
            out["particle_steps"] += float(m.group(4)) * float(m.group(5))   # rate x wall time
    if out["wall_s"] > 0:
        out["particle_steps_per_s"] = out["particle_steps"] / out["wall_s"]   # over all parts
    if out["parts"] == 0:
        out["wall_s"] = None
    out["left"] = len(out["left_at"])
    return out


# ---------------------------------------------------------------- the command line
def study_parser(doc):
    """A study's command line: the first paragraph of its docstring `doc` as the description,
    the rest as the epilog. -> (parser, its subparsers, one a command)."""
    ap = argparse.ArgumentParser(description=doc.split("\n\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter,
                                 epilog=doc.split("\n\n", 1)[1])
    return ap, ap.add_subparsers(dest="cmd", required=True)


def at_least_one(text):
    """argparse type: an integer >= 1."""
    try:
        n = int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected an integer >= 1, found {text!r}")
    if n < 1:
        raise argparse.ArgumentTypeError(f"expected an integer >= 1, found {n}")
    return n


def add_set_argument(p, set_names):
    """--set-name (of set_names) on the subparser p: which of the study's sets a command takes
    (default: all)."""
    p.add_argument("--set-name", action="extend", nargs="+", choices=set_names,
                   help="which sets (default: all)")


def add_run_arguments(p, set_names, repo):
    """The options of a study's `run` command, on the subparser p: --set-name (add_set_argument),
    --only, --threads/-j, --parallel/-P, --sphjet (default: the build under repo), --dry-run,
    and a hidden --tmax that shortens every run (plumbing checks)."""
    add_set_argument(p, set_names)
    p.add_argument("--only", action="extend", nargs="+", metavar="RUN",
                   help="only these runs of the chosen sets (names as `run --dry-run` lists them)")
    p.add_argument("--threads", "-j", type=int, default=2, help="OpenMP threads per run (default 2)")
    p.add_argument("--parallel", "-P", type=at_least_one, default=1, metavar="N",
                   help="runs at a time (default 1). On 2 cores, `--parallel 2 --threads 1` makes two "
                        "runs in 0.77 of the time that one after the other on two threads take")
    p.add_argument("--sphjet", default=os.path.join(repo, "build", "cpp_driver", "sphjet"),
                   help="sphjet binary (default: REPO/build/cpp_driver/sphjet)")
    p.add_argument("--dry-run", action="store_true", help="print the commands, run nothing")
    p.add_argument("--tmax", type=float, default=None, help=argparse.SUPPRESS)


def add_numerics_arguments(p):
    """--artificial-alpha A, --reconstruct, --c0 C, --cfl K, --leapfrog and --xsph E on the
    subparser p: numerics of every run of a study that the case leaves at their defaults
    (numerics.artificial_alpha, numerics.artificial_reconstruction, fluid.c0, time.cfl,
    numerics.integrator, numerics.xsph_eps; cases/CASE_FORMAT.md), in a study directory of its
    own (numerics_tag)."""
    p.add_argument("--artificial-alpha", type=float, default=0.0, metavar="A",
                   help="numerics.artificial_alpha = A in every run, on top of the laminar viscosity "
                        "(default 0: off; directory suffix _alphaA)")
    p.add_argument("--reconstruct", action="store_true",
                   help="numerics.artificial_reconstruction = true in every run: the artificial viscosity "
                        "of --artificial-alpha damps the particle-scale motion only (suffix _rec)")
    p.add_argument("--c0", type=float, default=None, metavar="C",
                   help="fluid.c0 = C [m/s] in every run of the measured jets: the sound speed, which "
                        "sets the step (default: the case's, 16; suffix _c0C)")
    p.add_argument("--cfl", type=float, default=None, metavar="K",
                   help="time.cfl = K in every run: the Courant number of the variable step "
                        "(default: the case's, 0.2; suffix _cflK)")
    p.add_argument("--leapfrog", action="store_true",
                   help="numerics.integrator = \"leapfrog\" in every run: one evaluation of the rates "
                        "per step instead of the predictor-corrector's two (suffix _lf)")
    p.add_argument("--xsph", type=float, default=None, metavar="E",
                   help="numerics.xsph_eps = E in every run, 0 < E <= 1: the weight of the XSPH "
                        "velocity correction (default: the case's; suffix _xsphE)")


def check_numerics(ap, args):
    """Refuses (ap.error) an alpha outside [0, 1], --reconstruct without an alpha, a sound speed
    that is not positive, a Courant number outside (0, 1] and an XSPH weight outside (0, 1]."""
    if not 0 <= args.artificial_alpha <= 1:
        ap.error(f"--artificial-alpha {args.artificial_alpha}: expected in [0, 1]")
    if args.reconstruct and not args.artificial_alpha > 0:
        ap.error("--reconstruct acts on the artificial viscosity of --artificial-alpha: give --artificial-alpha A > 0")
    if args.c0 is not None and not args.c0 > 0:
        ap.error(f"--c0 {args.c0}: expected a positive sound speed [m/s]")
    if args.cfl is not None and not 0 < args.cfl <= 1:
        ap.error(f"--cfl {args.cfl}: expected a Courant number in (0, 1]")
    if args.xsph is not None and not 0 < args.xsph <= 1:
        ap.error(f"--xsph {args.xsph}: expected an XSPH weight in (0, 1]")


# The shared numerics: (args attribute, case key, directory suffix, flag, the value a switch
# sets), in the order of their overrides, suffixes and flags. An option is given when its value
# is true (an alpha of 0, a sound speed or Courant number left at None and a switch not set are
# the case's); a switch (True) sets its key to its value and adds its suffix and flag alone, a
# number adds its value to each.
NUMERICS = (("artificial_alpha", "numerics.artificial_alpha", "_alpha", "--artificial-alpha", None),
            ("reconstruct", "numerics.artificial_reconstruction", "_rec", "--reconstruct", "true"),
            ("c0", "fluid.c0", "_c0", "--c0", None),
            ("cfl", "time.cfl", "_cfl", "--cfl", None),
            ("leapfrog", "numerics.integrator", "_lf", "--leapfrog", "leapfrog"),
            ("xsph", "numerics.xsph_eps", "_xsph", "--xsph", None))


def given_numerics(args):
    """-> (key, suffix, flag, value, set) of each of NUMERICS that args give: value '' for a
    switch, set the value its key is set to."""
    out = []
    for attr, key, suffix, flag, on in NUMERICS:
        v = getattr(args, attr)
        if v:
            out.append((key, suffix, flag, "" if v is True else f"{v:g}", on if v is True else f"{v:g}"))
    return out


def numerics_sets(args):
    """-> the --set overrides of args' numerics, [] when all are the case's."""
    return [f"{key}={value}" for key, _s, _f, _v, value in given_numerics(args)]


def numerics_tag(args):
    """-> the study directory's suffix for args' numerics: _alphaA, _alphaA_rec, _c0C, _cflK, _lf,
    _xsphE, those together or ''."""
    return "".join(suffix + v for _k, suffix, _f, v, _set in given_numerics(args))


def numerics_flags(args):
    """-> args' numerics as the command-line flags that give them ('' when all are the case's)."""
    return "".join(f" {flag}" + (f" {v}" if v else "") for _k, _s, flag, v, _set in given_numerics(args))


def dispatch(args, run, report, tool):
    """A study's `run` or `report` (args.cmd), with --root (and for `run` --sphjet) made
    absolute, since sphjet runs in the repository; a StudyError is printed as `tool: message`
    and gives exit code 2."""
    args.root = os.path.abspath(args.root)
    if args.cmd == "run":
        args.sphjet = os.path.abspath(args.sphjet)
    try:
        return run(args) if args.cmd == "run" else report(args)
    except StudyError as e:
        print(f"{tool}: {e}", file=sys.stderr)
        return 2


def open_report(sdir, out, how):
    """A report's start: sdir must hold a study (else StudyError naming it and `how`, the run
    command that makes it); the output directory out is made."""
    if not os.path.isdir(sdir):
        raise StudyError(f"{sdir}: no study there (run `{how}` first)")
    os.makedirs(out, exist_ok=True)


# ---------------------------------------------------------------- run
def run_command(sphjet, case, run_dir, sets, threads, tmax, go_on=False):
    """-> (state, argv): state is 'done', 'resume' or 'new'. go_on: a finished run resumes from
    its checkpoint too (to tmax), never starts afresh."""
    if finished(run_dir) and not go_on:
        return "done", None
    if go_on or os.path.isfile(os.path.join(run_dir, "checkpoint.h5")):
        argv = [sphjet, "run", "--resume", run_dir, "-j", str(threads)]
    else:
        argv = [sphjet, "run", case, "--out", run_dir, "-j", str(threads)]
        if os.path.isdir(run_dir) and os.listdir(run_dir):
            argv.append("--force")   # an aborted start without checkpoint: nothing to keep
        for s in sets:
            argv += ["--set", s]
    if tmax is not None:
        argv += ["--tmax", f"{tmax:g}"]
    return ("resume" if "--resume" in argv else "new"), argv


def tail(path, n=15):
    lines = read_lines(path)
    return "\n".join("    " + l for l in lines[-n:]) if lines else "    (no run.log)"


def select_runs(full, names, only, sphjet, dry_run):
    """The runs of the plan `full` (tuples whose [0] is the set name and [1] the run name) in
    the sets `names`, only those named in `only` when given; StudyError for a name not in the
    plan, or for a missing sphjet binary when runs are to be made."""
    todo = [r for r in full if r[0] in names]
    if only:
        known = {r[1] for r in full}
        bad = [x for x in only if x not in known]
        if bad:
            raise StudyError(f"--only {' '.join(bad)}: not in the plan; the runs are "
                             f"{', '.join(r[1] for r in full)}")
        todo = [r for r in todo if r[1] in only]
    if not dry_run and not os.access(sphjet, os.X_OK):
        raise StudyError(f"{sphjet}: sphjet binary not found or not executable "
                         f"(build it with tools/build.sh, or give --sphjet PATH)")
    return todo


def prefixed_copy(stream, prefix, lock):
    """Copies the lines of `stream` (a run's merged stdout and stderr) to this process's stdout
    as they come, each after `prefix` (the run's name), in a thread of its own: the lines of runs
    made side by side stay whole and say whose they are. -> the thread (ends at the stream's end)."""
    out = sys.stdout

    def copy():
        try:
            for line in stream:
                with lock:
                    try:
                        out.write(prefix + line if line.endswith("\n") else prefix + line + "\n")
                        out.flush()
                    except (OSError, ValueError):   # our stdout gone (a closed pipe): keep reading,
                        pass                        # so that the run never blocks on its output
        finally:
            stream.close()

    t = threading.Thread(target=copy, daemon=True)
    t.start()
    return t


def run_all(todo, sdir, case, sphjet, threads, tmax, dry_run, tool, title, cwd, parallel=1, more_time=None):
    """Runs `todo` (a list of (name, [key=value overrides])) of the base case `case` in
    sdir/NAME, `parallel` at a time, as the module says. tool: the command named in messages
    ("jet_study.py run"); title: the first line printed; cwd: where sphjet runs. A failure
    starts no more runs and stops the others with SIGTERM (each keeps a checkpoint). With more
    than one at a time, each run's output lines are printed after its name (prefixed_copy).
    more_time(name, run_dir): for a finished run, None, or (t, why) when it is to go on to the
    end t [s] (it resumes with --tmax t; asked again when that part ends), or (None, why) when
    it is made no longer for a reason worth printing beside "done". -> exit code."""
    locks = {}   # name -> the open lock file of a run this `run` makes (held until it returns)
    try:
        if not dry_run:
            os.makedirs(sdir, exist_ok=True)

        def take(name):
            """Whether this `run` may make the run `name`: its lock taken (or held already)."""
            if name not in locks:
                f = open(os.path.join(sdir, f".{name}.lock"), "w")
                try:
                    fcntl.flock(f, fcntl.LOCK_EX | fcntl.LOCK_NB)
                except OSError:
                    f.close()
                    return False
                locks[name] = f
            return True

        got_signal = []
        running = {}   # Popen -> its queue entry (k, (name, sets))
        asked = {}     # name -> more_time's answer for a run that has just ended
        readers = {}   # Popen -> the thread that copies its output (parallel > 1)
        out_lock = threading.Lock()

        def send_all(sig):
            for p in running:
                if p.poll() is None:
                    try:
                        p.send_signal(sig)
                    except ProcessLookupError:
                        pass

        def ask(name, run_dir):
            try:
                return more_time(name, run_dir)
            except (OSError, ValueError, KeyError, IndexError, csv.Error) as e:
                print(f"{name}: cannot tell whether it is to go on ({e}); left as it is", file=sys.stderr, flush=True)
                return None

        def forward(sig, _frame):
            got_signal.append(sig)
            send_all(sig)

        if not dry_run:
            signal.signal(signal.SIGINT, forward)
            signal.signal(signal.SIGTERM, forward)

        m = len(todo)
        print(title, flush=True)
        n_done = n_run = n_busy = 0
        failed = None   # the exit code to return once the runs still going have stopped
        queue = list(enumerate(todo, 1))
        while queue or running:
            while queue and len(running) < parallel and not got_signal and failed is None:
                entry = queue.pop(0)
                k, (name, sets) = entry
                run_dir = os.path.join(sdir, name)
                head = f"[{k}/{m}] {name}"
                longer = asked.pop(name, None)
                if longer is None and more_time and finished(run_dir):
                    longer = ask(name, run_dir)
                why_not = f" ({longer[1]})" if longer and longer[0] is None else ""
                if why_not:
                    longer = None
                state, argv = run_command(sphjet, case, run_dir, sets, threads, longer[0] if longer else tmax,
                                          go_on=bool(longer))
                if state == "done":
                    print(f"{head}: finished, skipped{why_not}", flush=True)
                    n_done += 1
                    continue
                if not dry_run and not take(name):
                    print(f"{head}: another `{tool}` is making it (lock {sdir}/.{name}.lock); skipped", flush=True)
                    n_busy += 1
                    continue
                what = (f"going on to t = {longer[0]:.4g} s ({longer[1]})" if longer
                        else "resuming from its checkpoint" if state == "resume" else "starting")
                print(f"{head}: {what}\n  {shlex.join(argv)}", flush=True)
                if dry_run:
                    continue
                os.makedirs(os.path.dirname(run_dir), exist_ok=True)
                try:
                    if parallel == 1:   # sphjet's own output, its progress line on a terminal
                        running[subprocess.Popen(argv, cwd=cwd)] = entry
                    else:
                        p = subprocess.Popen(argv, cwd=cwd, stdout=subprocess.PIPE,
                                             stderr=subprocess.STDOUT, text=True, errors="replace")
                        running[p] = entry
                        readers[p] = prefixed_copy(p.stdout, f"{name}| ", out_lock)
                except OSError as e:   # e.g. the binary replaced by a build while the study ran
                    send_all(signal.SIGTERM)
                    for p in running:
                        p.wait()
                    raise StudyError(f"{head}: cannot start {argv[0]}: {e.strerror}; the runs made "
                                     f"so far are kept, run `{tool}` again to go on (a study can use "
                                     f"a copy of the binary: --sphjet PATH)")
            if not running:   # none left to start (all done, a failure or a signal)
                break
            ended = [p for p in running if p.poll() is not None]
            if not ended:
                time.sleep(0.2)
                continue
            for p in ended:
                entry = running.pop(p)
                k, (name, _sets) = entry
                run_dir, head = os.path.join(sdir, name), f"[{k}/{m}] {name}"
                if p in readers:
                    readers.pop(p).join()   # its last lines before what follows on its end
                rc = p.returncode
                log = os.path.join(run_dir, "run.log")
                if got_signal:
                    print(f"{head}: stopped by signal {got_signal[0]} (sphjet exit {rc}); "
                          f"run `{tool}` again to resume", file=sys.stderr, flush=True)
                    continue
                if rc != 0 and blew_up(run_dir):
                    # A blow-up is a result (reported by `report`); the study goes on.
                    print(f"{head}: blew up ({blew_up(run_dir)[:160]}); going on", flush=True)
                    n_run += 1
                    continue
                if rc != 0 or not finished(run_dir):
                    if failed is None and running:
                        send_all(signal.SIGTERM)   # they stop with a checkpoint
                    if rc != 0:
                        print(f"{head}: FAILED with exit code {rc}; the end of {log}:\n{tail(log)}",
                              file=sys.stderr, flush=True)
                        if failed is None:
                            failed = rc if 0 < rc < 256 else 1
                    else:
                        print(f"{head}: sphjet exited 0 but {log} has no `done:` line; the end of it:\n"
                              f"{tail(log)}", file=sys.stderr, flush=True)
                        if failed is None:
                            failed = 1
                    continue
                longer = ask(name, run_dir) if more_time else None
                if longer and longer[0] is not None:
                    asked[name] = longer
                    queue.insert(0, entry)   # made longer next, before the runs not yet started
                    continue
                n_run += 1
                print(f"{head}: done" + (f" ({longer[1]})" if longer else ""), flush=True)
        if got_signal:
            return 128 + got_signal[0]
        if failed is not None:
            return failed
        if dry_run:
            print(f"dry run: {m - n_done} of {m} run(s) to do")
        else:
            busy = f", {n_busy} being made by another `{tool}`" if n_busy else ""
            print(f"{tool.split()[0]}: {n_run} run(s) made, {n_done} already finished{busy}, {m} in all")
        return 0

    finally:
        for f in locks.values():
            f.close()


# ---------------------------------------------------------------- a run's summary
def read_csv(path):
    """A CSV file with a header line -> list of dicts of strings."""
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def run_summary(run_dir, summary, reduce, need=()):
    """Fills `summary` (a dict with "status" and "notes"; the study's own fields with their
    empty values) from run_dir: run.log's numbers (parse_log), then reduce(rows) with the rows
    of jet.csv. -> reduce's result, or None where summary["status"] says why there is none:
    "missing" (no run directory), "no jet.csv", or "unreadable" with a note naming jet.csv and
    the error (a missing column of `need`, a value that is not a number, a KeyError or
    StudyError raised by reduce)."""
    summary.setdefault("status", "missing")
    summary.setdefault("notes", [])
    if not os.path.isdir(run_dir):
        summary["status"] = "missing"
        return None
    summary.update(parse_log(run_dir))
    path = os.path.join(run_dir, "jet.csv")
    if not os.path.isfile(path):
        summary["status"] = "no jet.csv"
        return None
    try:
        rows = read_csv(path)
        if rows and any(c not in rows[0] for c in need):
            raise StudyError(f"expected columns {', '.join(need)}, found {', '.join(rows[0])}")
        return reduce(rows)
    except (StudyError, OSError, KeyError, ValueError) as e:
        summary["status"] = "unreadable"
        summary["notes"].append(f"{path}: {e}")
        return None


def is_broken(row):
    """A jet.csv row of a broken jet (broken = 1)."""
    return int(float(row["broken"])) == 1


def first_breakup(rows):
    """The first jet.csv row with the jet broken, or None."""
    return next((x for x in rows if is_broken(x)), None)


def drops_at(drops, step):
    """The drops.csv rows of one breakup check (its step, as jet.csv writes it)."""
    return [x for x in drops if x["step"] == step]


# ---------------------------------------------------------------- report cells and tables
def fmt(v, spec=".2f", none="-"):
    """A number as a table cell; `none` for a missing one."""
    return none if v is None else format(v, spec)


def shown(path, repo):
    """A path as a committed report names it: relative to the repository `repo` when inside it,
    else as given."""
    rel = os.path.relpath(os.path.abspath(path), repo)
    return path if rel.startswith("..") else rel


def md_table(header, rows):
    """A Markdown table (header, then one line a row)."""
    out = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    out += ["| " + " | ".join(str(c) for c in row) + " |" for row in rows]
    return "\n".join(out) + "\n"
