"""The volumes the figures cut with, placed from the model's bounds (`cutaway inspect --json`), and
the closed OBJ mesh the mesh panel reads.

Coordinates are the model's: x east, y north, z as the grid's depths (the bounds say which end is
the top: wells stand above the smaller z when depths grow downwards, the generated models' case).
"""
import math
import os


def lerp(bounds, fx, fy, fz):
    """The point at fractions (fx, fy, fz) of the bounds along x, y, z."""
    lo, hi = bounds["min"], bounds["max"]
    return [lo[a] + f * (hi[a] - lo[a]) for a, f in enumerate((fx, fy, fz))]


def numbers(values):
    """A spec's comma-separated numbers: 5 significant digits, a metre on the presets' kilometres,
    so the captions that quote the specs stay readable."""
    return ",".join(f"{v:.5g}" for v in values)


def horizontal_extent(bounds):
    lo, hi = bounds["min"], bounds["max"]
    return max(hi[0] - lo[0], hi[1] - lo[1])


def box_spec(bounds):
    """A shaft through the middle of the model: the middle third in plan, from above the top down
    to 60% of the depth (above the top so the cut opens from the surface)."""
    return "box:" + numbers(lerp(bounds, 0.33, 0.33, -0.1) + lerp(bounds, 0.67, 0.67, 0.6))


def cylinder_spec(bounds):
    """A slanted drill core: from above the model's top near one corner to 70% of its depth in
    the middle, radius 8% of the horizontal extent."""
    return "cylinder:" + numbers(lerp(bounds, 0.2, 0.25, -0.2) + lerp(bounds, 0.55, 0.55, 0.7) +
                                 [0.08 * horizontal_extent(bounds)])


def well_spec(name, bounds, fraction=0.06):
    """`well:NAME,R` with R `fraction` of the horizontal extent (a few cells across)."""
    return f"well:{name},{fraction * horizontal_extent(bounds):.5g}"


def icosahedron(centre, radii):
    """Vertices and 1-based faces (outward, counter-clockwise) of an icosahedron scaled by `radii`
    per axis around `centre`: the smallest closed mesh that looks like a blob, not a box."""
    p = (1 + math.sqrt(5)) / 2
    unit = [(-1, p, 0), (1, p, 0), (-1, -p, 0), (1, -p, 0), (0, -1, p), (0, 1, p), (0, -1, -p), (0, 1, -p),
            (p, 0, -1), (p, 0, 1), (-p, 0, -1), (-p, 0, 1)]
    norm = math.sqrt(1 + p * p)
    vertices = [[centre[a] + radii[a] * v[a] / norm for a in range(3)] for v in unit]
    faces = [(1, 12, 6), (1, 6, 2), (1, 2, 8), (1, 8, 11), (1, 11, 12), (2, 6, 10), (6, 12, 5), (12, 11, 3), (11, 8, 7),
             (8, 2, 9), (4, 10, 5), (4, 5, 3), (4, 3, 7), (4, 7, 9), (4, 9, 10), (5, 10, 6), (3, 5, 12), (7, 3, 11),
             (9, 7, 8), (10, 9, 2)]
    return vertices, faces


def write_mesh_obj(bounds, folder):
    """An icosahedron in the middle of the model, wider than deep as the reservoir is, reaching
    above the top (so that the cut opens the surface) but not through the bottom, written as
    FOLDER/blob.obj; returns the `mesh:FILE` spec."""
    lo, hi = bounds["min"], bounds["max"]
    radii = [0.3 * (hi[0] - lo[0]), 0.3 * (hi[1] - lo[1]), 0.45 * (hi[2] - lo[2])]
    vertices, faces = icosahedron(lerp(bounds, 0.5, 0.5, 0.3), radii)
    path = os.path.join(folder, "blob.obj")
    with open(path, "w") as f:
        f.write("# icosahedron: a closed cut volume for the mesh panel\n")
        f.writelines(f"v {numbers(v).replace(',', ' ')}\n" for v in vertices)
        f.writelines(f"f {a} {b} {c}\n" for a, b, c in faces)
    return "mesh:" + path
