"""Tests of report.py: the Goals table judges each goal from the results it is given.

The results are those of a real run (trade-bench/results/, which the report needs anyway), copied
to a scratch directory, with the figures each goal reads set to known values. Standard library
only: `python3 -m unittest discover -s trade-bench/src/test/python` (pytest runs it too).
"""
import json
import os
import shutil
import subprocess
import sys
import tempfile
import unittest

BENCH = os.path.normpath(os.path.join(os.path.dirname(__file__), "..", "..", ".."))
REPORT = os.path.join(BENCH, "src", "main", "python", "report.py")
RESULTS = os.path.join(BENCH, "results")


class GoalsTableTest(unittest.TestCase):
    def setUp(self):
        self.dir = tempfile.mkdtemp(prefix="trade-report-")
        self.res = os.path.join(self.dir, "results")
        self.docs = os.path.join(self.dir, "docs")
        shutil.copytree(RESULTS, self.res, ignore=shutil.ignore_patterns("logs"))
        os.mkdir(self.docs)

    def tearDown(self):
        shutil.rmtree(self.dir)

    def edit(self, name, change):
        path = os.path.join(self.res, name)
        with open(path) as f:
            data = json.load(f)
        change(data)
        with open(path, "w") as f:
            json.dump(data, f)

    def goals(self):
        """Runs the report and answers its Goals table as {goal: (measured, verdict)}."""
        subprocess.run([sys.executable, REPORT, self.res, self.docs, "src/run-benchmarks"],
                       check=True, capture_output=True)
        with open(os.path.join(self.docs, "benchmarks.md")) as f:
            page = f.read()
        table = page.split("## Goals\n", 1)[1].split("\n\n", 1)[0]
        rows = {}
        for line in table.splitlines()[3:]:  # the blank line, the header and its rule
            cells = [c.strip() for c in line.strip("|").split("|")]
            rows[cells[0]] = (cells[1], cells[2])
        return rows

    def set_remote(self, small, calls64):
        """small: p50 µs by system; calls64: 64-caller calls/s by system."""
        def change(d):
            for system, p50 in small.items():
                d["latency"]["small"][system]["p50_us"] = p50
            for system, calls in calls64.items():
                d["throughput"]["64_callers"][system]["calls_per_s"] = calls
        self.edit("remote.json", change)

    def set_convergence(self, first_round_ms, warm_ms):
        """One run of 100 containers per figure (None: did not converge), like the run's own."""
        def change(d):
            template = next(s for s in d["sizes"] if s["containers"] == 100)
            d["sizes"] = [s for s in d["sizes"] if s["containers"] != 100]
            for ms, warm in zip(first_round_ms, warm_ms):
                d["sizes"].append(dict(template, converged=ms is not None,
                                       convergence_ms=ms or 60_000, warm_converged=warm is not None,
                                       warm_convergence_ms=warm or 60_000))
        self.edit("scale.json", change)

    def test_ratios_are_judged_against_the_same_run(self):
        self.set_remote({"trade": 10.0, "rmi": 20.0, "raw-tcp": 9.0, "grpc": 50.0},
                        {"trade": 150_000, "rmi": 100_000, "grpc": 10_000})
        g = self.goals()
        self.assertEqual(g["small-call p50 ≤ 1.0× RMI"], ("0.50×", "met"))
        self.assertEqual(g["small-call p50 ≤ 1.25× raw TCP"], ("1.11×", "met"))
        self.assertEqual(g["64-caller throughput ≥ 2× RMI"], ("1.50×", "**missed**"))
        self.assertEqual(g["64-caller throughput ≥ gRPC-java"], ("15.00×", "met"))

    def test_a_goal_on_its_bound_is_met_and_just_past_it_missed(self):
        self.set_remote({"trade": 12.5, "rmi": 12.4, "raw-tcp": 10.0},
                        {"trade": 200_000, "rmi": 100_000})
        g = self.goals()
        self.assertEqual(g["small-call p50 ≤ 1.25× raw TCP"], ("1.25×", "met"))
        self.assertEqual(g["small-call p50 ≤ 1.0× RMI"], ("1.01×", "**missed**"))
        self.assertEqual(g["64-caller throughput ≥ 2× RMI"], ("2.00×", "met"))

    def test_convergence_is_the_median_of_the_runs_and_a_run_that_never_converged_counts(self):
        self.set_convergence([9_000, 12_000, 11_000], [6_000, 7_000, 8_000])
        g = self.goals()
        self.assertEqual(g["100 containers converge ≤ 10 s (median of 3 runs)"], ("11.0 s", "**missed**"))
        self.assertEqual(g["the same in warm JVMs: a second round in the same JVMs (median of 3)"],
                         ("7.0 s", "met"))

        self.set_convergence([9_000, None, None], [6_000, 7_000, 8_000])
        g = self.goals()
        self.assertEqual(g["100 containers converge ≤ 10 s (median of 3 runs)"],
                         ("not within 60 s", "**missed**"))

    def test_start_and_death_are_judged_on_median_and_worst(self):
        def change(d):
            template = d["iterations"][0]
            d["iterations"] = [dict(template, start_to_callable_ms=250 if i % 2 else 400,
                                    kill_to_left_ms=1_200 if i == 0 else 10)
                               for i in range(8)]  # median 325 ms, worst 1,200 ms
        self.edit("lifecycle.json", change)
        g = self.goals()
        self.assertEqual(g["start → callable ≤ 300 ms (median)"], ("325 ms", "**missed**"))
        self.assertEqual(g["kill -9 → left ≤ 1 s (worst)"], ("1200 ms", "**missed**"))

    def test_a_part_that_did_not_run_leaves_its_goals_unjudged(self):
        os.remove(os.path.join(self.res, "scale.json"))
        os.remove(os.path.join(self.res, "lifecycle.json"))
        g = self.goals()
        self.assertEqual(g["100 containers converge ≤ 10 s (median of 0 runs)"], ("–", "–"))
        self.assertEqual(g["start → callable ≤ 300 ms (median)"], ("–", "–"))
        self.assertEqual(g["kill -9 → left ≤ 1 s (worst)"], ("–", "–"))
        self.assertEqual(g["≤ 16 MB heap per container (100 containers, largest)"], ("–", "–"))


if __name__ == "__main__":
    unittest.main()
