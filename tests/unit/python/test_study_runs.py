#!/usr/bin/env python3
"""Unit tests of tools/study_runs.py, the module the studies share (running their runs,
reading a run's run.log and jet.csv into its summary). Synthetic run directories and a stand-in
for sphjet (a small script that writes a run.log); no simulation. Each test states what it
checks; the numbers compared are exact (they are parsed from text or counted), except where a
test says otherwise.

usage: test_study_runs.py   (unittest; exit 0 when every test passes)
"""
import fcntl
import io
import os
import stat
import sys
import tempfile
import textwrap
import threading
import unittest
from contextlib import redirect_stderr, redirect_stdout

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(os.path.dirname(HERE)))
sys.path.insert(0, os.path.join(REPO, "tools"))

import study_runs as sr  # noqa: E402

CASE_LINE = "case: c.toml | particles 120 (boundary 20, fluid 100) | h = 0.002 m"
JET_HEADER = "time,step,broken,L_over_d0,u_flux,jet_tip_over_d0,n_drops,head_drop_d_over_d0"


def write(path, text):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w") as f:
        f.write(textwrap.dedent(text).lstrip("\n"))


def done_line(steps, total, t, wall, rate):
    return (f"done: {steps} steps ({total} in all) to t = {t} s (SPHysics clock {t} s) in "
            f"{wall} s wall; {rate} particle-steps/s; 3 outputs; 0 particles left the domain")


class RunLogTests(unittest.TestCase):
    """What run.log says of a run: finished or not, blown up, its numbers."""

    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.dir = self.tmp.name

    def tearDown(self):
        self.tmp.cleanup()

    def log(self, *lines):
        write(os.path.join(self.dir, "run.log"), "\n".join(lines) + "\n")

    def test_last_part_starts_at_the_last_start_or_resume(self):
        lines = ["sphjet 1 starting", "a", "sphjet 1 resuming", "b"]
        self.assertEqual(sr.last_part(lines), ["sphjet 1 resuming", "b"])
        self.assertEqual(sr.last_part(["x", "y"]), ["x", "y"])

    def test_done_after_a_signal_is_not_finished(self):
        # sphjet writes `done:` also when stopped by a signal: the run goes on at the next `run`
        self.log("sphjet 1 starting", CASE_LINE, "stopped by signal 15 at step 5",
                 done_line(5, 5, 0.01, 2.0, 300.0))
        self.assertFalse(sr.finished(self.dir))
        self.log("sphjet 1 starting", CASE_LINE, "stopped by signal 15 at step 5",
                 done_line(5, 5, 0.01, 2.0, 300.0), "sphjet 1 resuming",
                 done_line(7, 12, 0.02, 3.0, 280.0))
        self.assertTrue(sr.finished(self.dir))

    def test_a_blow_up_is_finished_and_named(self):
        failed = "FAILED: state check at step 40 (t = 0.012 s): density out of band"
        self.log("sphjet 1 starting", CASE_LINE, failed)
        self.assertEqual(sr.blew_up(self.dir), failed)
        self.assertTrue(sr.finished(self.dir))

    def test_parse_log_sums_parts(self):
        # 10 + 20 s of wall time over two parts; particle-steps/s over both:
        # (10 s x 60 + 20 s x 42) / 30 s = 48
        self.log("sphjet 1 starting", CASE_LINE, done_line(5, 5, 0.01, 10, 60.0),
                 "sphjet 1 resuming", CASE_LINE, done_line(7, 12, 0.02, 20, 42.0))
        got = sr.parse_log(self.dir)
        self.assertEqual((got["particles"], got["boundary"], got["fluid"]), (120, 20, 100))
        self.assertEqual((got["steps"], got["parts"], got["t_end"]), (12, 2, 0.02))
        self.assertEqual(got["wall_s"], 30.0)
        self.assertEqual(got["particle_steps"], 1440.0)
        self.assertEqual(got["particle_steps_per_s"], 48.0)
        self.assertTrue(got["finished"])

    def test_parse_log_counts_the_particles_that_left(self):
        # the last part's count is the run's; ids logged twice (a part made again) count once
        gone = "step 3 t = 0.004 s: 2 particle(s) left the domain and were removed (2 in all); ids 11 12"
        self.log("sphjet 1 starting", CASE_LINE, gone, "sphjet 1 resuming", CASE_LINE, gone,
                 "step 9 t = 0.015 s: 1 particle(s) left the domain and were removed (3 in all); ids 4")
        got = sr.parse_log(self.dir)
        self.assertEqual(got["left"], 3)
        self.assertEqual(got["left_at"], {11: 0.004, 12: 0.004, 4: 0.015})
        self.log("sphjet 1 starting", CASE_LINE, gone,
                 done_line(5, 5, 0.01, 10, 60.0).replace("0 particles left", "2 particles left"))
        self.assertEqual(sr.parse_log(self.dir)["left"], 2)
        # a part killed after id 13 left, resumed from a checkpoint before it: 13 is not kept,
        # and the last count is the resumed part's, which ends without a `done:` (it blew up)
        self.log("sphjet 1 starting", CASE_LINE, gone,
                 done_line(5, 5, 0.01, 10, 60.0).replace("0 particles left", "2 particles left"),
                 "sphjet 1 resuming", "resuming at step 5 t = 0.01 s from checkpoint.h5",
                 "step 7 t = 0.012 s: 1 particle(s) left the domain and were removed (3 in all); ids 13",
                 "sphjet 1 resuming", "resuming at step 5 t = 0.01 s from checkpoint.h5",
                 "step 8 t = 0.013 s: 2 particle(s) left the domain and were removed (4 in all); ids 14 15",
                 "FAILED: state check at step 9 (t = 0.014 s): density out of band")
        got = sr.parse_log(self.dir)
        self.assertEqual(got["left"], 4)
        self.assertEqual(got["left_at"], {11: 0.004, 12: 0.004, 14: 0.013, 15: 0.013})

    def test_parse_log_without_a_log(self):
        got = sr.parse_log(self.dir)
        self.assertIsNone(got["wall_s"])
        self.assertEqual(got["parts"], 0)
        self.assertFalse(got["finished"])


