"""The simulator cases of the front-tracking experiment: a generated model's deck run by OPM Flow,
or a shared deck (SPE9) copied and run with a restart at every report step.

Cases are kept in BUILD/front_tracking_cases/NAME/ (beside the binaries, git-ignored) and reused
while their EGRID and UNRST exist (--force runs them again): flow is the slow part of the
experiment and its output depends only on the deck.
"""
import json
import os
import shutil
import subprocess
import time

import cutaway_experiment as cx

SHARED_DATA = os.path.join(cx.REPO, "..", "shared", "data")
SPE9_DIR = os.path.join(SHARED_DATA, "opm", "spe9")
# SPE9's RPTRST writes a restart at the first report step of each year only; the experiment needs
# every report step (the record the deck's RPTRST is replaced by).
SPE9_RPTRST = ("'BASIC=4'", "'BASIC=2'")


def case_folder(build, name):
    return os.path.join(build, "front_tracking_cases", name)


def _flow(folder, deck):
    """Runs flow on DECK in `folder`; returns its wall time (s). Its log stays beside the case."""
    started = time.monotonic()
    with open(os.path.join(folder, "flow.log"), "w") as log:
        subprocess.run(["flow", deck, "--output-dir=" + folder], cwd=folder, check=True, stdout=log, stderr=subprocess.STDOUT)
    return time.monotonic() - started


def _ready(folder, case, force):
    info = os.path.join(folder, "case.json")
    if force or not all(os.path.exists(os.path.join(folder, case + ext)) for ext in (".EGRID", ".UNRST")) \
            or not os.path.exists(info):
        return None
    with open(info) as f:
        return json.load(f)


def _finish(folder, case, info):
    info["egrid"] = os.path.join(folder, case + ".EGRID")
    with open(os.path.join(folder, "case.json"), "w") as f:
        json.dump(info, f, indent=2)
    return info


def generated_case(exp, build, preset, force):
    """`cutaway generate --preset PRESET --deck DIR`, then flow; returns the case's description
    (egrid path, generate and flow wall times)."""
    folder, case = case_folder(build, preset), preset.upper()
    info = _ready(folder, case, force)
    if info:
        return info
    shutil.rmtree(folder, ignore_errors=True)
    os.makedirs(folder)
    started = time.monotonic()
    subprocess.run([exp.cutaway, "generate", "--preset", preset, "--deck", folder], check=True, stdout=subprocess.DEVNULL)
    generate_s = time.monotonic() - started
    flow_s = _flow(folder, case + ".DATA")
    return _finish(folder, case, {"name": preset, "source": f"cutaway generate --preset {preset} --deck DIR; flow",
                                  "generate_s": generate_s, "flow_s": flow_s})


def spe9_case(build, force):
    """SPE9 from shared/data with RPTRST at every report step, run by flow."""
    folder, case = case_folder(build, "spe9"), "SPE9"
    info = _ready(folder, case, force)
    if info:
        return info
    shutil.rmtree(folder, ignore_errors=True)
    os.makedirs(folder)
    for name in os.listdir(SPE9_DIR):
        if name.endswith(".DATA"):
            with open(os.path.join(SPE9_DIR, name)) as f:
                text = f.read()
            if name == "SPE9.DATA":
                if SPE9_RPTRST[0] not in text:
                    raise SystemExit(f"{SPE9_DIR}/SPE9.DATA: expected the record RPTRST {SPE9_RPTRST[0]} to replace")
                text = text.replace(*SPE9_RPTRST)
            with open(os.path.join(folder, name), "w") as f:
                f.write(text)
    flow_s = _flow(folder, "SPE9.DATA")
    return _finish(folder, case, {"name": "spe9", "source": "shared/data/opm/spe9/SPE9.DATA, RPTRST 'BASIC=2'; flow",
                                  "flow_s": flow_s})


def report_steps(exp, egrid):
    """`cutaway inspect CASE --json`'s report steps (index, report, date, days)."""
    out = subprocess.run([exp.cutaway, "inspect", egrid, "--json"], check=True, capture_output=True, text=True).stdout
    return json.loads(out)["report_steps"]
