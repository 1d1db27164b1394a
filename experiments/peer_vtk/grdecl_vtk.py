"""A small GRDECL reader (numpy) and the VTK unstructured grid of a corner-point model's active cells.

Only what the peer comparison needs: SPECGRID or DIMENS, COORD, ZCORN, ACTNUM and PORO (other
keywords are skipped; INCLUDE is not followed). Values may use `N*value` repeats, `--` starts a
comment, `/` ends a keyword. Layouts (SPEC.md section 1):
  COORD  (NY+1)(NX+1) pillars, i fastest, each top xyz then bottom xyz, model units;
  ZCORN  2NX x 2NY x 2NZ corner depths, x fastest, then y, then z (per layer the top-face corners
         of all cells, then the bottom-face corners), model units;
  ACTNUM, PORO  NX*NY*NZ values, i fastest (Eclipse cell order).
Points are put in the renderer's render space (orbit_camera.RenderFrame): centred on the active
cells' box, depth flipped to up, vertical exaggeration applied, so VTK and `cutaway render` share
one camera.
"""
import re

import numpy as np

# Keywords that take no data (no `/` terminator follows them).
NO_DATA_KEYWORDS = {"RUNSPEC", "GRID", "EDIT", "PROPS", "REGIONS", "SOLUTION", "SUMMARY", "SCHEDULE", "END",
                    "ECHO", "NOECHO"}
WANTED = ("SPECGRID", "DIMENS", "COORD", "ZCORN", "ACTNUM", "PORO")


class GrdeclError(ValueError):
    pass


def _tokens(text):
    """Whitespace tokens of `text` with `--` comments removed and `/` split off as its own token."""
    text = re.sub(r"--[^\n]*", " ", text)
    return text.replace("/", " / ").split()


def _expand(values):
    """Numbers of one keyword's data tokens, `N*value` repeats expanded; float64 array."""
    if not any("*" in v for v in values):
        return np.array(values, dtype=np.float64)
    out = []
    for v in values:
        if "*" in v:
            count, _, value = v.partition("*")
            if not value:
                raise GrdeclError(f"'{v}': default values (N*) are not supported")
            out.extend([value] * int(count))
        else:
            out.append(v)
    return np.array(out, dtype=np.float64)


def read_keywords(path):
    """{keyword: float64 array} of the WANTED keywords of a GRDECL file."""
    with open(path) as f:
        tokens = _tokens(f.read())
    found, at = {}, 0
    while at < len(tokens):
        keyword = tokens[at].strip("'\"").upper()
        at += 1
        if keyword in NO_DATA_KEYWORDS:
            continue
        try:
            end = tokens.index("/", at)
        except ValueError:
            raise GrdeclError(f"{path}: keyword {keyword}: no '/' terminator") from None
        if keyword in WANTED:
            found[keyword] = _expand(tokens[at:end]) if keyword != "SPECGRID" else _expand(tokens[at:at + 3])
        at = end + 1
    return found


class CornerPointGrid:
    """The arrays of one GRDECL grid: `dims` (NX, NY, NZ); `coord` (NY+1, NX+1, 2, 3) pillar top and
    bottom points; `zcorn` (2NZ, 2NY, 2NX) corner depths; `actnum` (NX*NY*NZ,) bool; `poro`
    (NX*NY*NZ,) float or None. Model units throughout."""

    def __init__(self, path):
        kw = read_keywords(path)
        for required in ("COORD", "ZCORN"):
            if required not in kw:
                raise GrdeclError(f"{path}: keyword {required} missing")
        dims = kw.get("SPECGRID", kw.get("DIMENS"))
        if dims is None:
            raise GrdeclError(f"{path}: SPECGRID or DIMENS missing")
        nx, ny, nz = (int(d) for d in dims[:3])
        self.dims = (nx, ny, nz)
        cells = nx * ny * nz
        self.coord = self._sized(kw["COORD"], 6 * (nx + 1) * (ny + 1), "COORD", path).reshape(ny + 1, nx + 1, 2, 3)
        self.zcorn = self._sized(kw["ZCORN"], 8 * cells, "ZCORN", path).reshape(2 * nz, 2 * ny, 2 * nx)
        actnum = kw.get("ACTNUM")
        self.actnum = np.ones(cells, bool) if actnum is None else self._sized(actnum, cells, "ACTNUM", path) != 0
        poro = kw.get("PORO")
        self.poro = None if poro is None else self._sized(poro, cells, "PORO", path)

    @staticmethod
    def _sized(values, expected, keyword, path):
        if values.size != expected:
            raise GrdeclError(f"{path}: keyword {keyword}: expected {expected} values, found {values.size}")
        return values

    @property
    def active_count(self):
        return int(self.actnum.sum())

    def depth_direction(self):
        """+1 when depths grow with k (z down), -1 otherwise; decided as the C++ grid does, from
        corner 0 of cell (0,0,0) against corner 4 of cell (0,0,NZ-1)."""
        return 1 if self.zcorn[0, 0, 0] <= self.zcorn[-1, 0, 0] else -1

    def active_corners(self):
        """(A, 8, 3) corners of the active cells in Eclipse order, model units, and (A, 8) corner ids:
        equal ids for equal corners (same pillar, same ZCORN depth), so neighbours that share a face
        share its points and faults do not. Corner c: bit 0 = +i, bit 1 = +j, bit 2 = bottom face;
        each is the point on its pillar at its ZCORN depth (linear in z between the pillar's top and
        bottom; a horizontal pillar keeps its top x, y)."""
        nx, ny, nz = self.dims
        kk, jj, ii = np.unravel_index(np.flatnonzero(self.actnum), (nz, ny, nx))
        corners = np.empty((ii.size, 8, 3))
        pillars = np.empty((ii.size, 8), dtype=np.int64)
        for c in range(8):
            di, dj, dk = c & 1, (c >> 1) & 1, (c >> 2) & 1
            depth = self.zcorn[2 * kk + dk, 2 * jj + dj, 2 * ii + di]
            top, bottom = self.coord[jj + dj, ii + di, 0], self.coord[jj + dj, ii + di, 1]
            dz = bottom[:, 2] - top[:, 2]
            t = np.divide(depth - top[:, 2], dz, out=np.zeros_like(depth), where=dz != 0)
            corners[:, c, :2] = top[:, :2] + t[:, None] * (bottom[:, :2] - top[:, :2])
            corners[:, c, 2] = depth
            pillars[:, c] = (jj + dj) * (nx + 1) + ii + di
        keys = np.stack([pillars.ravel().astype(np.float64), corners[:, :, 2].ravel()], axis=1)
        _, ids = np.unique(keys, axis=0, return_inverse=True)
        return corners, ids.reshape(-1, 8)

    def active_poro(self):
        """PORO of the active cells (Eclipse order), or None."""
        return None if self.poro is None else self.poro[self.actnum]


