"""Paper figures from rendered panels: a grid of panels at their native pixel size (so a 1280 px
render stays 1280 px wide in the figure), captions above each panel that never overlap, and an
optional zoom row: the same window of every panel, enlarged, where the figure's point is small.

The zoom window is found from the panels themselves: the window of a third of the panel's size
holding most pixels that differ between the panels (the figure's point is what differs).
"""
import math
import os
import textwrap

import numpy as np

import cutaway_experiment as cx

DPI = 100
CAPTION_PT = 16       # the smallest caption: 22 px at 100 dpi, about 3% of a 720 px panel
ZOOM = 3              # the zoom window is 1/ZOOM of the panel in each direction
MAX_COLUMNS = 2       # wider figures print too small at a journal's page width (no 5000 px strips)
GAP_IN = 0.15         # between panels, inches
# Print size (issue 46): every text at least 7 pt when the figure is printed 182 mm wide (a
# journal's double column), i.e. at least 7 pt x 25.4 / 72 mm = 2.47 mm of the 182.
PRINT_WIDTH_MM = 182
MIN_TEXT_PT = 7


def min_text_px(figure_width_px):
    """Smallest text height, pixels, that prints at MIN_TEXT_PT when the figure is PRINT_WIDTH_MM wide."""
    return math.ceil(MIN_TEXT_PT * 25.4 / 72 / PRINT_WIDTH_MM * figure_width_px)


def figure_width_px(columns, panel_width_px):
    """Width of a composed figure of `columns` panels `panel_width_px` wide (gaps included)."""
    return round(columns * panel_width_px + (columns + 1) * GAP_IN * DPI)


def columns_for(rows):
    """Columns of the composed figure: the widest row, at most MAX_COLUMNS (longer rows wrap)."""
    return min(MAX_COLUMNS, max(len(row) for row in rows))


def reflow(row, columns):
    """`row` cut into rows of at most `columns` panels."""
    return [row[i:i + columns] for i in range(0, len(row), columns)]


def wrap(caption, width_px, font_px):
    """Each line of `caption` wrapped to fit `width_px` at `font_px` (a character is about 0.55 em),
    in as few lines as the full width needs, of about equal length (no word left alone on the last)."""
    chars = max(12, int(width_px / (0.55 * font_px)))

    def balanced(line):
        lines = textwrap.wrap(line, chars) or [line]
        for width in range(-(-len(line) // len(lines)), chars):
            if len(candidate := textwrap.wrap(line, width)) <= len(lines):
                return candidate
        return lines

    return "\n".join("\n".join(balanced(line)) for line in caption.splitlines())


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


def difference_image(image, reference, colour_bar_box=None):
    """`image` faded to grey, with the pixels where it differs from `reference` (the threshold
    zoom_window uses) in red, the colour bar's box x0, y0, x1, y1 blanked; and the share of the
    model's pixels (non-white in either, outside that box) that differ."""
    differs = np.abs(image - reference).max(axis=2) > 24 / 255
    model = (image.min(axis=2) < 250 / 255) | (reference.min(axis=2) < 250 / 255)
    if colour_bar_box:
        x0, y0, x1, y1 = (int(round(v)) for v in colour_bar_box)
        model[y0:y1 + 1, x0:x1 + 1] = False
    grey = 0.35 + 0.65 * image.mean(axis=2, keepdims=True) * np.ones((1, 1, 3))
    grey[differs] = (0.85, 0.0, 0.0)
    if colour_bar_box:  # a greyed colour bar decodes nothing: left out of the difference map
        grey[y0:y1 + 1, x0:x1 + 1] = 1.0
    return grey, float((differs & model).sum() / max(model.sum(), 1))


def compose(rows, title, path, zoom=False, after=()):
    """rows: lists of (caption, image path); every image the same size. Rows longer than
    MAX_COLUMNS wrap. With `zoom`, every panel again inside the window zoom_window finds (outlined
    on the panels), after the panels; `after`: rows of (caption, RGB float image) last (neither
    zoomed nor outlined). Text is sized for print (min_text_px of the figure's width).
    Writes `path` (PNG); returns the layout: panel_size, panel_boxes (top-left pixel of each panel,
    in the order given, zoom panels last), width_px and text_px (the smallest text's height)."""
    plt = cx.pyplot()
    from matplotlib.patches import Rectangle
    panels = [(caption, load(image)) for row in rows for caption, image in row]
    h, w = panels[0][1].shape[:2]
    columns = columns_for(rows)
    grid = [reflowed for row in rows for reflowed in reflow([(c, load(i)) for c, i in row], columns)]
    window = zoom_window([image for _, image in panels]) if zoom else None
    if window:
        x0, y0, ww, wh = window
        grid += reflow([(f"{caption.splitlines()[0]} (zoom x{ZOOM})", image[y0:y0 + wh, x0:x0 + ww])
                        for caption, image in panels], columns)
    for row in after:
        grid += reflow(list(row), columns)
    width_px = figure_width_px(columns, w)
    font_px = max(CAPTION_PT * DPI / 72, min_text_px(width_px))
    caption_pt, title_pt = font_px * 72 / DPI, font_px * 72 / DPI * 1.25
    grid = [[(wrap(caption, w, font_px), image) for caption, image in row] for row in grid]
    caption_lines = max(caption.count("\n") + 1 for row in grid for caption, _ in row)
    caption_h = caption_lines * caption_pt * 1.35 / 72 + 0.1
    title = wrap(title, width_px, font_px * 1.25)
    title_h = (title.count("\n") + 1) * title_pt * 1.6 / 72 + 0.1
    panel_w, panel_h = w / DPI, h / DPI
    fig_w = width_px / DPI
    fig_h = title_h + len(grid) * (caption_h + panel_h + GAP_IN)
    fig = plt.figure(figsize=(fig_w, fig_h), dpi=DPI)
    fig.text(0.5, 1 - 0.5 * title_h / fig_h, title, ha="center", va="center", fontsize=title_pt)
    boxes = []
    for r, row in enumerate(grid):
        top = fig_h - title_h - r * (caption_h + panel_h + GAP_IN)
        for c, (caption, image) in enumerate(row):
            left = GAP_IN + c * (panel_w + GAP_IN)
            ax = fig.add_axes([left / fig_w, (top - caption_h - panel_h) / fig_h, panel_w / fig_w, panel_h / fig_h])
            ax.imshow(image, interpolation="nearest", aspect="auto")
            boxes.append([round(left * DPI), round((fig_h - top + caption_h) * DPI)])
            ax.set_axis_off()
            fig.text((left + 0.5 * panel_w) / fig_w, (top - 0.5 * caption_h) / fig_h, caption, ha="center", va="center",
                     fontsize=caption_pt)
            if window and len(boxes) <= len(panels):
                ax.add_patch(Rectangle((window[0], window[1]), window[2], window[3], fill=False, edgecolor="black",
                                       linewidth=3, linestyle="--"))
    fig.savefig(path, dpi=DPI)  # raster panels: a PDF would only wrap the same pixels
    plt.close(fig)
    print("wrote", os.path.relpath(path, cx.REPO))
    return {"zoom_window": list(window) if window else None, "panel_size": [w, h], "panel_boxes": boxes,
            "width_px": width_px, "text_px": round(font_px, 1)}
