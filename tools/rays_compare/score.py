# SPDX-License-Identifier: Apache-2.0
"""The one scorer of rays-compare, pure Python (no numpy): every tracker's run is scored here the same way.

Coordinates are the sequence's pixels with pixel centres at integers (as boxes.csv and rays-replay's
records, after the header's scale and offset). A run is a list of Frame records: whether the tracker
reported tracking, the outline it reported (the rays contour, or an OpenCV box as its 4 corners) and
the time it took. Per run:

  centre_in_box  share of the ground-truth frames (boxes.csv) whose outline centre (the mean of the
                 contour's points, the box's centre) lies in the ground-truth box, edges included; a
                 frame counts only while the tracker reports tracking
  mask_iou       mean over the frames with a mask (masks.y4m, 255 = target) of the IoU of the outline,
                 filled at pixel centres (even-odd), against the mask; 0 where not tracking
  tracked        share of the ground-truth frames in which the tracker reported tracking
  lost           lost events: frames where tracking stops after a tracked frame
  median_us, p99_us  the time per frame, both through percentile() (linear between closest ranks)

These are the definitions of ../shared/tools/score-real.py where the two measure the same thing.
"""
import csv
import json
import math
import os

from . import y4m


class Frame:
    __slots__ = ("frame", "tracking", "outline", "time_us")

    def __init__(self, frame, tracking, outline, time_us):
        self.frame, self.tracking, self.outline, self.time_us = frame, tracking, outline, time_us


class Truth:
    """A sequence's ground truth: boxes {frame: (x0, y0, x1, y1)} or None, masks [bytes] or None."""

    def __init__(self, width, height, frames, boxes=None, masks=None):
        self.width, self.height, self.frames, self.boxes, self.masks = width, height, frames, boxes, masks
        self._rows = {}

    def mask_rows(self, i):
        """Mask i as row bit sets (see mask_rows()), computed once for all the runs scored."""
        if i not in self._rows:
            self._rows[i] = mask_rows(self.masks[i], self.height, self.width)
        return self._rows[i]


def percentile(values, q):
    """The q-th percentile (0-100), linear between closest ranks (numpy's default); None when empty."""
    v = sorted(float(x) for x in values)
    if not v:
        return None
    pos = (len(v) - 1) * q / 100.0
    lo = math.floor(pos)
    hi = min(lo + 1, len(v) - 1)
    return v[lo] + (v[hi] - v[lo]) * (pos - lo)


def raster_rows(poly, h, w):
    """Even-odd fill of a polygon at pixel centres: one int per row, bit x set where pixel x is inside.

    A pixel (x, y) is inside when an odd number of the edges crossing row y cross it right of x
    (strictly), the rule of score-real.py's raster(); edges along a row are skipped."""
    rows = [0] * h
    n = len(poly)
    if n < 3:
        return rows
    full = (1 << w) - 1
    for i in range(n):
        x0, y0 = float(poly[i][0]), float(poly[i][1])
        x1, y1 = float(poly[(i + 1) % n][0]), float(poly[(i + 1) % n][1])
        if y0 == y1:
            continue
        # rows y with (y0 > y) != (y1 > y): the integers in [min(y0, y1), max(y0, y1)), within the frame
        first = max(0, math.ceil(min(y0, y1)))
        last = min(h - 1, math.ceil(max(y0, y1)) - 1)
        for y in range(first, last + 1):
            xc = x0 + (y - y0) * (x1 - x0) / (y1 - y0)
            # pixels x < xc: 0 .. ceil(xc) - 1
            k = math.ceil(xc) if xc > 0 else 0
            rows[y] ^= full if k >= w else (1 << k) - 1
    return rows


def raster(poly, h, w):
    """The filled polygon as a bytearray of h*w 0/1 samples (for overlays and tests)."""
    out = bytearray(h * w)
    for y, bits in enumerate(raster_rows(poly, h, w)):
        for x in range(w):
            if bits >> x & 1:
                out[y * w + x] = 1
    return out


_BIT_CHARS = bytes(0x31 if b > 127 else 0x30 for b in range(256))  # sample -> b"1" (target) / b"0"


def mask_rows(mask, h, w):
    """A mask plane (bytes, > 127 = target) as one int per row, bit x = pixel x."""
    return [int(mask[y * w:(y + 1) * w].translate(_BIT_CHARS)[::-1], 2) for y in range(h)]


