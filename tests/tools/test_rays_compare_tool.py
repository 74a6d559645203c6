#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""tools/rays-compare without python3-opencv: a PYTHONPATH folder whose cv2.py raises ImportError stands
in for its absence (for every Python the tool tries). The OpenCV trackers must be skipped with the one
SKIPPED line, and the rays runs on a tiny sequence this test writes still scored, by the same scorer.

usage: test_rays_compare_tool.py REPO_DIR RAYS_REPLAY
"""
import json
import os
import subprocess
import sys

REPO, RAYS_REPLAY = sys.argv[1], sys.argv[2]
TOOL = os.path.join(REPO, "tools", "rays-compare")
sys.path.insert(0, os.path.join(REPO, "tools"))
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from rays_compare import score, y4m  # noqa: E402
import rays_compare_fixture as fx  # noqa: E402

NO_OPENCV = "SKIPPED: OpenCV trackers: python3-opencv is not installed (apt-get install python3-opencv)"
BOX_UNSUPPORTED = "box start not supported by this rays-replay"
check = fx.check
work = fx.work_folder("test-rays-compare-tool-")
seq = os.path.join(work, "disc")
fx.moving_disc(seq, frames=12)
fake = os.path.join(work, "no-opencv")
os.makedirs(fake)
with open(os.path.join(fake, "cv2.py"), "w") as f:
    f.write('raise ImportError("simulated for the test: no python3-opencv")\n')
env = dict(os.environ, PYTHONPATH=fake + os.pathsep + os.environ.get("PYTHONPATH", ""))


def tool(*args):
    p = subprocess.run([sys.executable, TOOL, "--rays-replay", RAYS_REPLAY, *args],
                       capture_output=True, text=True, env=env)
    print(f"$ rays-compare {' '.join(args)}  -> exit {p.returncode}")
    print(p.stdout + p.stderr)
    return p


check("the tool is executable", os.access(TOOL, os.X_OK))
p = subprocess.run([sys.executable, TOOL, "--help"], capture_output=True, text=True)
check("--help", p.returncode == 0 and "apt-get install python3-opencv" in p.stdout)

# The table.
ov = os.path.join(work, "overlay")
p = tool("--overlay", ov, seq)
check("exit 0 without OpenCV", p.returncode == 0)
lines = p.stdout.splitlines()
check("the one SKIPPED line for all OpenCV trackers", lines.count(NO_OPENCV) == 1)
check("no OpenCV rows", not any(f"| {t} " in p.stdout for t in ("CSRT", "KCF", "MOSSE")))
point_rows = [ln for ln in lines if ln.startswith("| disc ") and "rays (point)" in ln]
check("a rays (point) row with numbers", len(point_rows) == 1 and len(point_rows[0].split("|")) == 9)
box_rows = [ln for ln in lines if ln.startswith("| disc ") and "rays (box)" in ln]
check("a rays (box) row: scored, or saying the box start is not supported",
      len(box_rows) == 1 and (BOX_UNSUPPORTED in box_rows[0] or len(box_rows[0].split("|")) == 9))

# The overlay: the truth's tile and one per rays run that ran, 256 x 256 each, one row; every frame.
runs = 1 + (BOX_UNSUPPORTED not in (box_rows[0] if box_rows else BOX_UNSUPPORTED))
video = y4m.read(os.path.join(ov, "disc.y4m")) if os.path.exists(os.path.join(ov, "disc.y4m")) else None
check("overlay written", video is not None)
if video is not None:
    check("overlay size and frames", (video.width, video.height, len(video.frames)) == (256 * (1 + runs), 256, 12),
          f"{video.width}x{video.height}, {len(video.frames)} frames")

# --json, keeping the runs: the tool's numbers are the scorer's on the run it made.
keep = os.path.join(work, "runs")
p = tool("--json", "--work", keep, seq)
check("--json exit 0", p.returncode == 0)
try:
    out = json.loads(p.stdout)
except ValueError:
    out = {"results": [], "skipped": []}
    check("--json prints JSON", False)
check("--json: SKIPPED listed", out["skipped"] == [NO_OPENCV])
check("--json: SKIPPED on stderr", NO_OPENCV in p.stderr)
rows = {r["tracker"]: r for r in out["results"]}
check("--json: only rays rows", set(rows) <= {"rays-point", "rays-box"} and "rays-point" in rows)
truth = score.load_truth(seq)
for tid, r in rows.items():
    if r["status"] != "ok":
        check(f"{tid}: not run only as unsupported", tid == "rays-box" and r["note"] == BOX_UNSUPPORTED, r["note"])
        continue
    s = score.score(score.load_run(os.path.join(keep, "disc", tid + ".jsonl")), truth)
    for k in ("centre_in_box", "mask_iou", "lost", "median_us", "p99_us"):
        want = round(s[k], 1 if k.endswith("_us") else 3) if isinstance(s[k], float) else s[k]
        check(f"{tid} {k} is the scorer's", r[k] == want, f"{r[k]} / {want}")
    check(f"{tid} scored frames", r["frames"] == 12 and r["timed_frames"] == 12 and r["centre_in_box"] > 0,
          f"frames {r['frames']}, timed {r['timed_frames']}, centre_in_box {r['centre_in_box']}")

# The nudged starts: 13 runs, init and 1-3 px from it; the row holds their means, the note the worst.
# A wrapper in front of rays-replay notes each run's --init.
starts_log = os.path.join(work, "starts.log")
wrapper = os.path.join(work, "rays-replay-noting-starts")
with open(wrapper, "w") as f:
    f.write(f'#!/bin/sh\nprintf "%s\\n" "$*" >> "{starts_log}"\nexec "{os.path.abspath(RAYS_REPLAY)}" "$@"\n')
os.chmod(wrapper, 0o755)
keep = os.path.join(work, "nudged")
p = subprocess.run([sys.executable, TOOL, "--rays-replay", wrapper, "--json", "--work", keep, "--trackers",
                    "rays-point-nudged", seq], capture_output=True, text=True, env=env)
print(p.stdout + p.stderr)
check("nudged: exit 0", p.returncode == 0)
try:
    row = json.loads(p.stdout)["results"][0]
except (ValueError, IndexError, KeyError):
    row = {"status": "missing"}
check("nudged: a scored row", row.get("status") == "ok" and row.get("tracker") == "rays-point-nudged", str(row))
if row.get("status") == "ok":
    with open(starts_log) as f:
        inits = [line.split("--init ")[1].split()[0] for line in f if "--init " in line]
    check("nudged: 13 runs, each from its own start", len(inits) == 13 and len(set(inits)) == 13, str(inits))
    runs = [f"rays-point-nudged-{k}.jsonl" for k in range(13)]
    scores = [score.score(score.load_run(os.path.join(keep, "disc", f)), truth) for f in runs]
    mean = round(sum(x["centre_in_box"] for x in scores) / len(scores), 3)
    worst = round(min(x["centre_in_box"] for x in scores), 3)
    check("nudged: centre_in_box is the mean of the runs' scores", row["centre_in_box"] == mean, f"{row['centre_in_box']} / {mean}")
    check("nudged: the worst start's centre_in_box", row["worst_centre_in_box"] == worst, f"{row['worst_centre_in_box']} / {worst}")
p = tool("--trackers", "rays-point-nudged", seq)
check("nudged: the table's note names the worst start per sequence",
      "note: rays (point ±3): the mean of 13 starts" in p.stdout and "disc " in p.stdout.split("worst start's centre_in_box:")[-1])

fx.finish()