class RunCommandTests(unittest.TestCase):
    """Which sphjet command a run directory gets, and which runs a plan selects."""

    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.dir = os.path.join(self.tmp.name, "r")

    def tearDown(self):
        self.tmp.cleanup()

    def test_new_resume_done(self):
        state, argv = sr.run_command("sphjet", "c.toml", self.dir, ["a.b=1"], 2, None)
        self.assertEqual(state, "new")
        self.assertEqual(argv, ["sphjet", "run", "c.toml", "--out", self.dir, "-j", "2",
                                "--set", "a.b=1"])
        # an aborted start without a checkpoint: nothing to keep, so --force
        write(os.path.join(self.dir, "run.log"), "sphjet 1 starting\n")
        state, argv = sr.run_command("sphjet", "c.toml", self.dir, [], 2, 0.5)
        self.assertEqual(state, "new")
        self.assertEqual(argv[-3:], ["--force", "--tmax", "0.5"])
        write(os.path.join(self.dir, "checkpoint.h5"), "")
        state, argv = sr.run_command("sphjet", "c.toml", self.dir, ["a.b=1"], 1, None)
        self.assertEqual((state, argv), ("resume", ["sphjet", "run", "--resume", self.dir, "-j", "1"]))
        write(os.path.join(self.dir, "run.log"), f"sphjet 1 starting\n{done_line(1, 1, 0.1, 1, 1)}\n")
        self.assertEqual(sr.run_command("sphjet", "c.toml", self.dir, [], 1, None), ("done", None))

    def test_select_runs(self):
        plan = [("a", "a1", []), ("a", "a2", []), ("b", "b1", [])]
        self.assertEqual([r[1] for r in sr.select_runs(plan, ["a"], None, "x", True)], ["a1", "a2"])
        self.assertEqual([r[1] for r in sr.select_runs(plan, ["a", "b"], ["b1"], "x", True)], ["b1"])
        with self.assertRaisesRegex(sr.StudyError, "--only nope: not in the plan"):
            sr.select_runs(plan, ["a"], ["nope"], "x", True)
        with self.assertRaisesRegex(sr.StudyError, "not found or not executable"):
            sr.select_runs(plan, ["a"], None, os.path.join(self.tmp.name, "none"), False)