def iou_rows(a, b):
    inter = sum((x & y).bit_count() for x, y in zip(a, b))
    union = sum((x | y).bit_count() for x, y in zip(a, b))
    return inter / union if union else 0.0


def box_outline(x0, y0, x1, y1):
    return [(x0, y0), (x1, y0), (x1, y1), (x0, y1)]


def centre(outline):
    """The mean of the outline's points: the rays contour's centroid as score-real.py takes it, a box's centre."""
    n = len(outline)
    return sum(p[0] for p in outline) / n, sum(p[1] for p in outline) / n


def load_truth(seq_dir, shape=None):
    """boxes.csv and masks.y4m where they exist; shape = (width, height, frames) of seq.y4m (read
    from it when not given)."""
    width, height, frames = shape or _y4m_shape(os.path.join(seq_dir, "seq.y4m"))
    boxes = masks = None
    path = os.path.join(seq_dir, "boxes.csv")
    if os.path.exists(path):
        with open(path, newline="") as f:
            boxes = {int(r["frame"]): tuple(float(r[k]) for k in ("x0", "y0", "x1", "y1"))
                     for r in csv.DictReader(f)}
    path = os.path.join(seq_dir, "masks.y4m")
    if os.path.exists(path):
        m = y4m.read(path)
        masks = [f[0] for f in m.frames]
        width, height = m.width, m.height
    return Truth(width, height, frames, boxes, masks)


def _y4m_shape(path):
    """(width, height, frames) of a YUV4MPEG2 file."""
    v = y4m.read(path)
    return v.width, v.height, len(v.frames)


def load_run(path):
    """A run as {frame: Frame}: rays-replay's JSON Lines (header, then records with "state" and
    "contour" in processing pixels, mapped here through the header's scale and offset) or
    rays-compare's OpenCV runs (records with "state" and "box": [x0, y0, x1, y1], box edges)."""
    frames = {}
    scale, offset = (1.0, 1.0), (0.0, 0.0)
    with open(path) as f:
        for line in f:
            if not line.strip():
                continue
            o = json.loads(line)
            if "frame" not in o:
                scale = tuple(o.get("scale", scale))
                offset = tuple(o.get("offset", offset))
                continue
            outline = []
            if o.get("contour"):
                outline = [(x * scale[0] + offset[0], y * scale[1] + offset[1]) for x, y in o["contour"]]
            elif o.get("box"):
                x0, y0, x1, y1 = (float(v) for v in o["box"])
                if x1 > x0 and y1 > y0:
                    outline = box_outline(x0, y0, x1, y1)
            tracking = o.get("state") == "tracking" and len(outline) >= 3
            t = o.get("time_us")
            frames[int(o["frame"])] = Frame(int(o["frame"]), tracking, outline if tracking else [],
                                            float(t) if t is not None else None)
    return frames


def score(run, truth):
    """Scores a run ({frame: Frame}) against a Truth; a dict of the measures (None where not measured)."""
    if truth.boxes:
        span = max(truth.boxes) + 1
        n = len(truth.boxes)
    else:
        span = max(truth.frames, max(run) + 1 if run else 0)
        n = span
    hits = tracked = lost = 0
    ious, times = [], []
    prev = False
    for i in range(span):
        fr = run.get(i)
        tracking = bool(fr and fr.tracking)
        if fr is not None and fr.time_us is not None:
            times.append(fr.time_us)
        if prev and not tracking:
            lost += 1
        prev = tracking
        if truth.masks is not None and i < len(truth.masks):
            if tracking:
                ious.append(iou_rows(raster_rows(fr.outline, truth.height, truth.width), truth.mask_rows(i)))
            else:
                ious.append(0.0)
        if truth.boxes is not None:
            b = truth.boxes.get(i)
            if b is None:
                continue
            if tracking:
                tracked += 1
                cx, cy = centre(fr.outline)
                hits += b[0] <= cx <= b[2] and b[1] <= cy <= b[3]
        elif tracking:
            tracked += 1
    return {
        "frames": n,
        "tracked": tracked / n if n else None,
        "centre_in_box": hits / n if truth.boxes and n else None,
        "mask_iou": sum(ious) / len(ious) if ious else None,
        "lost": lost,
        "median_us": percentile(times, 50),
        "p99_us": percentile(times, 99),
        "timed_frames": len(times),
    }
