# SPDX-License-Identifier: Apache-2.0
"""Sequence folders derived from one with ground truth, so that a change is judged beyond the exact
footage it was measured on (rays-compare --variants):

  reversed   the frames played backwards: the target is met from its last frame's side, and the start
             is that frame's: "init" at the mask's deepest point (the point farthest from its outside,
             where a person would click; the realset's own "init" points are within a pixel of it), or
             the box's centre without masks; "init_box" that frame's box
  every-2nd  frames 0, 2, 4, ...: twice the motion between frames, at half the frame rate; the start
             is the sequence's own
  grey       the same frames without their chroma (a mono camera's picture: what the tracker has
             where the source gives no colour); the start is the sequence's own
  there-and-back  frames 0 … N−1, then N−2 … 0: twice as long, and the target stops where the
             footage ends and retraces its path (a walker who turns back while others go on); the
             models learned on the way out meet the target again as it looked at the start; the
             start is the sequence's own
  mirrored   every frame flipped left to right (x -> width - 1 - x, pixel centres at integers): the
             same motion the other way round, which a tracker with no preferred side follows as well;
             the start is the sequence's own, mirrored

Pure Python, as the rest of rays-compare. The ground truth (boxes.csv, masks.y4m) moves with the frames.
"""
import json
import os

from . import score, y4m

KINDS = ("reversed", "every-2nd", "grey", "there-and-back", "mirrored")


def frame_order(kind, count):
    if kind == "reversed":
        return list(range(count - 1, -1, -1))
    if kind == "every-2nd":
        return list(range(0, count, 2))
    if kind in ("grey", "mirrored"):
        return list(range(count))
    if kind == "there-and-back":
        return list(range(count)) + list(range(count - 2, -1, -1))
    raise ValueError(f"unknown variant {kind!r}; choose from {', '.join(KINDS)}")


def deepest_point(plane, width, height):
    """(x, y) of the mask pixel (> 127) farthest from the mask's outside (the frame's border counts as
    outside), by the 3-4 chamfer distance; the first such pixel in row order; None for an empty mask."""
    far = 1 << 30
    d = [0 if plane[i] <= 127 else far for i in range(width * height)]
    for y in range(height):  # forward: the neighbours above and to the left
        for x in range(width):
            i = y * width + x
            if d[i] == 0:
                continue
            v = d[i]
            v = min(v, d[i - 1] + 3 if x > 0 else 3)
            if y > 0:
                v = min(v, d[i - width] + 3, d[i - width - 1] + 4 if x > 0 else 4,
                        d[i - width + 1] + 4 if x + 1 < width else 4)
            else:
                v = min(v, 3)
            d[i] = v
    for y in range(height - 1, -1, -1):  # backward: below and to the right
        for x in range(width - 1, -1, -1):
            i = y * width + x
            if d[i] == 0:
                continue
            v = d[i]
            v = min(v, d[i + 1] + 3 if x + 1 < width else 3)
            if y + 1 < height:
                v = min(v, d[i + width] + 3, d[i + width + 1] + 4 if x + 1 < width else 4,
                        d[i + width - 1] + 4 if x > 0 else 4)
            else:
                v = min(v, 3)
            d[i] = v
    best = max(range(width * height), key=lambda i: (d[i], -i))
    return None if d[best] == 0 else (best % width, best // width)


def mirror_rows(plane, width):
    """A row-major plane (bytes) with each row's samples in reverse order."""
    return b"".join(bytes(plane[i:i + width])[::-1] for i in range(0, len(plane), width))


def mirror_frame(frame, width, chroma_width):
    return tuple(mirror_rows(p, width if k == 0 else chroma_width) for k, p in enumerate(frame))


def derive(seq, kind, out_root):
    """Writes the `kind` variant of sequence folder `seq` as out_root/NAME-KIND and returns that folder.
    The reversed variant needs boxes.csv (its start is the last frame's)."""
    name = os.path.basename(os.path.normpath(seq))
    with open(os.path.join(seq, "meta.json")) as f:
        meta = json.load(f)
    video = y4m.read(os.path.join(seq, "seq.y4m"))
    order = frame_order(kind, len(video.frames))
    truth = score.load_truth(seq, shape=(video.width, video.height, len(video.frames)))
    boxes, masks = truth.boxes, truth.masks  # the scorer's reading of boxes.csv and masks.y4m
    if kind == "reversed" and (boxes is None or order[0] not in boxes):
        raise ValueError(f"{name}: the reversed variant needs boxes.csv with the last frame's box")

    out = os.path.join(out_root, f"{name}-{kind}")
    os.makedirs(out, exist_ok=True)
    fps = (video.fps[0], video.fps[1] * 2) if kind == "every-2nd" else video.fps
    grey = kind == "grey"  # the luma plane alone
    mirrored = kind == "mirrored"
    chroma_width = video.chroma_size[0]

    def frame_of(i):
        if grey:
            return video.frames[i][:1]
        return mirror_frame(video.frames[i], video.width, chroma_width) if mirrored else video.frames[i]

    y4m.write(os.path.join(out, "seq.y4m"), video.width, video.height, [frame_of(i) for i in order],
              "mono" if grey else video.colour, fps)
    if masks is not None:
        y4m.write(os.path.join(out, "masks.y4m"), truth.width, truth.height,
                  [(mirror_rows(masks[i], truth.width) if mirrored else masks[i],) for i in order if i < len(masks)],
                  "mono", fps)
    right = video.width - 1  # x -> right - x mirrors the sequence's pixels (centres at integers)
    if boxes is not None:
        with open(os.path.join(out, "boxes.csv"), "w") as f:
            f.write("frame,x0,y0,x1,y1\n")
            for k, i in enumerate(order):
                if i in boxes:
                    x0, y0, x1, y1 = boxes[i]
                    box = (right - x1, y0, right - x0, y1) if mirrored else boxes[i]
                    f.write(f"{k}," + ",".join(f"{v:.3f}" for v in box) + "\n")

    derived = dict(meta, name=f"{name}-{kind}", frames=len(order), derived_from=name, variant=kind)
    if "fps" in meta and kind == "every-2nd":
        derived["fps"] = meta["fps"] / 2
    if kind == "reversed":
        x0, y0, x1, y1 = boxes[order[0]]
        derived["init_box"] = [x0, y0, x1 - x0, y1 - y0]
        point = None
        if masks is not None and order[0] < len(masks):
            point = deepest_point(masks[order[0]], truth.width, truth.height)
        if point:  # in the sequence's pixels (pixel centres at integers), should the masks be another size
            sx, sy = video.width / truth.width, video.height / truth.height
            point = ((point[0] + 0.5) * sx - 0.5, (point[1] + 0.5) * sy - 0.5)
        derived["init"] = list(point) if point else [(x0 + x1) / 2, (y0 + y1) / 2]
    if mirrored:
        if "init_box" in meta:
            x, y, w, h = meta["init_box"]
            derived["init_box"] = [right - (x + w), y, w, h]
        if "init" in meta:
            derived["init"] = [right - meta["init"][0], meta["init"][1]]
    with open(os.path.join(out, "meta.json"), "w") as f:
        json.dump(derived, f, indent=1)
    return out