FAKE_SPHJET = """\
#!/usr/bin/env python3
# Stands in for sphjet run: a line on stdout and one on stderr, a run.log of one part; exit
# code from FAKE_RC.
import os, sys
a = sys.argv[1:]
out = a[a.index("--resume") + 1] if "--resume" in a else a[a.index("--out") + 1]
os.makedirs(out, exist_ok=True)
rc = int(os.environ.get("FAKE_RC", "0"))
print("progress of " + os.path.basename(out), flush=True)
print("a warning of " + os.path.basename(out), file=sys.stderr, flush=True)
with open(os.path.join(out, "run.log"), "a") as f:
    f.write("sphjet 1 " + ("resuming" if "--resume" in a else "starting") + "\\n")
    if rc == 0:
        f.write("done: 3 steps (3 in all) to t = 0.1 s (SPHysics clock 0.1 s) in 1 s wall; "
                "9 particle-steps/s; 1 outputs; 0 particles left the domain\\n")
sys.exit(rc)
"""


class CommandLineTests(unittest.TestCase):
    """A study's `run` options, as both studies give them."""

    def test_run_arguments(self):
        ap, sub = sr.study_parser("First paragraph.\n\nThe rest.")
        add = sub.add_parser("run")
        sr.add_run_arguments(add, ("a", "b"), "/repo")
        args = ap.parse_args(["run", "--set-name", "a", "--only", "r1", "r2", "-j", "3", "--tmax", "0.1"])
        self.assertEqual((args.cmd, args.set_name, args.only, args.threads, args.tmax, args.dry_run),
                         ("run", ["a"], ["r1", "r2"], 3, 0.1, False))
        self.assertEqual(args.sphjet, os.path.join("/repo", "build", "cpp_driver", "sphjet"))
        self.assertEqual((ap.description, ap.epilog), ("First paragraph.", "The rest."))
        with redirect_stderr(io.StringIO()), self.assertRaises(SystemExit):
            ap.parse_args(["run", "--set-name", "c"])   # not a set of the study
        self.assertEqual((args.parallel, ap.parse_args(["run", "--parallel", "2"]).parallel), (1, 2))
        for bad in ("0", "two"):
            err = io.StringIO()
            with redirect_stderr(err), self.assertRaises(SystemExit):
                ap.parse_args(["run", "--parallel", bad])
            self.assertIn("expected an integer >= 1", err.getvalue())

    def test_numerics_arguments(self):
        ap, sub = sr.study_parser("Doc.\n\nMore.")
        sr.add_numerics_arguments(sub.add_parser("run"))
        args = ap.parse_args(["run"])
        self.assertEqual((sr.numerics_sets(args), sr.numerics_tag(args), sr.numerics_flags(args)), ([], "", ""))
        args = ap.parse_args(["run", "--artificial-alpha", "0.02", "--reconstruct", "--c0", "12", "--cfl", "0.25"])
        sr.check_numerics(ap, args)
        self.assertEqual(sr.numerics_sets(args), ["numerics.artificial_alpha=0.02",
                                                  "numerics.artificial_reconstruction=true", "fluid.c0=12",
                                                  "time.cfl=0.25"])
        self.assertEqual(sr.numerics_tag(args), "_alpha0.02_rec_c012_cfl0.25")
        self.assertEqual(sr.numerics_flags(args), " --artificial-alpha 0.02 --reconstruct --c0 12 --cfl 0.25")
        # a switch that sets its key to a name, not to true
        args = ap.parse_args(["run", "--c0", "12", "--leapfrog"])
        self.assertEqual(sr.numerics_sets(args), ["fluid.c0=12", "numerics.integrator=leapfrog"])
        self.assertEqual((sr.numerics_tag(args), sr.numerics_flags(args)), ("_c012_lf", " --c0 12 --leapfrog"))
        for bad, says in ((["--c0", "0"], "expected a positive sound speed"),
                          (["--cfl", "1.5"], "expected a Courant number in (0, 1]"),
                          (["--reconstruct"], "give --artificial-alpha A > 0")):
            err = io.StringIO()
            with redirect_stderr(err), self.assertRaises(SystemExit):
                sr.check_numerics(ap, ap.parse_args(["run"] + bad))
            self.assertIn(says, err.getvalue())


