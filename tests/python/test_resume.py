"""Checkpoint and resume from Python (magfem.sweep, study, validate with checkpoint_dir= and
resume=True; issue 32), against the command line's --out DIR --resume.

An axial FE sweep stopped by KeyboardInterrupt from its progress callable after its first
position leaves the command line's checkpoint (and nothing else) in checkpoint_dir; resumed
from Python it gives sweep.csv byte for byte as an uninterrupted run and as `magfem sweep`.
That the resumed call takes the finished positions from the checkpoint (rather than solving
all again, which would give the same bytes) is shown by a record altered on disk, whose
value the resumed result carries. A resume on another case is refused with the command
line's message, the checkpoint left as it was. `magfem sweep --resume` at its default mesh
scale continues a sweep Python left at its default (the same mesh, one identity). A study
resumes alike; resume=True without a checkpoint notes it in words for Python as for the
command line; and `magfem validate --resume` continues a validation a Python call left. Run by ctest
`python_resume` with MAGFEM_EXE and PYTHONPATH=build/python (~15 s)."""
import json
import os
import shutil
import subprocess
import sys
import tempfile
import unittest

import numpy as np
import yaml

import magfem

SOURCE = os.environ.get("MAGFEM_SOURCE_DIR", ".")
EXE = os.environ.get("MAGFEM_EXE", os.path.join(SOURCE, "build", "magfem"))
CHECKPOINT = ".magfem-checkpoint.jsonl"
VOICE_COIL = os.path.join(SOURCE, "examples", "axi", "voice_coil_magnet.yaml")
COMPENSATOR = os.path.join(SOURCE, "examples", "3d", "compensator_study.yaml")
# Six coarse FE positions, one at a time, so that an interrupt after the first leaves some
# positions to do.
POSITIONS = [0.0, 1.0, 2.0, 3.0, 4.0, 5.0]
FE = dict(translate="coil", positions=POSITIONS, mesh_scale=3.0, order=1, jobs=1)


def stop_after(n):
    """A progress callable that interrupts the call once n positions are done."""
    def progress(done, total):
        if done >= n:
            raise KeyboardInterrupt
    return progress


def records(directory):
    """The checkpoint's records (its first line is the run's identity)."""
    with open(os.path.join(directory, CHECKPOINT), encoding="utf-8") as f:
        lines = f.read().splitlines()
    return [json.loads(line) for line in lines[1:]]


