#!/usr/bin/python3
"""VTK side of the peer comparison; run by run.py with /usr/bin/python3 (Debian's python3-vtk9).

  vtk_worker.py prepare GRID.grdecl --camera AZ EL DIST --size W H --vtu OUT.vtu --json OUT.json
      reads the GRDECL file (grdecl_vtk), writes the active cells as a vtkUnstructuredGrid of
      hexahedra in render space (OUT.vtu) and OUT.json: active cell count, total volume three ways
      (exact trilinear in numpy; VTK's vtkMeshQuality hex volume and vtkCellSizeFilter), the render
      frame and the orbit camera of the pose (DIST 0: framed as `cutaway render` frames it).
  xvfb-run -a -s "-screen 0 WxHx24" vtk_worker.py render PREPARED.json --modes surface clip
      --warmup N --repeat N --json OUT.json [--image-dir DIR]
      times each mode in an offscreen W x H window without multisampling (GLX on Mesa llvmpipe
      under Xvfb):
        surface: vtkDataSetSurfaceFilter -> mapper coloured by PORO -> actor with cell edges; the
                 pipeline executes once, frames redraw the same polygons;
        clip:    vtkTableBasedClipDataSet by the plane through the model centre facing the camera
                 (the half towards the camera removed) -> surface filter -> the same mapper; the
                 plane is marked Modified() before each frame, so every frame re-executes clip and
                 surface filter and its time includes them.
      A frame's time is the wall clock around renWin.Render() + renWin.WaitForCompletion()
      (glFinish), milliseconds.
"""
import argparse
import json
import os
import statistics
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import grdecl_vtk  # noqa: E402
import orbit_camera  # noqa: E402

import vtk  # noqa: E402  (python3-vtk9)
from vtkmodules.util import numpy_support  # noqa: E402


def prepare(args):
    """GRDECL -> render-space .vtu + the model's checks and camera (JSON)."""
    started = time.perf_counter()
    model = grdecl_vtk.CornerPointGrid(args.grdecl)
    corners, corner_ids = model.active_corners()
    read_s = time.perf_counter() - started
    frame = orbit_camera.RenderFrame(corners, model.depth_direction())
    grid = grdecl_vtk.unstructured_grid(frame.to_render(corners), corner_ids, model.active_poro())
    # Volumes in model units cubed: undo the vertical exaggeration of the render-space cells.
    unscale = 1.0 / frame.z_scale
    writer = vtk.vtkXMLUnstructuredGridWriter()
    writer.SetFileName(args.vtu)
    writer.SetInputData(grid)
    writer.SetDataModeToBinary()
    writer.Write()
    poro = model.active_poro()
    result = {
        "grdecl": args.grdecl, "vtu": args.vtu, "dims": list(model.dims), "active_cells": model.active_count,
        "vtk_cells": grid.GetNumberOfCells(), "vtk_points": grid.GetNumberOfPoints(),
        "volume_model_units3": {"trilinear_numpy": float(abs(grdecl_vtk.signed_volumes(corners)).sum()),
                                "vtk_mesh_quality_hex_volume": mesh_quality_volume(grid) * unscale,
                                "vtk_cell_size_filter": grdecl_vtk.vtk_total_volume(grid) * unscale},
        "poro_range": None if poro is None else [float(poro.min()), float(poro.max())],
        "frame": frame.describe(),
        "camera": orbit_camera.orbit_camera(frame, *args.camera, *args.size),
        "read_s": read_s, "prepare_s": time.perf_counter() - started, "vtk_version": vtk.vtkVersion.GetVTKVersion()}
    with open(args.json, "w") as f:
        json.dump(result, f, indent=1)


def mesh_quality_volume(grid):
    """Sum of vtkMeshQuality's hexahedron volumes (the grid's units cubed)."""
    quality = vtk.vtkMeshQuality()
    quality.SetInputData(grid)
    quality.SetHexQualityMeasureToVolume()
    quality.Update()
    values = numpy_support.vtk_to_numpy(quality.GetOutput().GetCellData().GetArray("Quality"))
    return float(values.astype("float64").sum())


def read_grid(path):
    reader = vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(path)
    reader.Update()
    return reader.GetOutput()


def apply_camera(renderer, camera):
    """Sets VTK's camera to the orbit camera (prepared JSON): eye, focal point, view up, vertical
    view angle and the near/far planes."""
    vtk_camera = renderer.GetActiveCamera()
    vtk_camera.SetPosition(*camera["eye"])
    vtk_camera.SetFocalPoint(*camera["focal_point"])
    vtk_camera.SetViewUp(*camera["view_up"])
    vtk_camera.SetViewAngle(camera["fovy_deg"])
    vtk_camera.SetClippingRange(camera["near"], camera["far"])


def surface_pipeline(grid, prepared, mode):
    """(actor, filters, plane or None) of a mode: surface, or clip (plane through the centre,
    normal pointing away from the eye, so the far half is kept). `filters` ends with the surface
    filter, whose output is what the mapper draws."""
    filters, plane = [], None
    if mode == "clip":
        plane = vtk.vtkPlane()
        plane.SetOrigin(0.0, 0.0, 0.0)
        plane.SetNormal(*[-d for d in prepared["camera"]["direction"]])
        clip = vtk.vtkTableBasedClipDataSet()
        clip.SetClipFunction(plane)
        filters.append(clip)
    filters.append(vtk.vtkDataSetSurfaceFilter())
    filters[0].SetInputData(grid)
    for upstream, downstream in zip(filters, filters[1:]):
        downstream.SetInputConnection(upstream.GetOutputPort())
    mapper = vtk.vtkPolyDataMapper()
    mapper.SetInputConnection(filters[-1].GetOutputPort())
    mapper.SetScalarModeToUseCellData()
    if prepared["poro_range"]:
        mapper.SetScalarRange(*prepared["poro_range"])
    actor = vtk.vtkActor()
    actor.SetMapper(mapper)
    actor.GetProperty().EdgeVisibilityOn()
    actor.GetProperty().SetEdgeColor(0.1, 0.1, 0.1)
    return actor, filters, plane


