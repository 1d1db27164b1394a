"""The command line every experiment takes (each run.py and run_all), and the folders it decides.

  --quick        small sizes, few repetitions: a smoke test (outputs under results/quick/ and
                 paper_figures/quick/, so it never overwrites the reference results)
  --force        measure again even when the outputs exist (otherwise the script skips)
  --report-only  rewrite results/NAME/README.md and redraw the plots from the JSON already there,
                 measuring nothing (figures made of rendered frames stay as they are)
  --build DIR    build folder holding bin/ (default: <repo>/build)
  --out DIR      where results/ and paper_figures/ go (default: the repository)
  --data DIR     the shared data (default: $CUTAWAY_SHARED_DATA, else <repo>/../shared/data); only
                 the experiments that read it check it
"""
import os
import sys

from experiment_io import REPO, shown


def refuse(option, message):
    """Bad input: one line naming the option and what was expected, exit code 2, nothing written."""
    print(f"{shown(sys.argv[0]) or 'experiment'}: {option}: {message}", file=sys.stderr)
    sys.exit(2)


def add_common_options(parser, report_only=True):
    """The options every experiment accepts and run_all passes through."""
    parser.add_argument("--quick", action="store_true", help="small sizes, few repetitions: a smoke test")
    parser.add_argument("--force", action="store_true", help="measure again even if the outputs exist")
    if report_only:
        parser.add_argument("--report-only", action="store_true",
                            help="rewrite results/NAME/README.md and redraw the plots from the JSON already there, "
                                 "without measuring")
    parser.add_argument("--build", default=os.path.join(REPO, "build"), help="build folder with bin/ (default: %(default)s)")
    parser.add_argument("--out", default=REPO,
                        help="write DIR/results/ and DIR/paper_figures/ (default: the repository, %(default)s)")
    parser.add_argument("--data", default=None,
                        help="the shared data folder (default: $CUTAWAY_SHARED_DATA, else <repo>/../shared/data)")
    return parser


def output_root(value):
    """The --out folder, absolute: an existing folder, or a new one whose parent exists."""
    path = os.path.abspath(value)
    if os.path.exists(path) and not os.path.isdir(path):
        refuse("--out", f"expected a folder, found the file {path}")
    if not os.path.exists(path) and not os.path.isdir(os.path.dirname(path)):
        refuse("--out", f"expected a folder or a new folder in an existing one, found {path} (its parent does not exist)")
    return path


def results_base(out, quick):
    """DIR/results, or DIR/results/quick for --quick runs."""
    return os.path.join(out, "results", "quick") if quick else os.path.join(out, "results")


def figures_folder(out, quick):
    """DIR/paper_figures, or DIR/paper_figures/quick for --quick runs."""
    return os.path.join(out, "paper_figures", "quick") if quick else os.path.join(out, "paper_figures")


def data_folder(value):
    """The shared data folder (--data, else $CUTAWAY_SHARED_DATA, else <repo>/../shared/data), checked."""
    if value is not None:
        option, path = "--data", value
    elif os.environ.get("CUTAWAY_SHARED_DATA"):
        option, path = "--data (from CUTAWAY_SHARED_DATA)", os.environ["CUTAWAY_SHARED_DATA"]
    else:
        option, path = "--data (default <repo>/../shared/data)", os.path.join(os.path.dirname(REPO), "shared", "data")
    path = os.path.abspath(path)
    if not os.path.isdir(path):
        refuse(option, f"expected the shared data folder, found no folder at {path} (pass --data DIR)")
    return path


def pass_through(args):
    """The options of `args` (parsed with add_common_options) as run_all hands them to each run.py."""
    flags = ["--build", os.path.abspath(args.build), "--out", os.path.abspath(args.out)]
    flags += ["--quick"] if args.quick else []
    flags += ["--force"] if args.force else []
    flags += ["--report-only"] if getattr(args, "report_only", False) else []
    flags += ["--data", os.path.abspath(args.data)] if args.data is not None else []
    return flags
