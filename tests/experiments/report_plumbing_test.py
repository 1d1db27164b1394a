"""The experiments' plumbing without measuring: the shared command line (--out, --data,
--report-only), the generated report and the results index, on copies of committed data in a
scratch folder. Run by ctest (label cpu): /usr/bin/python3 -m unittest report_plumbing_test."""
import json
import os
import shutil
import statistics
import subprocess
import sys
import tempfile
import unittest

REPO = os.path.abspath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
sys.path.insert(0, os.path.join(REPO, "experiments", "common"))
import cutaway_experiment as cx  # noqa: E402
import report_markdown as md  # noqa: E402
import results_index  # noqa: E402
import stage_style  # noqa: E402
import strategy_style  # noqa: E402

PYTHON = "/usr/bin/python3"


def run(*args, env=None):
    return subprocess.run([PYTHON, *args], capture_output=True, text=True, env=env)


class MarkdownTest(unittest.TestCase):
    def test_table_aligns_first_column_left_and_numbers_right(self):
        self.assertEqual(md.table(["a", "b", "c"], [[1, "2", 3.5]]), ["| a | b | c |", "|---|---:|---:|", "| 1 | 2 | 3.5 |"])

    def test_context_states_only_what_was_measured(self):
        context = {"gl_renderer": "llvmpipe", "LP_NUM_THREADS": "2", "git_revision": "abc1234", "cpu_count": 2}
        self.assertIn("load was not recorded", md.context_paragraph(context))
        context.update(load_average_at_start=[1.25, 0, 0], load_average_at_end=[3.5, 0, 0])
        text = md.context_paragraph(context)
        self.assertIn("1.2 at the start and 3.5 at the end", text)
        self.assertIn("LP_NUM_THREADS=2", text)
        self.assertNotIn("shared", text)

    def test_dirty_revision_is_named_in_the_context_and_the_command(self):
        context = {"git_revision": "abc1234-dirty", "lp_num_threads": "4"}
        self.assertIn("with uncommitted changes", md.context_paragraph(context))
        lines = md.reproduce_lines("table1", context, quick=True)
        self.assertIn("git checkout abc1234", lines)
        self.assertIn("LP_NUM_THREADS=4 experiments/table1/run.py --force --quick", lines)

    def test_index_entry_reads_back_the_headline(self):
        with tempfile.TemporaryDirectory() as scratch:
            report = md.Report("Title", "What it measures.", headline="x 12 ms")
            document = {"context": {"git_revision": "abc", "date": "2026-01-02T03:04:05+0000"}}
            path = os.path.join(scratch, "README.md")
            with open(path, "w") as f:
                f.write(md.markdown(report, "demo", document, scratch, os.path.join(scratch, "demo.json")))
            self.assertEqual(md.index_entry(path), {"experiment": "demo", "headline": "x 12 ms", "revision": "abc",
                                                    "date": "2026-01-02", "quick": False})


class CommandLineTest(unittest.TestCase):
    def setUp(self):
        self.scratch = tempfile.mkdtemp(prefix="cutaway-plumbing-")

    def tearDown(self):
        shutil.rmtree(self.scratch)

    def stored(self, experiment, data_file):
        """A copy of the committed data of `experiment` under SCRATCH/results/."""
        folder = os.path.join(self.scratch, "results", experiment)
        os.makedirs(folder)
        shutil.copy(os.path.join(REPO, "results", experiment, data_file), folder)
        return folder

    def test_report_only_writes_under_out_from_the_stored_data(self):
        folder = self.stored("table1", "table1.json")
        result = run(os.path.join(REPO, "experiments", "table1", "run.py"), "--report-only", "--out", self.scratch)
        self.assertEqual(result.returncode, 0, result.stderr)
        entry = md.index_entry(os.path.join(folder, "README.md"))
        with open(os.path.join(folder, "table1.json")) as f:
            revision = json.load(f)["context"]["git_revision"]
        self.assertEqual(entry["revision"], revision)
        self.assertIn("sapphire frame", entry["headline"])

    def test_report_only_without_data_is_one_line_and_exit_2(self):
        result = run(os.path.join(REPO, "experiments", "scale", "run.py"), "--report-only", "--out", self.scratch)
        self.assertEqual(result.returncode, 2)
        self.assertEqual(len(result.stderr.strip().splitlines()), 1, result.stderr)
        self.assertIn("--report-only", result.stderr)
        self.assertFalse(os.path.exists(os.path.join(self.scratch, "results", "scale", "README.md")))

    def test_missing_data_folder_names_the_option_and_the_path(self):
        missing = os.path.join(self.scratch, "no-such-data")
        result = run(os.path.join(REPO, "experiments", "volume_renders", "run.py"), "--force", "--out", self.scratch,
                     "--data", missing)
        self.assertEqual(result.returncode, 2)
        self.assertEqual(result.stderr.strip().splitlines(), [result.stderr.strip()])
        self.assertIn("--data", result.stderr)
        self.assertIn(missing, result.stderr)
        env = {**os.environ, "CUTAWAY_SHARED_DATA": missing}
        result = run(os.path.join(REPO, "experiments", "volume_renders", "run.py"), "--force", "--out", self.scratch, env=env)
        self.assertEqual(result.returncode, 2)
        self.assertIn("CUTAWAY_SHARED_DATA", result.stderr)

    def test_out_must_be_a_folder(self):
        path = os.path.join(self.scratch, "a-file")
        open(path, "w").close()
        result = run(os.path.join(REPO, "experiments", "table1", "run.py"), "--report-only", "--out", path)
        self.assertEqual(result.returncode, 2)
        self.assertIn("--out", result.stderr)

    def test_index_has_a_row_per_experiment_with_its_headline(self):
        self.stored("volume_fig7", "fig7.json")
        result = run(os.path.join(REPO, "experiments", "volume_fig7", "run.py"), "--report-only", "--out", self.scratch)
        self.assertEqual(result.returncode, 0, result.stderr)
        result = run(os.path.join(REPO, "experiments", "run_all"), "--index-only", "--out", self.scratch)
        self.assertEqual(result.returncode, 0, result.stderr)
        with open(os.path.join(self.scratch, "results", "README.md")) as f:
            index = f.read()
        rows = [line for line in index.splitlines() if line.startswith("| [") or line.startswith("| ")]
        experiments = results_index.experiment_names(os.path.join(REPO, "experiments"))
        for name in experiments:
            self.assertTrue(any(row.startswith(f"| {name} |") or row.startswith(f"| [{name}]") for row in rows), name)
        with open(os.path.join(self.scratch, "results", "volume_fig7", "fig7.json")) as f:
            eyes = json.load(f)["eyes"]
        # The headline's ratio: of the casters' medians over the eyes of each eye's median trial.
        medians = {c: statistics.median(statistics.median(e[c]["trials_ms"]) for e in eyes) for c in ("gpu", "cpu")}
        ratio = medians["cpu"] / medians["gpu"]
        fig7 = next(row for row in rows if row.startswith("| [volume_fig7]"))
        self.assertIn(f"({ratio:.2f}x)", fig7)


