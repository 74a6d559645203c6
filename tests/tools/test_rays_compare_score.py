#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""rays-compare's scorer (tools/rays_compare/score.py) on a 4-frame sequence this test writes, against
numbers worked out by hand below.

usage: test_rays_compare_score.py REPO_DIR SHARED_DIR CASE
CASE: score     the hand-computed measures (pure Python, runs anywhere)
      agrees    the same rays run through ../shared/tools/score-real.py gives the same numbers
                (SKIPPED, exit 77, where ../shared or numpy for /usr/bin/python3 is absent)
"""
import atexit
import json
import os
import shutil
import subprocess
import sys
import tempfile

REPO, SHARED, CASE = sys.argv[1], sys.argv[2], sys.argv[3]
sys.path.insert(0, os.path.join(REPO, "tools"))
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from rays_compare import score  # noqa: E402
import rays_compare_fixture as fx  # noqa: E402

failures = []


def check(what, got, want, tol=1e-9):
    ok = (got is None and want is None) or (got is not None and want is not None and abs(got - want) <= tol)
    print(f"{'ok  ' if ok else 'FAIL'} {what}: {got!r} (want {want!r})")
    if not ok:
        failures.append(what)


def skip(why):
    print(f"SKIPPED: {why}")
    sys.exit(77)


# The mask: pixels x 40..59, y 50..69 (20 x 20 = 400). Its box, edges half a pixel outside those
# pixel centres: x 39.5..59.5, y 49.5..69.5. Four frames, the same mask and box in each.
MASK = (40, 50, 59, 69)
BOX = (39.5, 49.5, 59.5, 69.5)
work = tempfile.mkdtemp(prefix="test-rays-compare-score-")
atexit.register(shutil.rmtree, work, True)
seq = os.path.join(work, "tiny")
luma, chroma = fx.grey_frames(4)
fx.write_sequence(seq, luma, chroma, [fx.rect_mask(*MASK)] * 4, {i: BOX for i in range(4)},
                  {"name": "tiny", "frames": 4, "init": [49.5, 59.5], "init_box": [39.5, 49.5, 20, 20]})


def sq(x0, y0, x1, y1):
    return [[x0, y0], [x1, y0], [x1, y1], [x0, y1]]


# A rays-replay run (header, then records in processing pixels; the header maps them by scale and offset).
# frame 0: the square 44.5..64.5 x 54.5..74.5 given in processing pixels 34.5..54.5 x 54.5..74.5,
#          shifted by the header's offset (10, 0). Its pixels: x 45..64, y 55..74 (400); with the mask
#          x 45..59 x y 55..69 = 15 x 15 = 225 in common; union 400 + 400 - 225 = 575; IoU 225/575.
#          The mean of its 4 points (54.5, 64.5) is in the box: a hit.
# frame 1: the mask's own outline, as 8 points (corners and edge midpoints, starting at a midpoint):
#          IoU 1. The mean of the points, (49.5, 59.5), is in the box: a hit.
# frame 2: a square 100..110 x 100..110 (processing 90..100): IoU 0, centre (105, 105) outside: a miss.
# frame 3: "lost" (no contour): IoU 0, not tracked, the one lost event.
# centre_in_box = 2 hits / 4 frames = 0.5; tracked = 3/4; mask_iou = (225/575 + 1 + 0 + 0) / 4.
# time_us 100, 200, 300, 1000: median (200 + 300) / 2 = 250; p99 at rank 0.99 * 3 = 2.97:
# 300 + 0.97 * (1000 - 300) = 979.
def shift(points, dx):
    return [[x - dx, y] for x, y in points]


rays_run = os.path.join(work, "rays.jsonl")
outline1 = [[49.5, 49.5], [59.5, 49.5], [59.5, 59.5], [59.5, 69.5], [49.5, 69.5], [39.5, 69.5],
            [39.5, 59.5], [39.5, 49.5]]
records = [
    {"source": {"width": 128, "height": 128}, "scale": [1.0, 1.0], "offset": [10.0, 0.0]},
    {"frame": 0, "state": "tracking", "ref": [44.5, 64.5], "contour": shift(sq(44.5, 54.5, 64.5, 74.5), 10),
     "time_us": 100.0},
    {"frame": 1, "state": "tracking", "ref": [39.5, 59.5], "contour": shift(outline1, 10), "time_us": 200.0},
    {"frame": 2, "state": "tracking", "ref": [95, 105], "contour": shift(sq(100, 100, 110, 110), 10),
     "time_us": 300.0},
    {"frame": 3, "state": "lost", "ref": None, "contour": [], "time_us": 1000.0},
]
with open(rays_run, "w") as f:
    f.write("\n".join(json.dumps(r) for r in records) + "\n")

# An OpenCV run as rays-compare records it (boxes as edges; frame 0 is init(), its time not counted).
# frame 0: the truth's box: IoU 1, centre (49.5, 59.5): a hit.
# frame 1: box 49.5..69.5 x 49.5..69.5: pixels x 50..69, y 50..69 (400); in common x 50..59 x 20 = 200;
#          union 600: IoU 1/3. Centre (59.5, 59.5) lies on the truth's right edge: edges count, a hit.
# frame 2: lost (a lost event). frame 3: box 0..9 x 0..9 again tracking: IoU 0, centre (4.5, 4.5): a miss.
# centre_in_box = 2/4; tracked = 3/4; mask_iou = (1 + 1/3 + 0 + 0) / 4; lost 1.
# time_us 10, 20, 40 (frames 1-3): median 20; p99 at rank 0.99 * 2 = 1.98: 20 + 0.98 * 20 = 39.6.
box_run = os.path.join(work, "csrt.jsonl")
records = [
    {"tracker": "csrt", "opencv": "test"},
    {"frame": 0, "init_us": 5000.0, "state": "tracking", "box": list(BOX)},
    {"frame": 1, "time_us": 10.0, "state": "tracking", "box": [49.5, 49.5, 69.5, 69.5]},
    {"frame": 2, "time_us": 20.0, "state": "lost", "box": None},
    {"frame": 3, "time_us": 40.0, "state": "tracking", "box": [0, 0, 9, 9]},
]
with open(box_run, "w") as f:
    f.write("\n".join(json.dumps(r) for r in records) + "\n")

truth = score.load_truth(seq)

if CASE == "score":
    # percentile(): numpy's default (linear between closest ranks), by hand.
    check("percentile 50 of 1..4", score.percentile([4, 1, 3, 2], 50), 2.5)
    check("percentile 99 of 1..4", score.percentile([1, 2, 3, 4], 99), 3.97)
    check("percentile 0 / 100", score.percentile([7, 3], 0) + score.percentile([7, 3], 100), 10.0)
    check("percentile of one", score.percentile([5], 99), 5.0)
    check("percentile of none", score.percentile([], 50), None)
    # raster(): the triangle (0,0) (4,0) (0,4) at pixel centres: x < 4 - y, rows 0..3: 4 + 3 + 2 + 1.
    tri = score.raster([(0, 0), (4, 0), (0, 4)], 8, 8)
    check("triangle pixels", sum(tri), 10)
    check("triangle row 1", sum(tri[8:16]), 3)
    check("triangle (3,0) in, (3,1) out", tri[3] * 10 + tri[8 + 3], 10)
    check("mask pixels", sum(score.raster(sq(39.5, 49.5, 59.5, 69.5), 128, 128)), 400)

    s = score.score(score.load_run(rays_run), truth)
    check("rays centre_in_box", s["centre_in_box"], 0.5)
    check("rays tracked", s["tracked"], 0.75)
    check("rays mask_iou", s["mask_iou"], (225 / 575 + 1) / 4)
    check("rays lost", s["lost"], 1)
    check("rays median_us", s["median_us"], 250.0)
    check("rays p99_us", s["p99_us"], 979.0)

    s = score.score(score.load_run(box_run), truth)
    check("box centre_in_box", s["centre_in_box"], 0.5)
    check("box tracked", s["tracked"], 0.75)
    check("box mask_iou", s["mask_iou"], (1 + 1 / 3) / 4)
    check("box lost", s["lost"], 1)
    check("box median_us", s["median_us"], 20.0)
    check("box p99_us", s["p99_us"], 39.6)
    check("box timed frames (init not counted)", s["timed_frames"], 3)

    # Without ground truth (a user's own folder): times and losses only.
    bare = score.Truth(128, 128, 4)
    s = score.score(score.load_run(rays_run), bare)
    check("no truth: centre_in_box", s["centre_in_box"], None)
    check("no truth: mask_iou", s["mask_iou"], None)
    check("no truth: lost", s["lost"], 1)
    check("no truth: median_us", s["median_us"], 250.0)
elif CASE == "agrees":
    ref = os.path.join(SHARED, "tools", "score-real.py")
    if not os.path.isfile(ref):
        skip(f"the reference scorer {ref} is absent on this machine")
    if subprocess.run(["/usr/bin/python3", "-c", "import numpy"], capture_output=True).returncode != 0:
        skip("score-real.py needs numpy for /usr/bin/python3 (python3-numpy), which is not installed")
    p = subprocess.run(["/usr/bin/python3", ref, seq, rays_run], capture_output=True, text=True)
    if p.returncode != 0:
        print(p.stderr)
        failures.append("score-real.py ran")
    else:
        want = json.loads(p.stdout)
        s = score.score(score.load_run(rays_run), truth)
        check("centre_in_box as score-real.py", round(s["centre_in_box"], 3), want["centre_in_box"])
        check("tracked as score-real.py", round(s["tracked"], 3), want["tracked"])
        check("mask_iou as score-real.py", round(s["mask_iou"], 3), want["mask_iou"])
        check("lost as score-real.py", s["lost"], want["lost_events"])
        check("median_us as score-real.py", round(s["median_us"], 1), want["time_us_median"])
        check("p99_us as score-real.py", round(s["p99_us"], 1), want["time_us_p99"])
else:
    sys.exit(f"unknown case {CASE}")

print(f"{len(failures)} failed" if failures else "all checks passed")
sys.exit(1 if failures else 0)
