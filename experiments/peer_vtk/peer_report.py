"""The peer_vtk report from the result document run.py computes; no measuring here."""
import report_markdown as md



def _ms(summary):
    """'median (min-max)' of a spread over rounds, ms."""
    if len(summary["rounds"]) == 1:
        return f"{summary['median']:.0f}"
    return f"{summary['median']:.0f} ({summary['min']:.0f}-{summary['max']:.0f})"


def _count(value):
    """A face count as stats.json gives it: an int, a per-stage object, or absent ('n/a')."""
    if value is None:
        return "n/a"
    if isinstance(value, (int, float)):
        return f"{int(value):,}"
    if isinstance(value, dict):  # per stage; nested objects (culling details) stay in the JSON
        return ", ".join(f"{k} {_count(v)}" for k, v in value.items() if isinstance(v, (int, float)))
    return str(value)


def _ratio(ratios, name):
    """The ratio of the medians, and the range of the rounds' own ratios where there are several."""
    rounds = ratios.get(name + "_rounds", [])
    if len(rounds) <= 1:
        return f"{ratios[name]:.2f}"
    return f"{ratios[name]:.2f} ({min(rounds):.2f}-{max(rounds):.2f})"


def report(document):
    """The report: per model and our configuration, VTK's and our frame times and faces, the
    ratios, and the checks that make them comparable."""
    context, proto = document["context"], document["protocol"]
    width, height = proto["size"]
    sapphire = next((m for m in document["models"] if m["model"].startswith("preset:sapphire")), document["models"][-1])
    default = next(iter(sapphire["ratios"]))
    result = md.Report(
        f"Peer comparison with VTK {context['vtk_version']}: the same grids, camera and size",
        f"Our plain and cutaway frames against VTK {context['vtk_version']} on the same GRDECL grids, camera (azimuth "
        f"{proto['camera_pose_deg'][0]:g}, elevation {proto['camera_pose_deg'][1]:g}, framed) and size ({width}x{height}). "
        f"Ours: {context['gl_renderer_ours']} (EGL). VTK: {context['gl_renderer_vtk']} ({context['vtk_window_class']}, "
        f"offscreen under Xvfb), LP_NUM_THREADS={context.get('lp_num_threads_vtk')}. No multisampling on either side. "
        f"Milliseconds per frame: median over {proto['rounds']} interleaved round(s) (min-max), each round the median "
        f"of {proto['vtk_repeat']} (VTK) / {proto['ours_repeat']} (ours) timed frames after warm-up.",
        headline=f"{sapphire['model'].split()[0]} cutaway / VTK clip {sapphire['ratios'][default]['cutaway_over_vtk_clip']:.2f}x ({default})")
    result.section("Frame times and faces",
                   "VTK surface = surface filter + cell edges (drawn polygons as faces); VTK clip = clip by the plane "
                   "through the centre facing the camera + surface filter, re-executed every frame. Ours plain = "
                   "`baseline_ms`, ours cutaway = `stages_ms.total` (1% primaries, 9x9 mean filter, SSAO, ray-cast "
                   "borders). Faces: ours as stats.json reports them (`baseline_faces_drawn`; `faces_drawn` per stage), "
                   "n/a where it does not. Ours: `visible` = the default renderer (GPU-culled faces, the default cut "
                   "strategy `auto`: one frustum per IJK box of adjacent primaries, or their union swept in O(pixels) from "
                   "the device's threshold on; column `cut` names the one drawn); `per-cell frustum` = the paper's one "
                   "frustum per primary; `all-faces` = every face of every cell (the paper's path). Ratios: of the "
                   "medians, and in brackets the range of the rounds' own ratios (each round's VTK and our frames ran "
                   "minutes apart).")
    rows = []
    for model in document["models"]:
        vtk = model["vtk"]
        for draw, ours in model["ours"].items():
            ratio = model["ratios"][draw]
            rows.append([model["model"].split()[0], f"{model['active_cells']:,}", draw, ours.get("cut_strategy", "n/a"),
                         _ms(vtk["surface"]), _count(vtk["surface"]["faces_drawn"]), _ms(vtk["clip"]),
                         _count(vtk["clip"]["faces_drawn"]), _ms(ours["plain_ms"]), _count(ours["plain_faces_drawn"]),
                         _ms(ours["cutaway_ms"]), _count(ours["cutaway_faces_drawn"]),
                         _ratio(ratio, "plain_over_vtk_surface"), _ratio(ratio, "cutaway_over_vtk_clip")])
    result.table(["model", "active cells", "ours", "cut", "VTK surface ms", "VTK faces", "VTK clip ms", "VTK clip faces",
                  "ours plain ms", "ours plain faces", "ours cutaway ms", "ours cutaway faces", "plain / VTK surface",
                  "cutaway / VTK clip"], rows, align="lrll" + "r" * 7 + "lrr")
    result.section("Checks", "The VTK grid has the same active cells as `cutaway inspect`; total volumes (relative "
                   "difference to inspect): " + "; ".join(
                       f"{m['model'].split()[0]} " + ", ".join(f"{name} {v['relative_difference']:.1e}"
                                                               for name, v in m["checks"]["volumes"].items())
                       for m in document["models"]) + ". Camera: model pixel boxes of the two sides differ by at most " +
                   ", ".join(f"{m['camera_check']['max_offset_px']} px ({m['model'].split()[0]})" for m in document["models"]) +
                   " (the camera-check images below).")
    return result