class RunAllTests(unittest.TestCase):
    """The study loop with a stand-in sphjet: runs what is missing, skips what is finished,
    stops on the first failure with its exit code."""

    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.sphjet = os.path.join(self.tmp.name, "sphjet")
        write(self.sphjet, FAKE_SPHJET)
        os.chmod(self.sphjet, os.stat(self.sphjet).st_mode | stat.S_IXUSR)
        self.sdir = os.path.join(self.tmp.name, "study")

    def tearDown(self):
        os.environ.pop("FAKE_RC", None)
        self.tmp.cleanup()

    def run_all(self, todo, dry_run=False, parallel=1):
        out, err = io.StringIO(), io.StringIO()
        with redirect_stdout(out), redirect_stderr(err):
            rc = sr.run_all(todo, self.sdir, "c.toml", self.sphjet, 1, None, dry_run,
                            "study.py run", "a study", self.tmp.name, parallel)
        return rc, out.getvalue(), err.getvalue()

    def test_two_at_a_time(self):
        todo = [("r1", []), ("r2", []), ("r3", [])]
        rc, out, _ = self.run_all(todo, parallel=2)
        self.assertEqual(rc, 0)
        for k in (1, 2, 3):
            self.assertIn(f"[{k}/3] r{k}: done", out)
            self.assertTrue(sr.finished(os.path.join(self.sdir, f"r{k}")))
        self.assertIn("3 run(s) made, 0 already finished, 3 in all", out)
        # the first two start before either is waited for
        self.assertLess(out.index("[2/3] r2: starting"), out.index("[1/3] r1: done"))
        # each run's output (stdout and stderr) comes whole, after the run's name, before its end
        for k in (1, 2, 3):
            for line in (f"r{k}| progress of r{k}\n", f"r{k}| a warning of r{k}\n"):
                self.assertEqual(out.count(line), 1)
                self.assertLess(out.index(line), out.index(f"[{k}/3] r{k}: done"))
        self.assertEqual(out.count("progress of"), 3)

    def test_made_longer_until_more_time_says_no(self):
        # r1 wants two more parts (to t = 0.2, then 0.3), asked after each; r2 none; with the
        # runs done, a second `run` asks again and makes r1 longer once more
        asked, ends = [], {"r1": [0.2, 0.3]}

        def more_time(name, run_dir):
            asked.append(name)
            left = ends.get(name)
            return (left.pop(0), "its window") if left else None

        out, err = io.StringIO(), io.StringIO()
        with redirect_stdout(out), redirect_stderr(err):
            rc = sr.run_all([("r1", []), ("r2", [])], self.sdir, "c.toml", self.sphjet, 1, None, False,
                            "study.py run", "a study", self.tmp.name, 1, more_time)
        out = out.getvalue()
        self.assertEqual(rc, 0)
        self.assertIn("[1/2] r1: going on to t = 0.2 s (its window)", out)
        self.assertIn("[1/2] r1: going on to t = 0.3 s (its window)", out)
        self.assertIn("--tmax 0.3", out)
        # r1 ends before r2 starts; each is counted once
        self.assertLess(out.index("[1/2] r1: done"), out.index("[2/2] r2: starting"))
        self.assertIn("2 run(s) made, 0 already finished, 2 in all", out)
        self.assertEqual(asked, ["r1", "r1", "r1", "r2"])
        log = os.path.join(self.sdir, "r1", "run.log")
        with open(log) as f:
            self.assertEqual(f.read().count("resuming"), 2)
        ends["r1"] = [0.4]
        out = io.StringIO()
        with redirect_stdout(out), redirect_stderr(io.StringIO()):
            rc = sr.run_all([("r1", []), ("r2", [])], self.sdir, "c.toml", self.sphjet, 1, None, False,
                            "study.py run", "a study", self.tmp.name, 1, more_time)
        self.assertEqual(rc, 0)
        self.assertIn("[1/2] r1: going on to t = 0.4 s", out.getvalue())
        self.assertIn("[2/2] r2: finished, skipped", out.getvalue())

    def test_made_no_longer_with_a_reason(self):
        # more_time's (None, why): the run ends there and `done` says why, at its end and when a
        # second `run` skips it; r2's None prints a plain `done`
        def more_time(name, run_dir):
            return (None, "its window not steady") if name == "r1" else None

        for finished_line in ("[1/2] r1: done (its window not steady)\n",
                              "[1/2] r1: finished, skipped (its window not steady)\n"):
            out = io.StringIO()
            with redirect_stdout(out), redirect_stderr(io.StringIO()):
                rc = sr.run_all([("r1", []), ("r2", [])], self.sdir, "c.toml", self.sphjet, 1, None,
                                False, "study.py run", "a study", self.tmp.name, 1, more_time)
            self.assertEqual(rc, 0)
            self.assertIn(finished_line, out.getvalue())
            self.assertNotIn("going on", out.getvalue())
        self.assertIn("[2/2] r2: finished, skipped\n", out.getvalue())
        with open(os.path.join(self.sdir, "r1", "run.log")) as f:
            self.assertEqual(f.read().count("resuming"), 0)

    def test_a_failing_more_time_leaves_the_run_as_it_is(self):
        def more_time(name, run_dir):
            raise KeyError("L_over_d0")

        out, err = io.StringIO(), io.StringIO()
        with redirect_stdout(out), redirect_stderr(err):
            rc = sr.run_all([("r1", [])], self.sdir, "c.toml", self.sphjet, 1, None, False,
                            "study.py run", "a study", self.tmp.name, 1, more_time)
        self.assertEqual(rc, 0)
        self.assertIn("[1/1] r1: done", out.getvalue())
        self.assertIn("r1: cannot tell whether it is to go on ('L_over_d0'); left as it is", err.getvalue())

    def test_copy_outlives_a_closed_stdout(self):
        # a stdout that fails (the pipe it went to closed): the copy reads on to the end, so a run
        # never blocks on a full pipe, and closes the stream
        class Gone(io.StringIO):
            def write(self, _s):
                raise BrokenPipeError(32, "Broken pipe")
        stream = io.StringIO("a line\n" * 100000)
        with redirect_stdout(Gone()):
            t = sr.prefixed_copy(stream, "r1| ", threading.Lock())
        t.join(10)
        self.assertFalse(t.is_alive())
        self.assertTrue(stream.closed)

    def test_failure_with_two_at_a_time_starts_no_more(self):
        os.environ["FAKE_RC"] = "3"
        rc, out, err = self.run_all([("r1", []), ("r2", []), ("r3", [])], parallel=2)
        self.assertEqual(rc, 3)
        # both first runs fail; whichever ends first is reported with its code
        self.assertIn(": FAILED with exit code 3", err)
        self.assertNotIn("[3/3]", out)
        self.assertFalse(os.path.exists(os.path.join(self.sdir, "r3")))

    def test_runs_then_skips(self):
        todo = [("r1", ["a=1"]), ("r2", [])]
        rc, out, _ = self.run_all(todo, dry_run=True)
        self.assertEqual(rc, 0)
        self.assertIn("dry run: 2 of 2 run(s) to do", out)
        self.assertFalse(os.path.exists(os.path.join(self.sdir, "r1")))
        rc, out, _ = self.run_all(todo)
        self.assertEqual(rc, 0)
        self.assertIn("[1/2] r1: done", out)
        self.assertIn("2 run(s) made, 0 already finished, 2 in all", out)
        self.assertTrue(sr.finished(os.path.join(self.sdir, "r1")))
        rc, out, _ = self.run_all(todo)
        self.assertEqual(rc, 0)
        self.assertIn("[2/2] r2: finished, skipped", out)
        self.assertIn("0 run(s) made, 2 already finished", out)

    def test_a_run_another_run_command_makes_is_skipped(self):
        # another `run` in the same study directory holds r1's lock: this one makes r2 alone,
        # leaves r1's directory untouched and says so; once the lock is let go, r1 is made
        os.makedirs(self.sdir)
        with open(os.path.join(self.sdir, ".r1.lock"), "w") as held:
            fcntl.flock(held, fcntl.LOCK_EX | fcntl.LOCK_NB)
            rc, out, _ = self.run_all([("r1", []), ("r2", [])])
        self.assertEqual(rc, 0)
        self.assertIn("[1/2] r1: another `study.py run` is making it", out)
        self.assertIn("[2/2] r2: done", out)
        self.assertIn("1 run(s) made, 0 already finished, 1 being made by another `study.py run`, 2 in all", out)
        self.assertFalse(os.path.exists(os.path.join(self.sdir, "r1")))
        rc, out, _ = self.run_all([("r1", []), ("r2", [])])
        self.assertEqual(rc, 0)
        self.assertIn("[1/2] r1: done", out)
        self.assertIn("1 run(s) made, 1 already finished, 2 in all", out)

    def test_first_failure_stops_with_its_code(self):
        os.environ["FAKE_RC"] = "3"
        rc, out, err = self.run_all([("r1", []), ("r2", [])])
        self.assertEqual(rc, 3)
        self.assertIn("[1/2] r1: FAILED with exit code 3", err)
        # the second run is never started (its progress line and its directory; the
        # temporary directory's random name may hold "r2" itself)
        self.assertNotIn("[2/2]", out)
        self.assertFalse(os.path.exists(os.path.join(self.sdir, "r2")))


