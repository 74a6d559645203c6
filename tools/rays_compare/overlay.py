# SPDX-License-Identifier: Apache-2.0
"""Side-by-side overlay video for a person to look at, pure Python: one tile per tracker, each the
sequence's frame (enlarged) with that tracker's contour or box drawn in its colour, the ground-truth box
(where there is one) in grey, and a label; the first tile shows the ground truth alone. Written as a
YUV4MPEG2 4:2:0 file (C420jpeg), which ffplay, mpv and VLC play.
"""
from . import y4m

# 3x5 glyphs, rows top to bottom, "#" = ink
_FONT = {
    "A": ("###", "#.#", "###", "#.#", "#.#"), "B": ("##.", "#.#", "##.", "#.#", "##."),
    "C": ("###", "#..", "#..", "#..", "###"), "D": ("##.", "#.#", "#.#", "#.#", "##."),
    "E": ("###", "#..", "##.", "#..", "###"), "F": ("###", "#..", "##.", "#..", "#.."),
    "G": ("###", "#..", "#.#", "#.#", "###"), "H": ("#.#", "#.#", "###", "#.#", "#.#"),
    "I": ("###", ".#.", ".#.", ".#.", "###"), "J": ("..#", "..#", "..#", "#.#", "###"),
    "K": ("#.#", "#.#", "##.", "#.#", "#.#"), "L": ("#..", "#..", "#..", "#..", "###"),
    "M": ("#.#", "###", "###", "#.#", "#.#"), "N": ("##.", "#.#", "#.#", "#.#", "#.#"),
    "O": ("###", "#.#", "#.#", "#.#", "###"), "P": ("###", "#.#", "###", "#..", "#.."),
    "Q": ("###", "#.#", "#.#", "###", "..#"), "R": ("##.", "#.#", "##.", "#.#", "#.#"),
    "S": ("###", "#..", "###", "..#", "###"), "T": ("###", ".#.", ".#.", ".#.", ".#."),
    "U": ("#.#", "#.#", "#.#", "#.#", "###"), "V": ("#.#", "#.#", "#.#", "#.#", ".#."),
    "W": ("#.#", "#.#", "###", "###", "#.#"), "X": ("#.#", "#.#", ".#.", "#.#", "#.#"),
    "Y": ("#.#", "#.#", ".#.", ".#.", ".#."), "Z": ("###", "..#", ".#.", "#..", "###"),
    "0": ("###", "#.#", "#.#", "#.#", "###"), "1": (".#.", "##.", ".#.", ".#.", "###"),
    "2": ("###", "..#", "###", "#..", "###"), "3": ("###", "..#", ".##", "..#", "###"),
    "4": ("#.#", "#.#", "###", "..#", "..#"), "5": ("###", "#..", "###", "..#", "###"),
    "6": ("###", "#..", "###", "#.#", "###"), "7": ("###", "..#", "..#", ".#.", ".#."),
    "8": ("###", "#.#", "###", "#.#", "###"), "9": ("###", "#.#", "###", "..#", "###"),
    "-": ("...", "...", "###", "...", "..."), " ": ("...", "...", "...", "...", "..."),
}

# RGB colours of the trackers; grey for the ground truth.
PALETTE = [(255, 60, 60), (255, 200, 0), (60, 220, 60), (60, 160, 255), (230, 80, 255), (0, 230, 230)]
TRUTH = (200, 200, 200)


def ycbcr(rgb):
    """Full-range BT.601 (JPEG) Y, Cb, Cr of an RGB colour."""
    r, g, b = rgb
    y = 0.299 * r + 0.587 * g + 0.114 * b
    cb = 128 - 0.168736 * r - 0.331264 * g + 0.5 * b
    cr = 128 + 0.5 * r - 0.418688 * g - 0.081312 * b
    return tuple(max(0, min(255, int(round(v)))) for v in (y, cb, cr))


