#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""rays-compare's variants (tools/rays_compare/variants.py) of a sequence this test writes: played
backwards, at every 2nd frame, without its chroma, to its end and back and mirrored, the ground truth
moved with the frames, the reversed start at the last frame's mask's deepest point; and the tool running them
(--variants) beside the folder itself.

usage: test_rays_compare_variants.py REPO_DIR RAYS_REPLAY
"""
import json
import os
import subprocess
import sys

REPO, RAYS_REPLAY = sys.argv[1], sys.argv[2]
sys.path.insert(0, os.path.join(REPO, "tools"))
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from rays_compare import score, variants, y4m  # noqa: E402
import rays_compare_fixture as fx  # noqa: E402

check = fx.check
work = fx.work_folder("test-rays-compare-variants-")

# An L whose box's centre lies outside it: a vertical arm 30 px wide (x 10..39, y 10..99) and a
# horizontal one 14 px tall (x 10..99, y 86..99). Its deepest point is on the wide arm's middle line.
mask = bytearray(fx.rect_mask(10, 10, 39, 99))
for y in range(86, 100):
    mask[y * fx.W + 10:y * fx.W + 100] = b"\xff" * 90
point = variants.deepest_point(mask, fx.W, fx.H)
check("the L's deepest point lies on its wide arm's middle line", point is not None and 24 <= point[0] <= 25
      and 24 <= point[1] <= 85, f"{point}")
check("an empty mask has no deepest point", variants.deepest_point(bytearray(fx.W * fx.H), fx.W, fx.H) is None)

# A disc moving 2 px right a frame over 7 frames; frame i's luma carries its index in pixel (0, 0).
seq = os.path.join(work, "disc")
meta = fx.moving_disc(seq, frames=7, radius=12, start=(40, 60), step=(2, 0))
video = y4m.read(os.path.join(seq, "seq.y4m"))
frames = [bytearray(f[0]) for f in video.frames]
for i, f in enumerate(frames):
    f[0] = i
fx.write_sequence(seq, frames, [(f[1], f[2]) for f in video.frames],
                  [m[0] for m in y4m.read(os.path.join(seq, "masks.y4m")).frames],
                  score.load_truth(seq).boxes, meta)
boxes = score.load_truth(seq).boxes

rev = variants.derive(seq, "reversed", os.path.join(work, "variants"))
check("the reversed folder is named after the kind", os.path.basename(rev) == "disc-reversed", rev)
r = y4m.read(os.path.join(rev, "seq.y4m"))
check("reversed: the frames backwards", [f[0][0] for f in r.frames] == [6, 5, 4, 3, 2, 1, 0],
      f"{[f[0][0] for f in r.frames]}")
check("reversed: the chroma moves with its luma", r.frames[0][1:] == video.frames[6][1:])
rboxes = score.load_truth(rev).boxes
check("reversed: frame k's box is frame 6 - k's", all(rboxes[k] == boxes[6 - k] for k in range(7)))
rmasks = y4m.read(os.path.join(rev, "masks.y4m"))
check("reversed: the masks backwards", rmasks.frames[0][0][60 * fx.W + 52] == 255 and rmasks.frames[0][0][60 * fx.W + 38] == 0)
rmeta = json.load(open(os.path.join(rev, "meta.json")))
check("reversed: starts at the last frame's disc centre (its mask's deepest point)", rmeta["init"] == [52, 60], f"{rmeta['init']}")
b6 = boxes[6]
check("reversed: init_box is the last frame's box", rmeta["init_box"] == [b6[0], b6[1], b6[2] - b6[0], b6[3] - b6[1]],
      f"{rmeta['init_box']}")
check("reversed: frame count and origin", rmeta["frames"] == 7 and rmeta["derived_from"] == "disc")

two = variants.derive(seq, "every-2nd", os.path.join(work, "variants"))
t = y4m.read(os.path.join(two, "seq.y4m"))
check("every-2nd: frames 0, 2, 4, 6", [f[0][0] for f in t.frames] == [0, 2, 4, 6], f"{[f[0][0] for f in t.frames]}")
check("every-2nd: half the frame rate", t.fps == (30, 2), f"{t.fps}")
tboxes = score.load_truth(two).boxes
check("every-2nd: frame k's box is frame 2k's", all(tboxes[k] == boxes[2 * k] for k in range(4)))
tmeta = json.load(open(os.path.join(two, "meta.json")))
check("every-2nd: the sequence's own start", tmeta["init"] == meta["init"] and tmeta["init_box"] == meta["init_box"])

grey = variants.derive(seq, "grey", os.path.join(work, "variants"))
g = y4m.read(os.path.join(grey, "seq.y4m"))
check("grey: mono, the same frames' luma", g.colour == "mono" and [f[0] for f in g.frames] == [bytes(f) for f in frames]
      and all(len(f) == 1 for f in g.frames), f"{g.colour}, {len(g.frames)} frames")
check("grey: the frame rate and the ground truth unchanged", g.fps == video.fps and score.load_truth(grey).boxes == boxes)
gmeta = json.load(open(os.path.join(grey, "meta.json")))
check("grey: the sequence's own start", gmeta["init"] == meta["init"] and gmeta["init_box"] == meta["init_box"]
      and gmeta["name"] == "disc-grey")

back = variants.derive(seq, "there-and-back", os.path.join(work, "variants"))
b = y4m.read(os.path.join(back, "seq.y4m"))
check("there-and-back: frames 0 … 6, then 5 … 0", [f[0][0] for f in b.frames] == [0, 1, 2, 3, 4, 5, 6, 5, 4, 3, 2, 1, 0],
      f"{[f[0][0] for f in b.frames]}")
check("there-and-back: the chroma moves with its luma", b.frames[8][1:] == video.frames[4][1:])
bboxes = score.load_truth(back).boxes
check("there-and-back: frame k's box is frame 12 - k's on the way back",
      all(bboxes[k] == boxes[k] for k in range(7)) and all(bboxes[k] == boxes[12 - k] for k in range(7, 13)))
bmasks = y4m.read(os.path.join(back, "masks.y4m"))
check("there-and-back: the masks moved with the frames", len(bmasks.frames) == 13 and bmasks.frames[12] == bmasks.frames[0]
      and bmasks.frames[7] == bmasks.frames[5])
bmeta = json.load(open(os.path.join(back, "meta.json")))
check("there-and-back: the sequence's own start, 13 frames", bmeta["init"] == meta["init"] and
      bmeta["init_box"] == meta["init_box"] and bmeta["frames"] == 13 and bmeta["name"] == "disc-there-and-back")

mir = variants.derive(seq, "mirrored", os.path.join(work, "variants"))
mv = y4m.read(os.path.join(mir, "seq.y4m"))
check("mirrored: the same frames in order, each row reversed",
      len(mv.frames) == 7 and all(mv.frames[i][0][fx.W - 1] == i for i in range(7))
      and mv.frames[3][0][40 * fx.W + 5] == video.frames[3][0][40 * fx.W + fx.W - 1 - 5], f"{len(mv.frames)} frames")
cw = mv.chroma_size[0]
check("mirrored: the chroma rows reversed with their luma",
      mv.colour == video.colour and mv.frames[2][1][10 * cw + 3] == video.frames[2][1][10 * cw + cw - 1 - 3]
      and mv.frames[2][2][30 * cw] == video.frames[2][2][30 * cw + cw - 1])
mmasks = y4m.read(os.path.join(mir, "masks.y4m"))
# Frame 6's disc is centred at x = 52, so the mirrored one at 127 - 52 = 75.
check("mirrored: the masks mirrored", mmasks.frames[6][0][60 * fx.W + 75] == 255 and mmasks.frames[6][0][60 * fx.W + 52] == 0
      and mmasks.frames[6][0][60 * fx.W + 75 + 12] == 255 and mmasks.frames[6][0][60 * fx.W + 75 + 13] == 0)
mboxes = score.load_truth(mir).boxes
check("mirrored: frame k's box is frame k's mirrored about x = 63.5",
      all(mboxes[k] == (fx.W - 1 - boxes[k][2], boxes[k][1], fx.W - 1 - boxes[k][0], boxes[k][3]) for k in range(7)),
      f"{mboxes[6]} against {boxes[6]}")
mmeta = json.load(open(os.path.join(mir, "meta.json")))
check("mirrored: the start mirrored (the disc's centre and its box)",
      mmeta["init"] == [fx.W - 1 - meta["init"][0], meta["init"][1]]
      and mmeta["init_box"] == [mboxes[0][0], mboxes[0][1], mboxes[0][2] - mboxes[0][0], mboxes[0][3] - mboxes[0][1]]
      and mmeta["name"] == "disc-mirrored", f"{mmeta['init']}, {mmeta['init_box']}")

os.remove(os.path.join(seq, "boxes.csv"))
try:
    variants.derive(seq, "reversed", os.path.join(work, "none"))
    check("reversed without boxes.csv is refused", False)
except ValueError as e:
    check("reversed without boxes.csv is refused, saying why", "boxes.csv" in str(e), str(e))
# The tool still compares the folder itself, and reports the variant it could not make as a failed row.
p = subprocess.run([sys.executable, os.path.join(REPO, "tools", "rays-compare"), "--rays-replay", RAYS_REPLAY,
                    "--trackers", "rays-point", "--variants", "reversed", "--json", seq], capture_output=True, text=True)
try:
    rows = {row["sequence"]: row for row in json.loads(p.stdout)["results"]}
except ValueError:
    rows = {}
check("without boxes.csv: the folder compared, the reversed variant a failed row, exit 1",
      p.returncode == 1 and rows.get("disc", {}).get("status") == "ok"
      and rows.get("disc-reversed", {}).get("status") == "failed" and "boxes.csv" in rows["disc-reversed"]["note"],
      f"exit {p.returncode}, rows {sorted(rows)}")
fx.write_sequence(seq, frames, [(f[1], f[2]) for f in video.frames],
                  [m[0] for m in y4m.read(os.path.join(seq, "masks.y4m")).frames], boxes, meta)

# The tool: the folder and its five variants, each scored (the disc is easy: tracked in every frame).
p = subprocess.run([sys.executable, os.path.join(REPO, "tools", "rays-compare"), "--rays-replay", RAYS_REPLAY,
                    "--trackers", "rays-point", "--variants", "reversed,every-2nd,grey,there-and-back,mirrored", "--json", seq],
                   capture_output=True, text=True)
check("rays-compare --variants exits 0", p.returncode == 0, "" if p.returncode == 0 else p.stderr.strip()[-300:])
try:
    rows = json.loads(p.stdout)["results"]
except ValueError:
    rows = []
by_name = {row["sequence"]: row for row in rows}
check("rows for the folder and its five variants",
      sorted(by_name) == ["disc", "disc-every-2nd", "disc-grey", "disc-mirrored", "disc-reversed", "disc-there-and-back"],
      f"{sorted(by_name)}")
for name, row in sorted(by_name.items()):
    check(f"{name}: the disc's centre in its box in every frame", row.get("centre_in_box") == 1.0,
          f"{row.get('centre_in_box')}")
bad = subprocess.run([sys.executable, os.path.join(REPO, "tools", "rays-compare"), "--variants", "sideways", seq],
                     capture_output=True, text=True)
unknown = bad.returncode == 2 and "--variants: unknown sideways" in bad.stderr
check("an unknown variant is a usage error", unknown, "" if unknown else bad.stderr.strip()[-200:])

fx.finish()