class SummaryTests(unittest.TestCase):
    """run_summary and the row tests: a run's status when it has no directory, no jet.csv or an
    unreadable one, and the rows handed to the study's reduction otherwise."""

    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.dir = os.path.join(self.tmp.name, "run")

    def tearDown(self):
        self.tmp.cleanup()

    def jet(self, text):
        write(os.path.join(self.dir, "jet.csv"), text)

    def test_missing_and_no_jet_csv(self):
        r = {"status": "missing", "notes": []}
        self.assertIsNone(sr.run_summary(self.dir, r, lambda rows: 1))
        self.assertEqual(r["status"], "missing")
        write(os.path.join(self.dir, "run.log"),
              f"sphjet 1 starting\n{CASE_LINE}\n{done_line(4, 4, 0.1, 2, 240)}\n")
        self.assertIsNone(sr.run_summary(self.dir, r, lambda rows: 1))
        self.assertEqual(r["status"], "no jet.csv")
        self.assertEqual(r["particles"], 120)   # run.log read all the same
        self.assertTrue(r["finished"])

    def test_rows_reach_the_reduction(self):
        self.jet(f"""
            {JET_HEADER}
            0.01,10,0,0,0.06,0.5,0,0
            0.02,20,1,8.5,0.07,9.0,2,1.9
            0.03,30,1.0,7.5,0.07,9.5,3,1.8
            """)
        r = {"status": "missing", "notes": []}
        rows = sr.run_summary(self.dir, r, lambda rows: rows, need=JET_HEADER.split(","))
        self.assertEqual(len(rows), 3)
        self.assertEqual(sr.first_breakup(rows)["step"], "20")
        self.assertEqual([sr.is_broken(x) for x in rows], [False, True, True])
        self.assertEqual(r["notes"], [])

    def test_unreadable(self):
        # a column missing from `need`, and a value that is not a number in the reduction
        self.jet("time,step\n0.01,10\n")
        r = {"status": "missing", "notes": []}
        self.assertIsNone(sr.run_summary(self.dir, r, lambda rows: rows, need=("time", "broken")))
        self.assertEqual(r["status"], "unreadable")
        self.assertEqual(r["notes"], [f"{os.path.join(self.dir, 'jet.csv')}: expected columns "
                                      f"time, broken, found time, step"])
        self.jet(f"{JET_HEADER}\n0.01,10,yes,0,0,0,0,0\n")
        r = {"status": "missing", "notes": []}
        self.assertIsNone(sr.run_summary(self.dir, r, sr.first_breakup))
        self.assertEqual(r["status"], "unreadable")
        self.assertIn("could not convert string to float: 'yes'", r["notes"][0])

    def test_no_breakup_and_drops_at(self):
        self.assertIsNone(sr.first_breakup([{"broken": "0"}, {"broken": "0.0"}]))
        drops = [{"step": "20", "d": "1"}, {"step": "30", "d": "2"}, {"step": "20", "d": "3"}]
        self.assertEqual([x["d"] for x in sr.drops_at(drops, "20")], ["1", "3"])
        self.assertEqual(sr.drops_at(drops, "40"), [])


class TableTests(unittest.TestCase):
    def test_fmt(self):
        self.assertEqual(sr.fmt(None), "-")
        self.assertEqual(sr.fmt(1.234), "1.23")
        self.assertEqual(sr.fmt(3, "d"), "3")
        self.assertEqual(sr.fmt(None, none="n/a"), "n/a")

    def test_md_table(self):
        self.assertEqual(sr.md_table(["a", "b"], [[1, "x"], [2.5, None]]),
                         "| a | b |\n|---|---|\n| 1 | x |\n| 2.5 | None |\n")

    def test_shown(self):
        # inside the repository: relative to it; outside: as given
        repo = os.path.join(os.sep, "r", "repo")
        self.assertEqual(sr.shown(os.path.join(repo, "runs", "s"), repo), os.path.join("runs", "s"))
        self.assertEqual(sr.shown(os.path.join(os.sep, "tmp", "s"), repo), os.path.join(os.sep, "tmp", "s"))


if __name__ == "__main__":
    unittest.main()