class Canvas:
    """A 4:2:0 picture (Y at w x h, Cb and Cr at half size) to draw on."""

    def __init__(self, w, h):
        self.w, self.h = w, h
        self.y = bytearray(w * h)
        self.cb = bytearray(b"\x80" * ((w // 2) * (h // 2)))
        self.cr = bytearray(b"\x80" * ((w // 2) * (h // 2)))

    def dot(self, x, y, col):
        if 0 <= x < self.w and 0 <= y < self.h:
            self.y[y * self.w + x] = col[0]
            c = (y // 2) * (self.w // 2) + x // 2
            if x // 2 < self.w // 2 and y // 2 < self.h // 2:
                self.cb[c], self.cr[c] = col[1], col[2]

    def line(self, x0, y0, x1, y1, col):
        steps = int(max(abs(x1 - x0), abs(y1 - y0))) + 1
        for k in range(steps + 1):
            t = k / steps
            self.dot(int(round(x0 + (x1 - x0) * t)), int(round(y0 + (y1 - y0) * t)), col)

    def polygon(self, pts, col):
        for i in range(len(pts)):
            (ax, ay), (bx, by) = pts[i], pts[(i + 1) % len(pts)]
            self.line(ax, ay, bx, by, col)

    def text(self, x, y, s, col, size=2):
        shadow = (16, 128, 128)
        for pass_col, d in ((shadow, 1), (col, 0)):
            cx = x
            for ch in s.upper():
                glyph = _FONT.get(ch, _FONT[" "])
                for gy, row in enumerate(glyph):
                    for gx, ink in enumerate(row):
                        if ink == "#":
                            for sy in range(size):
                                for sx in range(size):
                                    self.dot(cx + gx * size + sx + d, y + gy * size + sy + d, pass_col)
                cx += 4 * size

    def paste(self, tile, ox, oy):
        """Copies another canvas in at (ox, oy); both offsets even."""
        for r in range(tile.h):
            d = (oy + r) * self.w + ox
            self.y[d:d + tile.w] = tile.y[r * tile.w:(r + 1) * tile.w]
        cw = tile.w // 2
        for r in range(tile.h // 2):
            d = (oy // 2 + r) * (self.w // 2) + ox // 2
            self.cb[d:d + cw] = tile.cb[r * cw:(r + 1) * cw]
            self.cr[d:d + cw] = tile.cr[r * cw:(r + 1) * cw]


def _enlarge(plane, w, h, s):
    """Nearest-neighbour enlargement of a w x h plane by the whole factor s."""
    out = bytearray(w * s * h * s)
    row = bytearray(w * s)
    for y in range(h):
        src = plane[y * w:(y + 1) * w]
        for k in range(s):
            row[k::s] = src
        for k in range(s):
            d = (y * s + k) * w * s
            out[d:d + w * s] = row
    return out


def frame_tile(video, frame, s):
    """The frame as a 4:2:0 canvas enlarged s times (mono frames get neutral chroma)."""
    w, h = video.width, video.height
    tile = Canvas(w * s, h * s)
    tile.y[:] = _enlarge(frame[0], w, h, s)
    if len(frame) == 3:
        cw, ch = video.chroma_size
        # to the tile's 4:2:0 chroma (w*s/2 x h*s/2) by nearest neighbour from the source's chroma
        tw, th = tile.w // 2, tile.h // 2
        # tile chroma (x, y) sits on tile luma (2x, 2y), i.e. source luma (2x // s, 2y // s)
        xs = [min(cw - 1, (2 * x // s) * cw // w) for x in range(tw)]
        for ty in range(th):
            sy = min(ch - 1, (2 * ty // s) * ch // h)
            cbrow, crrow = frame[1][sy * cw:(sy + 1) * cw], frame[2][sy * cw:(sy + 1) * cw]
            tile.cb[ty * tw:(ty + 1) * tw] = bytes(cbrow[x] for x in xs)
            tile.cr[ty * tw:(ty + 1) * tw] = bytes(crrow[x] for x in xs)
    return tile


def write(path, video, runs, truth=None, scale=2, columns=3):
    """runs: [(label, {frame: score.Frame}, colour index into PALETTE)] in tile order. Returns the
    output size (w, h)."""
    s = max(1, int(scale))
    if (video.width * s) % 2 or (video.height * s) % 2:
        s *= 2  # 4:2:0 wants even sizes
    tw, th = video.width * s, video.height * s
    tiles = 1 + len(runs)
    cols = max(1, min(columns, tiles))
    rows = (tiles + cols - 1) // cols
    W, H = tw * cols, th * rows
    colours = [ycbcr(PALETTE[c % len(PALETTE)]) for _, _, c in runs]
    grey = ycbcr(TRUTH)
    white = ycbcr((255, 255, 255))

    def to_tile(p):  # sequence pixel (centres at integers) -> tile pixel
        return (p[0] + 0.5) * s - 0.5, (p[1] + 0.5) * s - 0.5

    def frames():
        for i, frame in enumerate(video.frames):
            out = Canvas(W, H)
            base = frame_tile(video, frame, s)
            box = truth.boxes.get(i) if truth is not None and truth.boxes else None
            for t in range(tiles):
                tile = Canvas(tw, th)
                tile.y[:], tile.cb[:], tile.cr[:] = base.y, base.cb, base.cr
                if box is not None:
                    tile.polygon([to_tile(p) for p in ((box[0], box[1]), (box[2], box[1]),
                                                       (box[2], box[3]), (box[0], box[3]))], grey)
                if t == 0:
                    tile.text(2, 2, f"{i}", white)
                    tile.text(2, th - 12, "TRUTH" if box is not None else "INPUT", grey)
                else:
                    label, run, _ = runs[t - 1]
                    rec = run.get(i)
                    if rec is not None and rec.tracking:
                        tile.polygon([to_tile(p) for p in rec.outline], colours[t - 1])
                    tile.text(2, 2, label + ("" if rec is not None and rec.tracking else " LOST"),
                              colours[t - 1])
                out.paste(tile, (t % cols) * tw, (t // cols) * th)
            yield bytes(out.y), bytes(out.cb), bytes(out.cr)

    y4m.write(path, W, H, frames(), colour="420jpeg", fps=video.fps)
    return W, H
