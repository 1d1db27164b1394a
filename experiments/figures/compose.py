"""Paper figures from rendered panels: a grid of panels at their native pixel size (so a 1280 px
render stays 1280 px wide in the figure), captions above each panel that never overlap, and an
optional zoom row: the same window of every panel, enlarged, where the figure's point is small.

The zoom window is found from the panels themselves: the window of a third of the panel's size
holding most pixels that differ between the panels (the figure's point is what differs).
"""
import os

import numpy as np

import cutaway_experiment as cx

DPI = 100
CAPTION_PT = 16       # 22 px at 100 dpi: about 3% of a 720 px panel
TITLE_PT = 20
ZOOM = 3              # the zoom window is 1/ZOOM of the panel in each direction


def load(path):
    """RGB float image (rows top to bottom) of a PNG."""
    return cx.pyplot().imread(path)[..., :3]


def zoom_window(images):
    """(x0, y0, w, h) of the window 1/ZOOM of the panel's size with the most pixels that differ
    between the panels (any channel by more than 24/255); the centre when none differ."""
    h, w = images[0].shape[:2]
    wh, ww = h // ZOOM, w // ZOOM
    differs = np.zeros((h, w), dtype=np.float64)
    for a in range(len(images)):
        for b in range(a + 1, len(images)):
            differs += (np.abs(images[a] - images[b]).max(axis=2) > 24 / 255)
    if not differs.any():
        return (w - ww) // 2, (h - wh) // 2, ww, wh
    integral = np.pad(differs.cumsum(0).cumsum(1), ((1, 0), (1, 0)))
    sums = integral[wh:, ww:] - integral[:-wh, ww:] - integral[wh:, :-ww] + integral[:-wh, :-ww]
    y0, x0 = np.unravel_index(np.argmax(sums), sums.shape)
    return int(x0), int(y0), ww, wh


def compose(rows, title, path, zoom=False):
    """rows: lists of (caption, image path); every image the same size. Writes `path` (PNG). With `zoom`, a last row shows every panel of the first row inside
    the window zoom_window finds (outlined on the panels)."""
    plt = cx.pyplot()
    from matplotlib.patches import Rectangle
    images = [[load(image) for _, image in row] for row in rows]
    h, w = images[0][0].shape[:2]
    window = zoom_window(images[0]) if zoom else None
    grid = [list(zip([c for c, _ in row], imgs)) for row, imgs in zip(rows, images)]
    if window:
        x0, y0, ww, wh = window
        grid.append([(f"{caption} (zoom x{ZOOM})", img[y0:y0 + wh, x0:x0 + ww]) for caption, img in grid[0]])
    cols = max(len(row) for row in grid)
    gap = 0.15
    caption_lines = max(caption.count("\n") + 1 for row in grid for caption, _ in row)
    caption_h = caption_lines * CAPTION_PT * 1.35 / 72 + 0.1
    title_h = TITLE_PT * 1.6 / 72 + 0.1
    panel_w, panel_h = w / DPI, h / DPI
    fig_w = cols * panel_w + (cols + 1) * gap
    fig_h = title_h + len(grid) * (caption_h + panel_h + gap)
    fig = plt.figure(figsize=(fig_w, fig_h), dpi=DPI)
    fig.text(0.5, 1 - 0.5 * title_h / fig_h, title, ha="center", va="center", fontsize=TITLE_PT)
    boxes = []  # each panel's top-left pixel in the written PNG, rows in order (the zoom row last)
    for r, row in enumerate(grid):
        top = fig_h - title_h - r * (caption_h + panel_h + gap)
        for c, (caption, image) in enumerate(row):
            left = gap + c * (panel_w + gap)
            ax = fig.add_axes([left / fig_w, (top - caption_h - panel_h) / fig_h, panel_w / fig_w, panel_h / fig_h])
            ax.imshow(image, interpolation="nearest", aspect="auto")
            boxes.append([round(left * DPI), round((fig_h - top + caption_h) * DPI)])
            ax.set_axis_off()
            fig.text((left + 0.5 * panel_w) / fig_w, (top - 0.5 * caption_h) / fig_h, caption, ha="center", va="center",
                     fontsize=CAPTION_PT)
            if window and r == 0:
                ax.add_patch(Rectangle((window[0], window[1]), window[2], window[3], fill=False, edgecolor="black",
                                       linewidth=2, linestyle="--"))
    fig.savefig(path, dpi=DPI)  # raster panels: a PDF would only wrap the same pixels
    plt.close(fig)
    print("wrote", os.path.relpath(path, cx.REPO))
    return {"zoom_window": list(window) if window else None, "panel_size": [w, h], "panel_boxes": boxes}
