"""One experiment's generated report, results/NAME/README.md: markdown helpers (tables, figure
links) and the parts every report shares (the machine, revision, LP_NUM_THREADS and GL renderer
from the data's context, the command that reproduces the run), plus the one-line summary that
experiments/run_all's index reads back from the report's first line.

A report states only what its data holds: a context without a load average says it was not
recorded, one without a date gives the date its data was committed, named as such."""
import json
import os
import re

from experiment_io import commit_date

INDEX_MARK = "<!-- index: "
INDEX_LINE = re.compile(r"^<!-- index: (\{.*\}) -->$")


def table(header, rows, align=None):
    """Markdown table lines; `align` one letter per column, 'l' or 'r' (default: the first column
    left, the others right, as numbers are)."""
    align = align or "l" + "r" * (len(header) - 1)
    lines = ["| " + " | ".join(header) + " |", "|" + "|".join("---" if a == "l" else "---:" for a in align) + "|"]
    lines += ["| " + " | ".join(str(cell) for cell in row) + " |" for row in rows]
    return lines


def ms(value):
    """Milliseconds as a table shows them: whole above 100, one decimal below."""
    return "-" if value is None else f"{value:,.0f}" if value >= 100 else f"{value:.1f}"


def first(context, *keys):
    """The first of `keys` the context holds (older runs named some fields differently)."""
    return next((context[k] for k in keys if context.get(k) not in (None, "")), None)


def run_date(context, data_path):
    """(date, how it is known): the run's recorded date, else the date its data was committed."""
    date = first(context, "date")
    if date:
        return str(date)[:10], "recorded"
    committed = commit_date(data_path) if data_path else None
    return (committed, "committed") if committed else (None, "unknown")


def load_sentence(context):
    """The machine's measured load, or that it was not measured (never a guess)."""
    cores = first(context, "cpu_count", "num_cpus")
    start, end = context.get("load_average_at_start"), first(context, "load_average_at_end", "load_average_1_5_15_min_at_end")
    if start is None and end is None:
        return "The machine's load was not recorded in this run."
    parts = ([f"{start[0]:.1f} at the start"] if start else []) + ([f"{end[0]:.1f} at the end"] if end else [])
    return f"Load average (1 minute, {cores} cores): {' and '.join(parts)} of the run."


def system_name(uname):
    """'Linux 6.1.0 x86_64' from a `uname -a`-like string (with or without the host name)."""
    words = str(uname or "").split()
    if not words:
        return "system not recorded"
    release = next((w for w in words[1:] if re.match(r"\d+\.\d+", w)), "")
    return " ".join(w for w in (words[0], release, words[-1] if len(words) > 1 else "") if w)


def context_paragraph(context, data_path=None):
    """Where and how the data was measured, from its context."""
    revision = first(context, "git_revision") or "unknown"
    dirty = revision.endswith("-dirty")
    date, known = run_date(context, data_path)
    cores, model = first(context, "cpu_count", "num_cpus") or "?", first(context, "cpu_model")
    cpu = f"{cores} x {model}" if model else f"{cores} CPUs (model not recorded)"
    system = system_name(first(context, "uname"))
    when = {"recorded": f"on {date}", "committed": f"committed on {date} (the run's date was not recorded)",
            "unknown": "date not recorded"}[known]
    return (f"Machine: {cpu} ({system}); GL renderer {first(context, 'gl_renderer', 'gl_renderer_ours') or 'not recorded'}; "
            f"LP_NUM_THREADS={first(context, 'LP_NUM_THREADS', 'lp_num_threads') or 'unset'}. Revision "
            f"`{revision.removesuffix('-dirty')}`" + (" with uncommitted changes to the code" if dirty else "") +
            f", {when}. {load_sentence(context)}")


