#!/usr/bin/env python3
"""Renders of the real F3 crop and the synthetic cube in the three transfer functions.

Interface (for experiments/run_all):
  experiments/volume_renders/run.py [--quick] [--force] [--build DIR]
Writes paper_figures/volume_render_{f3,synthetic}_{grey,pseudo,layer}.png (colour bar included)
and results/volume/renders.json (each render's stats and the machine context). Skips when all
exist unless --force. --quick: 256x256 pixels and a 40x40x80 synthetic cube instead of 640x640 and
"paper-250".
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "volume_common"))
import volume_experiment as vx  # noqa: E402

TRANSFER_FUNCTIONS = ("grey", "pseudo", "layer")


def main():
    json_path = os.path.join(vx.RESULTS, "renders.json")
    images = {(cube, tf): os.path.join(vx.FIGURES, f"volume_render_{cube}_{tf}.png")
              for cube in ("f3", "synthetic") for tf in TRANSFER_FUNCTIONS}
    args = vx.begin(__doc__, [json_path, *images.values()])
    if args is None:
        return
    size = "256" if args.quick else "640"
    renders, last_stats = [], None
    with vx.Workspace(args) as work:
        cubes = {"f3": os.path.join(vx.REPO, "..", "shared", "data", "segy", "f3.sgy"),
                 "synthetic": work.generate("synthetic", *(["--dims", "40", "40", "80"] if args.quick else ["--preset", "paper-250"]),
                                            "--seed", "1")}
        for (cube, tf), image in images.items():
            stats = work.volume(cubes[cube], "--tf", tf, "--size", size, size, "--camera", "40", "25", "0", image=image)
            stats["input"]["path"] = os.path.basename(stats["input"]["path"])
            renders.append({"cube": cube, "transfer_function": tf, "image": os.path.relpath(image, vx.REPO), "stats": stats})
            last_stats = stats
            print("wrote", os.path.relpath(image, vx.REPO))
    vx.write_json(json_path, {"experiment": "volume_renders", "quick": args.quick, "context": vx.machine_context(last_stats),
                              "renders": renders})


if __name__ == "__main__":
    main()
