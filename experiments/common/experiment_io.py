"""What every experiment script shares below the command line: the repository's path, its git
revision, JSON in and out, matplotlib, and how written paths are printed."""
import json
import os
import subprocess
import sys

REPO = os.path.abspath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))


def shown(path):
    """`path` relative to the repository when inside it (shorter in logs), else absolute."""
    path = os.path.abspath(path)
    return os.path.relpath(path, REPO) if path.startswith(REPO + os.sep) else path


def wrote(path):
    print("wrote", shown(path), flush=True)


def write_json(path, data):
    with open(path, "w") as f:
        json.dump(data, f, indent=2)
        f.write("\n")
    wrote(path)


def read_json(path):
    with open(path) as f:
        return json.load(f)


def git_revision():
    """HEAD of the checkout the scripts run from, with "-dirty" when tracked files outside results/
    and paper_figures/ have uncommitted changes (the code that measured is not HEAD's)."""
    try:
        head = subprocess.run(["git", "-C", REPO, "rev-parse", "HEAD"], capture_output=True, text=True, check=True).stdout.strip()
        dirty = subprocess.run(["git", "-C", REPO, "status", "--porcelain", "--untracked-files=no", "--", ".", ":!results",
                                ":!paper_figures"],
                               capture_output=True, text=True).stdout.strip()
        return head + ("-dirty" if dirty else "")
    except (OSError, subprocess.CalledProcessError):
        return "unknown"


def commit_date(path):
    """The date (YYYY-MM-DD) of the last commit that added or changed `path`'s content (following
    renames, which keep the date of the data they moved), or None (not committed, no git)."""
    try:
        out = subprocess.run(["git", "-C", os.path.dirname(os.path.abspath(path)), "log", "-1", "--follow", "--diff-filter=AM",
                              "--format=%cs", "--",
                              os.path.basename(path)], capture_output=True, text=True, check=True).stdout.strip()
        return out or None
    except (OSError, subprocess.CalledProcessError):
        return None


def require_matplotlib():
    """matplotlib.pyplot with the Agg backend; re-runs the script under /usr/bin/python3 (where
    Debian's python3-matplotlib lives) when the python3 on PATH lacks it."""
    try:
        import matplotlib
    except ImportError:
        system = "/usr/bin/python3"
        if os.path.realpath(sys.executable) != os.path.realpath(system) and os.path.exists(system):
            os.execv(system, [system] + sys.argv)
        raise SystemExit("matplotlib is missing: apt-get install python3-matplotlib (scripts/install-deps.sh)")
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    return plt
