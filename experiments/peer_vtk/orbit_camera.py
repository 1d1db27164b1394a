"""The renderer's render space and orbit camera, in numpy, so VTK frames what `cutaway render` frames.

Mirrors src/cutaway/model_frame.cpp (make_model_frame) and src/cutaway/camera.cpp
(make_orbit_camera) in double precision (the C++ side rounds render-space values to float).
Render space: X east, Y north, Z up, model units with Z scaled by `z_scale`, origin at the centre
of the active cells' bounding box. Angles in degrees; azimuth around +Z with 0 = looking along +Y
(camera south of the model), elevation above the horizontal.
"""
import math

import numpy as np

FOVY_DEG = 30.0  # pipeline::default_fovy_deg: vertical field of view of every frame


class RenderFrame:
    """Model units to render space. `corners`: (A, 8, 3) active-cell corners, model units;
    `depth_direction`: +1 when z is depth (grows with k); `z_scale` <= 0 picks the renderer's
    automatic exaggeration (the smallest >= 1 making the thickness 1/5 of the larger lateral extent)."""

    def __init__(self, corners, depth_direction, z_scale=0.0):
        points = corners.reshape(-1, 3)
        low, high = points.min(axis=0), points.max(axis=0)
        self.centre = 0.5 * (low + high)
        self.up_sign = -float(depth_direction)
        if z_scale <= 0:
            lateral = max(high[0] - low[0], high[1] - low[1])
            thickness = high[2] - low[2]
            z_scale = max(1.0, 0.2 * lateral / thickness) if thickness > 0 else 1.0
        self.z_scale = float(z_scale)
        a, b = self.to_render(low), self.to_render(high)
        self.render_min, self.render_max = np.minimum(a, b), np.maximum(a, b)

    def to_render(self, points):
        """Render-space copy of `points` (..., 3), model units."""
        out = np.array(points, dtype=np.float64) - self.centre
        out[..., 2] *= self.up_sign * self.z_scale
        return out

    def radius(self):
        """Half the diagonal of the render-space box (render units)."""
        return 0.5 * float(np.linalg.norm(self.render_max - self.render_min))

    def describe(self):
        return {"centre_model_units": self.centre.tolist(), "z_scale": self.z_scale, "up_sign": self.up_sign,
                "render_min": self.render_min.tolist(), "render_max": self.render_max.tolist(),
                "radius": self.radius()}


def view_direction(azimuth_deg, elevation_deg):
    """Unit vector from the orbit centre towards the eye."""
    az = math.radians(azimuth_deg)
    el = math.radians(min(max(elevation_deg, -89.0), 89.0))
    return np.array([math.sin(az) * math.cos(el), -math.cos(az) * math.cos(el), math.sin(el)])


def framing_distance(frame, direction, aspect, fovy_deg=FOVY_DEG):
    """Smallest eye distance (render units) along `direction` from the centre at which the 8 corners
    of the render-space box are in view, plus 5% (what `--camera AZ EL 0` uses)."""
    forward = -direction
    right = np.cross(forward, (0.0, 0.0, 1.0))
    right /= np.linalg.norm(right)
    up = np.cross(right, forward)
    tan_y = math.tan(0.5 * math.radians(fovy_deg))
    tan_x = tan_y * aspect
    distance = 0.0
    for c in range(8):
        corner = np.where([c & 1, c & 2, c & 4], frame.render_max, frame.render_min)
        along = float(corner @ forward)
        distance = max(distance, abs(float(corner @ right)) / tan_x - along, abs(float(corner @ up)) / tan_y - along)
    return 1.05 * max(distance, 1e-3 * frame.radius())


def orbit_camera(frame, azimuth_deg, elevation_deg, distance, width, height):
    """The camera of an orbit pose around the centre for a `width` x `height` image: eye (render
    units), focal point (origin), view up +Z, vertical fov (degrees), near/far planes hugging the
    bounding sphere. `distance` 0 frames the whole model."""
    direction = view_direction(azimuth_deg, elevation_deg)
    if distance <= 0:
        distance = framing_distance(frame, direction, width / height)
    radius = max(frame.radius(), 1e-6)
    near = max(distance - 1.5 * radius, 1e-3 * distance)
    return {"azimuth_deg": azimuth_deg, "elevation_deg": elevation_deg, "distance": distance,
            "eye": (distance * direction).tolist(), "focal_point": [0.0, 0.0, 0.0], "view_up": [0.0, 0.0, 1.0],
            "direction": direction.tolist(), "fovy_deg": FOVY_DEG, "near": near, "far": distance + 1.5 * radius,
            "size": [width, height]}