class SweepResume(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.case = magfem.Case.load(VOICE_COIL)
        cls.whole = magfem.sweep(cls.case, **FE)
        with tempfile.TemporaryDirectory() as out:
            subprocess.run([EXE, "sweep", VOICE_COIL, "--move", "coil", "--axis", "z",
                            "--positions", ",".join("%g" % p for p in POSITIONS),
                            "--mesh-scale", "3", "--order", "1", "--jobs", "1", "--quiet",
                            "--out", out], check=True, stdout=subprocess.DEVNULL,
                           stderr=subprocess.DEVNULL)
            with open(os.path.join(out, "sweep.csv"), encoding="utf-8") as f:
                cls.cli_csv = f.read()

    def setUp(self):
        self.dir = tempfile.mkdtemp()
        self.addCleanup(shutil.rmtree, self.dir)

    def interrupted(self, directory):
        """An interrupted sweep into `directory`; returns how many positions it kept."""
        with self.assertRaises(KeyboardInterrupt):
            magfem.sweep(self.case, checkpoint_dir=directory, progress=stop_after(1), **FE)
        # The checkpoint, in the directory given, and nothing else half-written there.
        self.assertEqual(os.listdir(directory), [CHECKPOINT])
        kept = len(records(directory))
        self.assertGreaterEqual(kept, 1)
        return kept

    def test_resumed_sweep_is_the_uninterrupted_one(self):
        kept = self.interrupted(self.dir)
        print("interrupted after %d of %d positions" % (kept, len(POSITIONS)))
        self.assertLess(kept, len(POSITIONS), "the interrupt came after every position")
        seen = []
        resumed = magfem.sweep(self.case, checkpoint_dir=self.dir, resume=True,
                               progress=lambda done, total: seen.append(done), **FE)
        # Byte for byte: restored rows are the computed doubles (17 digits in the file).
        self.assertEqual(resumed.csv(), self.whole.csv())
        self.assertEqual(resumed.csv(), self.cli_csv)
        for name in self.whole.columns:
            np.testing.assert_array_equal(resumed[name], self.whole[name], err_msg=name)
        self.assertEqual(seen[-1], len(POSITIONS))
        # Complete: the checkpoint has served, as the command line removes it.
        self.assertEqual(os.listdir(self.dir), [])

    def test_resume_takes_the_finished_positions_from_the_checkpoint(self):
        self.interrupted(self.dir)
        # Alter one finished position's force on disk: a resume that solves it again (resume
        # ignored) would give the true force back.
        path = os.path.join(self.dir, CHECKPOINT)
        with open(path, encoding="utf-8") as f:
            lines = f.read().splitlines()
        entry = json.loads(lines[1])
        self.assertIn("fz_N", entry["value"])
        entry["value"]["fz_N"] = 1234.5
        lines[1] = json.dumps(entry)
        with open(path, "w", encoding="utf-8") as f:
            f.write("\n".join(lines) + "\n")
        resumed = magfem.sweep(self.case, checkpoint_dir=self.dir, resume=True, **FE)
        altered = int(np.argmin(np.abs(np.array(POSITIONS) - 1e3 * float(entry["key"]))))
        self.assertEqual(resumed["Fz_N"][altered], 1234.5)
        others = np.arange(len(POSITIONS)) != altered
        np.testing.assert_array_equal(resumed["Fz_N"][others], self.whole["Fz_N"][others])

    def test_without_resume_the_checkpoint_is_started_again(self):
        self.interrupted(self.dir)
        with open(os.path.join(self.dir, CHECKPOINT), encoding="utf-8") as f:
            lines = f.read().splitlines()
        entry = json.loads(lines[1])
        entry["value"]["fz_N"] = 1234.5
        with open(os.path.join(self.dir, CHECKPOINT), "w", encoding="utf-8") as f:
            f.write("\n".join([lines[0], json.dumps(entry)]) + "\n")
        again = magfem.sweep(self.case, checkpoint_dir=self.dir, **FE)
        self.assertEqual(again.csv(), self.whole.csv())

    def test_a_resume_of_another_case_is_refused_as_the_command_line_refuses_it(self):
        self.interrupted(self.dir)
        with open(os.path.join(self.dir, CHECKPOINT), "rb") as f:
            before = f.read()
        with open(VOICE_COIL, encoding="utf-8") as f:
            other = yaml.safe_load(f)
        other["regions"][2]["current"] = 2.0  # the coil's current: another case
        with self.assertRaises(magfem.InputError) as err:
            magfem.sweep(magfem.Case.from_dict(other), checkpoint_dir=self.dir, resume=True,
                         **FE)
        self.assertEqual(err.exception.field, "resume")
        reason = str(err.exception).split("'resume': ", 1)[1]
        self.assertIn("was left by a different run", reason)
        # The command line on the same other case and directory says the same.
        other_file = os.path.join(tempfile.mkdtemp(), "other.yaml")
        self.addCleanup(shutil.rmtree, os.path.dirname(other_file))
        with open(other_file, "w", encoding="utf-8") as f:
            yaml.safe_dump(other, f, sort_keys=False)
        run = subprocess.run([EXE, "sweep", other_file, "--move", "coil", "--axis", "z",
                              "--positions", "0:1:5", "--mesh-scale", "3", "--order", "1",
                              "--quiet", "--resume", "--out", self.dir],
                             stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
        self.assertEqual(run.returncode, 2)
        self.assertIn(reason, run.stderr)
        with open(os.path.join(self.dir, CHECKPOINT), "rb") as f:
            self.assertEqual(f.read(), before)
        # Other overrides of the same case are another run too.
        with self.assertRaises(magfem.InputError):
            magfem.sweep(self.case, checkpoint_dir=self.dir, resume=True,
                         **{**FE, "mesh_scale": 2.5})

    def test_the_command_line_resumes_a_python_sweep_at_the_default_scale(self):
        # Python's mesh_scale=1.0 and the command line's "as in the case" (0) are the same
        # mesh, so the checkpoint's identity names both as 1 (RunCheckpoint::mesh_scale_key):
        # without that the command line refuses it ("a different run", exit 2).
        default = {k: v for k, v in FE.items() if k != "mesh_scale"}
        default["positions"] = POSITIONS[:2]
        with self.assertRaises(KeyboardInterrupt):
            magfem.sweep(self.case, checkpoint_dir=self.dir, progress=stop_after(1), **default)
        kept = len(records(self.dir))
        self.assertGreaterEqual(kept, 1)
        run = subprocess.run([EXE, "sweep", VOICE_COIL, "--move", "coil", "--axis", "z",
                              "--positions", "0,1", "--order", "1", "--jobs", "1", "--quiet",
                              "--resume", "--out", self.dir],
                             stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
        self.assertEqual(run.returncode, 0, run.stderr)
        self.assertIn("--resume: %d finished positions from the checkpoint" % kept, run.stderr)
        self.assertFalse(os.path.exists(os.path.join(self.dir, CHECKPOINT)))

    def test_resume_needs_a_directory(self):
        with self.assertRaises(magfem.InputError) as err:
            magfem.sweep(self.case, resume=True, **FE)
        self.assertEqual(err.exception.field, "checkpoint_dir")


class StudyResume(unittest.TestCase):
    """The analytic compensator over a 2 x 2 grid: designs finish in milliseconds, so the
    interrupt may come after all of them; an altered record shows they are restored."""
    ARGS = dict(params={"R_out": [40, 50], "R_in": [30, 35]}, objectives="torque_at:90",
                rotate="outer", axis="y")

    def test_resumed_study_is_the_uninterrupted_one(self):
        case = magfem.Case.load(COMPENSATOR)
        whole = magfem.study(case, **self.ARGS)
        directory = tempfile.mkdtemp()
        self.addCleanup(shutil.rmtree, directory)
        for _ in range(2):  # one resumed as it is, one with a record altered
            with self.assertRaises(KeyboardInterrupt):
                magfem.study(case, checkpoint_dir=directory, progress=stop_after(1), jobs=1,
                             **self.ARGS)
            self.assertEqual(os.listdir(directory), [CHECKPOINT])
            if _ == 0:
                resumed = magfem.study(case, checkpoint_dir=directory, resume=True,
                                       **self.ARGS)
                self.assertEqual(resumed.csv(), whole.csv())
                self.assertEqual(os.listdir(directory), [])
        path = os.path.join(directory, CHECKPOINT)
        with open(path, encoding="utf-8") as f:
            lines = f.read().splitlines()
        entry = json.loads(lines[1])
        entry["value"]["objectives"] = [4.25]
        with open(path, "w", encoding="utf-8") as f:
            f.write("\n".join([lines[0], json.dumps(entry)]) + "\n")
        resumed = magfem.study(case, checkpoint_dir=directory, resume=True, **self.ARGS)
        self.assertEqual(np.count_nonzero(resumed["torque_at_90deg_Nm"] == 4.25), 1)


    def test_resume_without_a_checkpoint_is_a_note_worded_for_python_too(self):
        # The note comes from the library (pipeline/run_checkpoint.cpp) on stderr, for the
        # command line's --resume and resume=True alike: it names neither's spelling.
        directory = tempfile.mkdtemp()
        self.addCleanup(shutil.rmtree, directory)
        script = ("import magfem; magfem.study(magfem.Case.load(%r), checkpoint_dir=%r, "
                  "resume=True, **%r)" % (COMPENSATOR, directory, self.ARGS))
        run = subprocess.run([sys.executable, "-c", script], stdout=subprocess.DEVNULL,
                             stderr=subprocess.PIPE, text=True)
        self.assertEqual(run.returncode, 0, run.stderr)
        self.assertIn("magfem: note: resume: no checkpoint in %s, starting from the beginning"
                      % directory, run.stderr)
        self.assertNotIn("--resume", run.stderr)


class ValidateResume(unittest.TestCase):
    """validate's checkpoint is the command line's, identity and all: an entry finished by an
    interrupted Python call is restored by `magfem validate --out DIR --resume`."""
    ENTRY = "harwin.t1.paper.max_ratio_4"

    def test_the_command_line_continues_a_python_run(self):
        directory = tempfile.mkdtemp()
        self.addCleanup(shutil.rmtree, directory)
        with self.assertRaises(KeyboardInterrupt):
            magfem.validate(entries=[self.ENTRY], jobs=1, checkpoint_dir=directory,
                            progress=stop_after(1))
        self.assertEqual([r["key"] for r in records(directory)], [self.ENTRY])
        run = subprocess.run([EXE, "validate", "--only", self.ENTRY, "--jobs", "1", "--resume",
                              "--out", directory], stdout=subprocess.DEVNULL,
                             stderr=subprocess.PIPE, text=True)
        self.assertEqual(run.returncode, 0, run.stderr)
        self.assertIn(self.ENTRY, run.stderr)
        self.assertIn(" resumed", run.stderr)
        self.assertFalse(os.path.exists(os.path.join(directory, CHECKPOINT)))


if __name__ == "__main__":
    unittest.main()