def reproduce_lines(name, context, quick):
    """The commands that rerun the experiment at the revision that measured it."""
    revision = (first(context, "git_revision") or "HEAD").removesuffix("-dirty")
    threads = first(context, "LP_NUM_THREADS", "lp_num_threads")
    command = (f"LP_NUM_THREADS={threads} " if threads and threads != "unset" else "") + \
        f"experiments/{name}/run.py --force" + (" --quick" if quick else "")
    lines = ["```sh", f"git checkout {revision}" if revision not in ("unknown", "HEAD") else "# at the current checkout",
             "cmake --preset release && cmake --build build -j2", command, "```"]
    if str(first(context, "git_revision") or "").endswith("-dirty"):
        lines.append("The run had uncommitted changes on top of that revision: the command repeats it only approximately.")
    return lines


def figure_lines(readme_folder, paths):
    """An image link per existing figure (relative to the report, with its PDF where there is one);
    figures not on disk are named as missing."""
    lines = []
    for path in paths:
        relative = os.path.relpath(path, readme_folder)
        if not os.path.exists(path):
            lines.append(f"- `{os.path.basename(path)}`: missing (run the experiment without --report-only to draw it)")
            continue
        pdf = os.path.splitext(path)[0] + ".pdf"
        extra = f" ([PDF]({os.path.relpath(pdf, readme_folder)}))" if path.endswith(".png") and os.path.exists(pdf) else ""
        lines.append(f"- [{os.path.basename(path)}]({relative}){extra}")
        lines.append(f"  ![{os.path.basename(path)}]({relative})")
    return lines


class Report:
    """The experiment-specific part of a report: title, what it measures (one paragraph), a headline
    for the index (one short phrase with its number, or None), then sections of text and tables,
    and the figures it links."""

    def __init__(self, title, measures, headline=None):
        self.title, self.measures, self.headline = title, measures, headline
        self.body, self.figures = [], []

    def section(self, heading, *paragraphs):
        self.body += ([""] if self.body and self.body[-1] else []) + [f"## {heading}", ""]
        for paragraph in paragraphs:
            self.text(paragraph)
        return self

    def text(self, paragraph):
        self.body += [paragraph, ""]
        return self

    def table(self, header, rows, align=None):
        self.body += table(header, rows, align) + [""]
        return self

    def bullets(self, items):
        self.body += [f"- {item}" for item in items] + [""]
        return self

    def figure(self, *paths):
        self.figures += list(paths)
        return self


def markdown(report, name, document, readme_folder, data_path):
    """The whole README: index line, title, what it measures, machine and revision, how to
    reproduce, the experiment's sections, its figures."""
    context = document.get("context") or {}
    quick = bool(document.get("quick", context.get("quick")))
    date, _ = run_date(context, data_path)
    entry = {"experiment": name, "headline": report.headline, "revision": first(context, "git_revision"), "date": date,
             "quick": quick}
    lines = [INDEX_MARK + json.dumps(entry) + " -->", f"# {report.title}", "",
             f"Generated by `experiments/{name}/run.py` from `{os.path.basename(data_path)}` beside this file "
             "(`--report-only` rewrites it from that data); do not edit.", ""]
    if quick:
        lines += ["**Quick run**: small sizes and few repetitions, a smoke test, not a reference result.", ""]
    lines += [report.measures, "", "## Machine and revision", "", context_paragraph(context, data_path), "",
              "## Reproduce", "", *reproduce_lines(name, context, quick)]
    lines += [""] + report.body
    if report.figures:
        lines += ["", "## Figures", "", *figure_lines(readme_folder, report.figures)]
    text = "\n".join(line.rstrip() for line in lines).rstrip() + "\n"
    return re.sub(r"\n{3,}", "\n\n", text)  # sections join with one blank line


def index_entry(readme_path):
    """The summary a generated report carries on its first line, or None (not a generated report)."""
    try:
        with open(readme_path) as f:
            match = INDEX_LINE.match(f.readline().strip())
    except OSError:
        return None
    return json.loads(match.group(1)) if match else None


def title_of(readme_path):
    """The first '# ' heading of a markdown file, or None."""
    try:
        with open(readme_path) as f:
            return next((line[2:].strip() for line in f if line.startswith("# ")), None)
    except OSError:
        return None
