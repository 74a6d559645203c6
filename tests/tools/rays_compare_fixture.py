# SPDX-License-Identifier: Apache-2.0
"""Tiny sequence folders in the realset layout (seq.y4m, masks.y4m, boxes.csv, meta.json), written by the
rays-compare tests themselves, pure Python."""
import atexit
import json
import os
import shutil
import sys
import tempfile

W = H = 128
failures = []


def check(what, ok, detail=""):
    """Prints one check's outcome; finish() fails the test if any did not hold."""
    print(f"{'ok  ' if ok else 'FAIL'} {what}{': ' + detail if detail else ''}")
    if not ok:
        failures.append(what)


def finish():
    print(f"{len(failures)} failed" if failures else "all checks passed")
    sys.exit(1 if failures else 0)


def work_folder(prefix):
    """A temporary folder, removed when the test exits."""
    work = tempfile.mkdtemp(prefix=prefix)
    atexit.register(shutil.rmtree, work, True)
    return work


def _y4m(path, frames, colour):
    with open(path, "wb") as f:
        f.write(f"YUV4MPEG2 W{W} H{H} F30:1 Ip A1:1 C{colour}\n".encode())
        for planes in frames:
            f.write(b"FRAME\n")
            for p in planes:
                f.write(bytes(p))


def rect_mask(x0, y0, x1, y1):
    """A Cmono plane: 255 on pixels x0..x1, y0..y1 (inclusive), 0 elsewhere."""
    m = bytearray(W * H)
    for y in range(y0, y1 + 1):
        m[y * W + x0:y * W + x1 + 1] = b"\xff" * (x1 - x0 + 1)
    return m


def write_sequence(folder, luma, chroma, masks, boxes, meta):
    """luma: [W*H planes]; chroma: [(cb, cr)] of 64x64 planes; masks: [W*H planes] or None;
    boxes: {frame: (x0, y0, x1, y1)} or None; meta: meta.json's dict."""
    os.makedirs(folder, exist_ok=True)
    _y4m(os.path.join(folder, "seq.y4m"), [(y, cb, cr) for y, (cb, cr) in zip(luma, chroma)], "420jpeg")
    if masks is not None:
        _y4m(os.path.join(folder, "masks.y4m"), [(m,) for m in masks], "mono")
    if boxes is not None:
        with open(os.path.join(folder, "boxes.csv"), "w") as f:
            f.write("frame,x0,y0,x1,y1\n")
            for i, b in sorted(boxes.items()):
                f.write(f"{i},{b[0]:.3f},{b[1]:.3f},{b[2]:.3f},{b[3]:.3f}\n")
    with open(os.path.join(folder, "meta.json"), "w") as f:
        json.dump(meta, f, indent=1)


def grey_frames(n, value=100):
    return [bytearray([value]) * (W * H) for _ in range(n)], [(bytearray(b"\x80" * 4096),) * 2 for _ in range(n)]


def moving_disc(folder, frames=12, radius=16, start=(56, 64), step=(1, 0)):
    """An orange disc moving over a dark, textured green background: its mask, its boxes (edges half a
    pixel outside the outermost pixel centres) and meta.json with init (the centre) and init_box."""
    seed = 12345
    texture = bytearray(W * H)
    for k in range(W * H):  # a fixed pseudo-random texture, +-12 grey levels
        seed = (seed * 1103515245 + 12345) & 0x7FFFFFFF
        texture[k] = 60 + (seed >> 16) % 25 - 12
    luma, chroma, masks, boxes = [], [], [], {}
    for i in range(frames):
        cx, cy = start[0] + step[0] * i, start[1] + step[1] * i
        y = bytearray(texture)
        m = bytearray(W * H)
        cb, cr = bytearray(b"\x70" * 4096), bytearray(b"\x70" * 4096)  # greenish background
        for py in range(H):
            for px in range(W):
                if (px - cx) ** 2 + (py - cy) ** 2 <= radius * radius:
                    y[py * W + px] = 190
                    m[py * W + px] = 255
                    cb[(py // 2) * 64 + px // 2], cr[(py // 2) * 64 + px // 2] = 70, 200  # orange
        luma.append(y)
        chroma.append((cb, cr))
        masks.append(m)
        boxes[i] = (cx - radius - 0.5, cy - radius - 0.5, cx + radius + 0.5, cy + radius + 0.5)
    b0 = boxes[0]
    meta = {"name": os.path.basename(folder), "frames": frames, "fps": 30, "init": [start[0], start[1]],
            "init_box": [b0[0], b0[1], b0[2] - b0[0], b0[3] - b0[1]]}
    write_sequence(folder, luma, chroma, masks, boxes, meta)
    return meta