class FilterClock:
    """Counts the executions of `filters` and their wall time (ms), from Start/EndEvent observers."""

    def __init__(self, filters):
        self.executions, self.ms, self._began = 0, 0.0, {}
        for f in filters:
            f.AddObserver("StartEvent", lambda caller, _event: self._began.__setitem__(id(caller), time.perf_counter()))
            f.AddObserver("EndEvent", self._end)

    def _end(self, caller, _event):
        self.executions += 1
        self.ms += 1e3 * (time.perf_counter() - self._began.pop(id(caller)))

    def take(self):
        """(executions, ms) since the last take."""
        taken = (self.executions, self.ms)
        self.executions, self.ms = 0, 0.0
        return taken


def time_mode(grid, prepared, mode, warmup, repeat, image):
    """Renders `warmup` then `repeat` frames of one mode; returns its frame times (ms), the filter
    executions and filter time (ms) inside each timed frame, and the polygons drawn."""
    width, height = prepared["camera"]["size"]
    actor, filters, plane = surface_pipeline(grid, prepared, mode)
    clock = FilterClock(filters)
    renderer = vtk.vtkRenderer()
    renderer.SetBackground(1.0, 1.0, 1.0)
    renderer.AddActor(actor)
    window = vtk.vtkRenderWindow()
    window.SetOffScreenRendering(1)
    # No multisampling, as ours: VTK's default window asks for 4 samples, which made its frame
    # 4-5x slower on llvmpipe (petra 1080p surface + edges: about 370 ms against 70-100 ms).
    window.SetMultiSamples(0)
    window.SetSize(width, height)
    window.AddRenderer(renderer)
    apply_camera(renderer, prepared["camera"])
    times, executions, filter_ms = [], [], []
    for frame in range(warmup + repeat):
        if plane is not None:
            plane.Modified()
        clock.take()
        began = time.perf_counter()
        window.Render()
        window.WaitForCompletion()
        elapsed_ms = 1e3 * (time.perf_counter() - began)
        if frame >= warmup:
            times.append(elapsed_ms)
            count, ms = clock.take()
            executions.append(count)
            filter_ms.append(ms)
    result = {"mode": mode, "frame_ms": times, "median_ms": statistics.median(times),
              "filter_executions_per_frame": executions, "filter_ms": filter_ms,
              "filter_median_ms": statistics.median(filter_ms),
              "faces_drawn": filters[-1].GetOutput().GetNumberOfCells(),
              "gl_renderer": gl_renderer(window), "window_class": window.GetClassName(),
              "size": list(window.GetSize())}
    if image:
        save_png(window, image)
        result["image"] = image
    window.Finalize()
    return result


def gl_renderer(window):
    """The 'OpenGL renderer string' line of ReportCapabilities (None if VTK does not say)."""
    for line in window.ReportCapabilities().splitlines():
        if "renderer string" in line.lower():
            return line.split(":", 1)[1].strip()
    return None


def save_png(window, path):
    grab = vtk.vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.ReadFrontBufferOff()
    grab.Update()
    writer = vtk.vtkPNGWriter()
    writer.SetFileName(path)
    writer.SetInputConnection(grab.GetOutputPort())
    writer.Write()


def render(args):
    with open(args.prepared) as f:
        prepared = json.load(f)
    grid = read_grid(prepared["vtu"])
    results = []
    for mode in args.modes:
        image = os.path.join(args.image_dir, f"vtk_{mode}.png") if args.image_dir else None
        results.append(time_mode(grid, prepared, mode, args.warmup, args.repeat, image))
    with open(args.json, "w") as f:
        json.dump({"modes": results, "vtk_version": vtk.vtkVersion.GetVTKVersion(),
                   "lp_num_threads": os.environ.get("LP_NUM_THREADS", "unset"),
                   "display": os.environ.get("DISPLAY")}, f, indent=1)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    commands = parser.add_subparsers(dest="command", required=True)
    p = commands.add_parser("prepare")
    p.add_argument("grdecl")
    p.add_argument("--camera", type=float, nargs=3, default=(35.0, 30.0, 0.0), metavar=("AZ", "EL", "DIST"))
    p.add_argument("--size", type=int, nargs=2, required=True, metavar=("W", "H"))
    p.add_argument("--vtu", required=True)
    p.add_argument("--json", required=True)
    r = commands.add_parser("render")
    r.add_argument("prepared")
    r.add_argument("--modes", nargs="+", choices=("surface", "clip"), default=("surface", "clip"))
    r.add_argument("--warmup", type=int, default=2)
    r.add_argument("--repeat", type=int, default=5)
    r.add_argument("--json", required=True)
    r.add_argument("--image-dir")
    args = parser.parse_args()
    prepare(args) if args.command == "prepare" else render(args)


if __name__ == "__main__":
    main()