class PlotTest(unittest.TestCase):
    def test_every_strategy_in_the_data_has_its_own_colour_and_marker(self):
        with open(os.path.join(REPO, "results", "cut_strategies", "results.json")) as f:
            names = set(json.load(f)["context"]["strategies"].split(",")) | {"auto"}
        self.assertEqual(names - set(strategy_style.STYLES), set())
        self.assertEqual(len({c for c, _ in strategy_style.STYLES.values()}), len(strategy_style.STYLES))
        self.assertEqual(len({m for _, m in strategy_style.STYLES.values()}), len(strategy_style.STYLES))

    def test_no_stage_has_a_strategy_colour(self):
        stages = {c for s, c in stage_style.COLOURS.items() if s != "total"}  # the total: black, drawn bold
        self.assertEqual(stages & {c for c, _ in strategy_style.STYLES.values()}, set())
        self.assertEqual(len(set(stage_style.COLOURS.values())), len(stage_style.COLOURS))

    def test_report_only_redraws_rounds_from_data_with_one_timed_frame(self):
        for name, data in (("stage_over_path", "stage_over_path.json"), ("scale", "scale.json")):
            folder = os.path.join(self.scratch, "results", name)
            os.makedirs(folder)
            shutil.copy(os.path.join(REPO, "results", name, data), folder)
            result = run(os.path.join(REPO, "experiments", name, "run.py"), "--report-only", "--out", self.scratch)
            self.assertEqual(result.returncode, 0, result.stderr)
            self.assertNotIn("text below", result.stderr)
            self.assertTrue(os.path.exists(os.path.join(self.scratch, "paper_figures", name + ".png")), name)

    def test_device_label_names_what_the_data_recorded(self):
        self.assertEqual(cx.device_label({"gl_renderer": "NVIDIA H200/PCIe/SSE2"}), "NVIDIA H200")
        label = cx.device_label({"gl_renderer": "llvmpipe (LLVM 15.0.6, 256 bits)", "LP_NUM_THREADS": "3"})
        self.assertIn("software rasteriser, 3 threads", label)
        self.assertIn("thread count not recorded", cx.device_label({"gl_renderer": "llvmpipe"}))

    def test_report_only_redraws_the_plots_at_print_size(self):
        folder = os.path.join(self.scratch, "results", "cut_strategies")
        os.makedirs(folder)
        shutil.copy(os.path.join(REPO, "results", "cut_strategies", "results.json"), folder)
        result = run(os.path.join(REPO, "experiments", "cut_strategies", "run.py"), "--report-only", "--out", self.scratch)
        self.assertEqual(result.returncode, 0, result.stderr)
        self.assertNotIn("text below", result.stderr)
        for name in ("cut_strategies_time", "cut_strategies_ratio", "cut_strategies_error"):
            for ext in (".png", ".pdf"):
                self.assertTrue(os.path.exists(os.path.join(self.scratch, "paper_figures", name + ext)), name + ext)

    def setUp(self):
        self.scratch = tempfile.mkdtemp(prefix="cutaway-plots-")

    def tearDown(self):
        shutil.rmtree(self.scratch)


if __name__ == "__main__":
    unittest.main()
