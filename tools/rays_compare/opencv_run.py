#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""One OpenCV tracker over a YUV4MPEG2 sequence, for rays-compare (run as its own process, so that it can
use whichever Python has python3-opencv, and so that its memory and threads end with it).

  opencv_run.py --probe
      prints {"cv2": version or null, "error": why not or null, "trackers": {name: null or why missing}}
  opencv_run.py --tracker csrt|kcf|mosse --input SEQ.y4m --box X,Y,W,H --out RUN.jsonl [--threads N]
      X,Y,W,H: the start box, edges in the sequence's pixels with pixel centres at integers. Writes a
      header {"tracker", "opencv", "threads", "init_box_cv"}, then per frame {"frame", "state":
      "tracking"|"lost", "box": [x0, y0, x1, y1] (edges, pixel centres at integers) or null,
      "time_us"}: update()'s wall time; frame 0 is init() (its time as "init_us", not "time_us").
      The start box goes to CSRT and KCF rounded to whole pixels (their API takes an int Rect) and
      to MOSSE as it is (the legacy API takes a Rect2d); "init_box_cv" is what was given.

Frames are converted to BGR as full-range BT.601 (C420jpeg): chroma upsampled bilinearly to the
luma size, then cv2.COLOR_YCrCb2BGR (JPEG's matrix).
"""
import argparse
import json
import os
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from rays_compare import y4m  # noqa: E402

# name -> (attribute path under cv2, where it lives)
TRACKERS = {
    "csrt": ("TrackerCSRT_create", "the contrib tracking module"),
    "kcf": ("TrackerKCF_create", "the contrib tracking module"),
    "mosse": ("legacy.TrackerMOSSE_create", "the contrib tracking module's legacy API"),
}


def _lookup(cv2, path):
    obj = cv2
    for part in path.split("."):
        obj = getattr(obj, part, None)
        if obj is None:
            return None
    return obj


def probe():
    out = {"cv2": None, "error": None, "trackers": {}}
    try:
        import cv2  # noqa: F401
    except Exception as e:  # ImportError, or a broken install raising something else
        out["error"] = f"{type(e).__name__}: {e}"
        print(json.dumps(out))
        return 0
    out["cv2"] = getattr(cv2, "__version__", "?")
    for name, (path, where) in TRACKERS.items():
        out["trackers"][name] = None if _lookup(cv2, path) else \
            f"cv2.{path} is missing from this OpenCV {out['cv2']} (it is in {where})"
    print(json.dumps(out))
    return 0


def to_bgr(cv2, np, video, frame):
    w, h = video.width, video.height
    luma = np.frombuffer(frame[0], np.uint8).reshape(h, w)
    if len(frame) == 1:
        return cv2.cvtColor(luma, cv2.COLOR_GRAY2BGR)
    cw, ch = video.chroma_size
    cb = np.frombuffer(frame[1], np.uint8).reshape(ch, cw)
    cr = np.frombuffer(frame[2], np.uint8).reshape(ch, cw)
    if (cw, ch) != (w, h):
        cb = cv2.resize(cb, (w, h), interpolation=cv2.INTER_LINEAR)
        cr = cv2.resize(cr, (w, h), interpolation=cv2.INTER_LINEAR)
    return cv2.cvtColor(cv2.merge([luma, cr, cb]), cv2.COLOR_YCrCb2BGR)


def run(args):
    import cv2
    import numpy as np
    if args.threads >= 0:
        cv2.setNumThreads(args.threads)
    create = _lookup(cv2, TRACKERS[args.tracker][0])
    if create is None:
        print(f"opencv_run: cv2.{TRACKERS[args.tracker][0]} is missing", file=sys.stderr)
        return 3
    video = y4m.read(args.input)
    x, y, w, h = (float(v) for v in args.box.split(","))
    # OpenCV's pixel i spans [i, i+1): our edge e (pixel centres at integers) is OpenCV's e + 0.5.
    # The new API (CSRT, KCF) takes an int Rect; the legacy one (MOSSE) a Rect2d, given exactly.
    legacy = TRACKERS[args.tracker][0].startswith("legacy.")
    rect = (x + 0.5, y + 0.5, w, h) if legacy else \
        (int(round(x + 0.5)), int(round(y + 0.5)), max(1, int(round(w))), max(1, int(round(h))))
    tracker = create()
    with open(args.out, "w") as out:
        out.write(json.dumps({"tracker": args.tracker, "opencv": cv2.__version__,
                              "threads": cv2.getNumThreads(), "init_box_cv": rect}) + "\n")
        for i, frame in enumerate(video.frames):
            bgr = to_bgr(cv2, np, video, frame)
            if i == 0:
                t0 = time.perf_counter_ns()
                ok = tracker.init(bgr, rect)
                t1 = time.perf_counter_ns()
                ok = ok is None or bool(ok)  # the new API returns None, the legacy one a bool
                box = rect
                rec = {"frame": 0, "init_us": round((t1 - t0) / 1000.0, 1)}
            else:
                t0 = time.perf_counter_ns()
                ok, box = tracker.update(bgr)
                t1 = time.perf_counter_ns()
                rec = {"frame": i, "time_us": round((t1 - t0) / 1000.0, 1)}
            bx, by, bw, bh = (float(v) for v in box)
            ok = bool(ok) and bw > 0 and bh > 0
            rec["state"] = "tracking" if ok else "lost"
            rec["box"] = [round(bx - 0.5, 3), round(by - 0.5, 3), round(bx + bw - 0.5, 3),
                          round(by + bh - 0.5, 3)] if ok else None
            out.write(json.dumps(rec) + "\n")
    return 0


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--probe", action="store_true")
    ap.add_argument("--tracker", choices=sorted(TRACKERS))
    ap.add_argument("--input")
    ap.add_argument("--box")
    ap.add_argument("--out")
    ap.add_argument("--threads", type=int, default=1)
    args = ap.parse_args()
    if args.probe:
        return probe()
    if not (args.tracker and args.input and args.box and args.out):
        ap.error("--tracker, --input, --box and --out are needed (or --probe)")
    return run(args)


if __name__ == "__main__":
    sys.exit(main())