def signed_volumes(corners):
    """Exact signed volumes (units cubed) of trilinear hexahedra, (A, 8, 3) Eclipse-ordered corners:
    2x2x2 Gauss quadrature of the Jacobian determinant d(x,y,z)/d(i,j,k), as the C++ signed_volume."""
    g = 0.5 / np.sqrt(3.0)
    nodes = (0.5 - g, 0.5 + g)
    rel = corners - corners[:, :1, :]
    volume = np.zeros(corners.shape[0])
    bits = np.array([[c & 1, (c >> 1) & 1, (c >> 2) & 1] for c in range(8)])
    sign = 2.0 * bits - 1.0
    for u in nodes:
        for v in nodes:
            for w in nodes:
                f = np.where(bits == 1, (u, v, w), (1 - u, 1 - v, 1 - w))  # (8, 3) shape factors per axis
                weights = np.stack([sign[:, 0] * f[:, 1] * f[:, 2], f[:, 0] * sign[:, 1] * f[:, 2],
                                    f[:, 0] * f[:, 1] * sign[:, 2]], axis=1)  # (8, 3): d/du, d/dv, d/dw
                jac = np.einsum("ca,nck->nak", weights, rel)  # (A, 3 derivatives, 3 coords)
                volume += np.linalg.det(jac) / 8.0
    return volume


# Eclipse corner order (bit 0 = +i, bit 1 = +j, bit 2 = bottom) to VTK_HEXAHEDRON order (one face's
# 4 points counter-clockwise, then the opposite face's in the same order): VTK's (r, s, t) = (i, j, k).
# A cell whose Jacobian d(x,y,z)/d(i,j,k) is negative (the render space flips depth to up) takes the
# faces the other way round, (r, s, t) = (i, j, -k), so that VTK sees positive volumes and outward faces.
ECLIPSE_TO_VTK_HEX = np.array((0, 1, 3, 2, 4, 5, 7, 6))
ECLIPSE_TO_VTK_HEX_FLIPPED = np.array((4, 5, 7, 6, 0, 1, 3, 2))


def unstructured_grid(corners_render, corner_ids, poro):
    """vtkUnstructuredGrid of hexahedra, one per active cell: `corners_render` (A, 8, 3) render-space
    corners in Eclipse order, `corner_ids` (A, 8) shared point ids (active_corners), `poro` (A,) or
    None (cell array "PORO"). Cells across a fault keep their own points, so vtkDataSetSurfaceFilter
    finds the faces a plain frame must draw: shell, fault and inactive-neighbour faces."""
    import vtk
    from vtkmodules.util import numpy_support

    count = corners_render.shape[0]
    points = np.empty((int(corner_ids.max()) + 1, 3), dtype=np.float32)
    points[corner_ids.ravel()] = corners_render.reshape(-1, 3)
    order = np.where((signed_volumes(corners_render) < 0)[:, None], ECLIPSE_TO_VTK_HEX_FLIPPED, ECLIPSE_TO_VTK_HEX)
    ordered_ids = np.take_along_axis(corner_ids, order, axis=1)
    vtk_points = vtk.vtkPoints()
    vtk_points.SetData(numpy_support.numpy_to_vtk(points, deep=True))
    connectivity = np.hstack([np.full((count, 1), 8), ordered_ids]).astype(np.int64)
    cells = vtk.vtkCellArray()
    cells.SetCells(count, numpy_support.numpy_to_vtkIdTypeArray(connectivity.ravel(), deep=True))
    grid = vtk.vtkUnstructuredGrid()
    grid.SetPoints(vtk_points)
    grid.SetCells(vtk.VTK_HEXAHEDRON, cells)
    if poro is not None:
        array = numpy_support.numpy_to_vtk(np.ascontiguousarray(poro, dtype=np.float32), deep=True)
        array.SetName("PORO")
        grid.GetCellData().SetScalars(array)
    return grid


def vtk_total_volume(grid):
    """Sum of the cells' volumes as VTK computes them (vtkCellSizeFilter), in the grid's units cubed."""
    import vtk
    from vtkmodules.util import numpy_support

    sizes = vtk.vtkCellSizeFilter()
    sizes.SetInputData(grid)
    sizes.ComputeVertexCountOff()
    sizes.ComputeLengthOff()
    sizes.ComputeAreaOff()
    sizes.ComputeVolumeOn()
    sizes.Update()
    return float(numpy_support.vtk_to_numpy(sizes.GetOutput().GetCellData().GetArray("Volume")).astype(np.float64).sum())
