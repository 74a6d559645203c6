# SPDX-License-Identifier: Apache-2.0
"""rays-compare: the Active Rays tracker (rays-replay) beside OpenCV's CSRT, KCF and MOSSE on sequence folders,
all scored by one scorer (score.py). See tools/rays-compare --help."""
import argparse
import json
import os
import shutil
import subprocess
import sys
import tempfile

from . import overlay, score, variants, y4m

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))
DEFAULT_RAYS_REPLAY = os.path.join(REPO, "build", "release", "tools", "rays-replay", "rays-replay")
OPENCV_RUN = os.path.join(HERE, "opencv_run.py")
NO_OPENCV = "SKIPPED: OpenCV trackers: python3-opencv is not installed (apt-get install python3-opencv)"
PROC = 128  # rays-replay's processing frame (kFrameSize)

# id -> (table label, overlay label, kind)
TRACKERS = {
    "rays-point": ("rays (point)", "rays pt", "rays"),
    "rays-box": ("rays (box)", "rays box", "rays"),
    "rays-point-nudged": ("rays (point ±3)", "", "rays"),
    "rays-box-nudged": ("rays (box ±3)", "", "rays"),
    "csrt": ("CSRT", "csrt", "opencv"),
    "kcf": ("KCF", "kcf", "opencv"),
    "mosse": ("MOSSE", "mosse", "opencv"),
}
DEFAULT_TRACKERS = ["rays-point", "rays-box", "csrt", "kcf", "mosse"]
BOX_UNSUPPORTED = "box start not supported by this rays-replay"
# A user's click (or box) lands a few pixels from where the sequence's author put it: the nudged rows
# start the rays from init and from 12 starts round it, in the sequence's pixels, and report the mean.
NUDGES = [(0, 0), (1, 0), (-1, 0), (0, 1), (0, -1), (2, 2), (-2, 2), (2, -2), (-2, -2), (3, 0), (-3, 0), (0, 3), (0, -3)]

DESCRIPTION = """\
Runs the Active Rays tracker (rays-replay) and OpenCV's CSRT, KCF and MOSSE on each sequence folder and
scores every run with one scorer (tools/rays_compare/score.py): one table, sequence x tracker.

A sequence folder holds seq.y4m (YUV4MPEG2; 8-bit mono, 4:2:0, 4:2:2 or 4:4:4, full-range colour as
C420jpeg) and meta.json with "init_box": [x, y, w, h] (the target's box in the first frame) and
optionally "init": [x, y] (a point inside it; the box's centre otherwise), in the sequence's pixels with
pixel centres at integers; boxes.csv (frame,x0,y0,x1,y1: box edges) and masks.y4m (255 = target) are
the ground truth where there is one (../shared/realset has six such folders). Without ground truth only
losses and times are measured; --overlay shows the runs side by side to look at (for any folder).

  tools/rays-compare ../shared/realset/*
  tools/rays-compare --overlay /tmp/overlay --trackers rays-point,csrt MY_SEQ
  tools/rays-compare --variants reversed,every-2nd --trackers rays-point,rays-box,csrt ../shared/realset/*

Trackers (--trackers):
  rays-point  rays-replay --init X,Y from "init" (a user's click)
  rays-box    rays-replay --init X,Y,W,H from "init_box" (a rays-replay that refuses it gets the
              row "box start not supported by this rays-replay")
  rays-point-nudged, rays-box-nudged  (not in the default) the same from 13 starts: init, and moved by
              1 px along each axis, 2 px along both, 3 px along each; each measure is the mean over
              the 13 runs (times: of their medians and p99s), and a note gives the worst
              centre_in_box. How much the outcome hangs on the exact click.
  csrt, kcf   cv2.TrackerCSRT_create, cv2.TrackerKCF_create  } started on "init_box", on the same
  mosse       cv2.legacy.TrackerMOSSE_create                 } frames converted to BGR
With --variants, each folder is also compared as it is played backwards (NAME-reversed: started from
its last frame, "init" at that frame's mask's deepest point, or its box's centre) and at every 2nd frame
(NAME-every-2nd: twice the motion per frame), the ground truth moved with the frames, and without its
chroma (NAME-grey: what a mono camera gives), played to its end and back (NAME-there-and-back:
twice as long, the target turning back where the footage ends), and flipped left to right
(NAME-mirrored: the same motion the other way round). They are written under --work, or a
temporary folder (tools/rays_compare/variants.py): a change tuned to the footage as it was recorded
shows there.

The sequence is given to rays-replay as it is (it scales to 128x128 itself); X,Y and the box are mapped
to its processing pixels, its contours back through its header's scale and offset.

Measures (score.py; ../shared/tools/score-real.py's definitions where both measure the same):
  centre_in_box  share of the frames of boxes.csv whose contour centroid (mean of its points) or box
                 centre lies in the ground-truth box; frames where the tracker does not report
                 tracking count as misses
  mask_iou       mean IoU against masks.y4m of the contour's polygon, or the box, filled at pixel
                 centres; 0 where not tracking ("-" without masks)
  lost           times tracking stopped (rays: the state leaves "tracking"; OpenCV: update() says false)
  median_us, p99_us  time per frame: rays-replay's own time_us per record (every frame, the start
                 frame too), OpenCV's update() call (init() not counted); one percentile function
                 (linear between closest ranks) for all

OpenCV comes from Debian's python3-opencv (apt-get install python3-opencv), only for this benchmark: it
is not a dependency of raysd and tools/install-deps does not install it. The OpenCV runs use the first
Python that imports cv2 among --opencv-python, this one and /usr/bin/python3; without one they are
skipped (the rays runs are still scored).

Exit status: 0 when every run that could run ran, 1 when one failed, 2 for bad arguments.
"""


def parse_args(argv):
    ap = argparse.ArgumentParser(prog="rays-compare", description=DESCRIPTION,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("sequences", nargs="+", metavar="SEQ_DIR", help="sequence folders (others are ignored, saying so)")
    ap.add_argument("--rays-replay", default=DEFAULT_RAYS_REPLAY, metavar="PATH",
                    help="the rays-replay binary (default: build/release/tools/rays-replay/rays-replay in this checkout)")
    ap.add_argument("--trackers", default=",".join(DEFAULT_TRACKERS), metavar="LIST",
                    help="comma-separated, from " + ", ".join(TRACKERS) + " (default: " + ",".join(DEFAULT_TRACKERS) + ")")
    ap.add_argument("--json", action="store_true", help="print the results as one JSON object instead of the table")
    ap.add_argument("--overlay", metavar="DIR",
                    help="write DIR/SEQUENCE.y4m per sequence: the trackers side by side, contour or box drawn")
    ap.add_argument("--overlay-scale", type=int, default=2, metavar="N", help="tile enlargement (default 2)")
    ap.add_argument("--work", metavar="DIR", help="keep each run's JSON Lines as DIR/SEQUENCE/TRACKER.jsonl")
    ap.add_argument("--variants", default="", metavar="LIST",
                    help="also each folder played backwards, at every 2nd frame or without its chroma: "
                         "comma-separated, from " + ", ".join(variants.KINDS) + " (reversed needs boxes.csv)")
    ap.add_argument("--opencv-python", metavar="PATH", help="the Python with python3-opencv for the OpenCV runs")
    ap.add_argument("--opencv-threads", type=int, default=1, metavar="N",
                    help="cv2.setNumThreads for the OpenCV runs (default 1: one core, as the tracker; -1 leaves OpenCV's default)")
    args = ap.parse_args(argv)
    chosen = [t.strip() for t in args.trackers.split(",") if t.strip()]
    bad = [t for t in chosen if t not in TRACKERS]
    if bad or not chosen:
        ap.error(f"--trackers: unknown {', '.join(bad) or '(none given)'}; choose from {', '.join(TRACKERS)}")
    args.trackers = chosen
    args.variants = [v.strip() for v in args.variants.split(",") if v.strip()]
    bad = [v for v in args.variants if v not in variants.KINDS]
    if bad:
        ap.error(f"--variants: unknown {', '.join(bad)}; choose from {', '.join(variants.KINDS)}")
    return args


def find_opencv(preferred):
    """(python, probe) for the first interpreter whose cv2 imports, else (None, last probe)."""
    candidates = [p for p in (preferred, sys.executable, "/usr/bin/python3") if p]
    seen, last = set(), {"cv2": None, "error": "no Python to try", "trackers": {}}
    for py in candidates:
        key = os.path.realpath(py)
        if key in seen or not os.path.exists(py):
            continue
        seen.add(key)
        try:
            p = subprocess.run([py, OPENCV_RUN, "--probe"], capture_output=True, text=True, timeout=120)
            last = json.loads(p.stdout.strip().splitlines()[-1])
        except (OSError, ValueError, IndexError, subprocess.TimeoutExpired) as e:
            last = {"cv2": None, "error": f"{py}: {e}", "trackers": {}}
            continue
        if last.get("cv2"):
            return py, last
    return None, last


def load_meta(seq):
    with open(os.path.join(seq, "meta.json")) as f:
        meta = json.load(f)
    box = meta.get("init_box")
    point = meta.get("init")
    if box is not None and (len(box) != 4 or box[2] <= 0 or box[3] <= 0):
        raise ValueError(f"meta.json: init_box must be [x, y, w, h] with w, h > 0, not {box}")
    if point is not None and len(point) != 2:
        raise ValueError(f"meta.json: init must be [x, y], not {point}")
    if box is None and point is None:
        raise ValueError("meta.json has neither init_box [x, y, w, h] nor init [x, y]")
    return meta, ([float(v) for v in box] if box else None), ([float(v) for v in point] if point else None)


def to_proc(w, h):
    """Sequence pixel -> rays-replay processing pixel (the inverse of its header's scale and offset)."""
    sx, sy = w / PROC, h / PROC
    ox, oy = (sx - 1) / 2, (sy - 1) / 2
    return lambda x, y: ((x - ox) / sx, (y - oy) / sy), (sx, sy)


def fmt(v):
    return f"{v:.2f}"


def run_rays(binary, video_path, init, out):
    """(status, note): ok | unsupported | failed."""
    cmd = [binary, "--input", video_path, "--init", ",".join(fmt(v) for v in init), "--out", out]
    try:
        p = subprocess.run(cmd, capture_output=True, text=True)
    except OSError as e:
        return "failed", f"rays-replay did not start: {e}"
    if p.returncode == 0:
        return "ok", ""
    first = (p.stderr.strip().splitlines() or [f"exit {p.returncode}"])[0]
    # An older rays-replay knows only --init X,Y and refuses four numbers as a bad argument (exit 2).
    if len(init) == 4 and p.returncode == 2 and "--init" in first and "W" not in first.split("not '")[0]:
        return "unsupported", BOX_UNSUPPORTED
    return "failed", f"rays-replay exit {p.returncode}: {first}"


def run_nudged(binary, video_path, start, out, truth, row):
    """The rays from each of NUDGES' starts, scored; `row` gets the means and the worst centre_in_box."""
    scores = []
    for k, (dx, dy) in enumerate(NUDGES):
        path = f"{out[:-len('.jsonl')]}-{k}.jsonl"
        status, note = run_rays(binary, video_path, start(dx, dy), path)
        if status != "ok":
            return status, note
        scores.append(score.score(score.load_run(path), truth))
    means = {}
    for key, v in scores[0].items():
        values = [s[key] for s in scores]
        if all(x == v for x in values):  # the same for every start (the frame counts): as it is
            means[key] = v
        else:
            means[key] = None if any(x is None for x in values) else sum(values) / len(values)
    row.update(rounded(means))
    if row.get("centre_in_box") is not None:
        worst = min(s["centre_in_box"] for s in scores)
        row["worst_centre_in_box"] = round(worst, 3)
    return "ok", ""


def run_opencv(python, tracker, video_path, box, out, threads):
    cmd = [python, OPENCV_RUN, "--tracker", tracker, "--input", video_path,
           "--box", ",".join(repr(v) for v in box), "--out", out, "--threads", str(threads)]
    p = subprocess.run(cmd, capture_output=True, text=True)
    if p.returncode == 0:
        return "ok", ""
    lines = p.stderr.strip().splitlines() or [f"exit {p.returncode}"]
    return "failed", f"OpenCV {tracker} failed: {lines[-1]}"


def rounded(measures):
    out = {}
    for k, v in measures.items():
        if isinstance(v, float):
            v = round(v, 1) if k.endswith("_us") else round(v, 3)
        out[k] = v
    return out


def compare_sequence(seq, args, work, opencv_py, opencv_ok, log):
    """Rows for one sequence folder, and the overlay if asked."""
    name = os.path.basename(os.path.normpath(seq))
    video_path = os.path.join(seq, "seq.y4m")
    meta, box, point = load_meta(seq)
    video = y4m.read(video_path)
    truth = score.load_truth(seq, shape=(video.width, video.height, len(video.frames)))
    proc, (sx, sy) = to_proc(video.width, video.height)
    os.makedirs(os.path.join(work, name), exist_ok=True)
    rows, runs = [], []
    for tid in args.trackers:
        label, short, kind = TRACKERS[tid]
        row = {"sequence": name, "tracker": tid, "label": label, "status": "ok", "note": ""}
        rows.append(row)
        out = os.path.join(work, name, tid + ".jsonl")
        if kind == "rays":
            if tid.startswith("rays-point"):
                if point is None:
                    point = [box[0] + box[2] / 2, box[1] + box[3] / 2]
                    row["note"] = "started at init_box's centre (meta.json has no init)"
                start = lambda dx, dy: list(proc(point[0] + dx, point[1] + dy))
            else:
                if box is None:
                    row.update(status="skipped", note="meta.json has no init_box")
                    continue
                # A box's edges scale as lengths: covering pixels x .. x+w-1, its left edge lies at
                # x - 0.5 in centre coordinates, which maps to x/sx - 0.5 in processing pixels.
                start = lambda dx, dy: [(box[0] + dx) / sx, (box[1] + dy) / sy, box[2] / sx, box[3] / sy]
            log(f"{name}: {label}")
            if tid.endswith("-nudged"):
                status, note = run_nudged(args.rays_replay, video_path, start, out, truth, row)
                if status != "ok":
                    row.update(status=status, note=note)
                continue
            status, note = run_rays(args.rays_replay, video_path, start(0, 0), out)
        else:
            if not opencv_ok.get(tid, False):
                row.update(status="skipped", note=opencv_ok.get(tid + ":why", "OpenCV is not available"))
                continue
            if box is None:
                row.update(status="skipped", note="meta.json has no init_box")
                continue
            log(f"{name}: {label}")
            status, note = run_opencv(opencv_py, tid, video_path, box, out, args.opencv_threads)
        if status != "ok":
            row.update(status=status, note=note)
            continue
        run = score.load_run(out)
        row.update(rounded(score.score(run, truth)))
        runs.append((short, run, list(TRACKERS).index(tid)))
    if args.overlay:
        os.makedirs(args.overlay, exist_ok=True)
        path = os.path.join(args.overlay, name + ".y4m")
        log(f"{name}: overlay -> {path}")
        overlay.write(path, video, runs, truth, scale=args.overlay_scale)
        for r in rows:
            r.setdefault("overlay", path)
    return rows


def cell(v, digits):
    if v is None:
        return "-"
    if isinstance(v, int):
        return str(v)
    return f"{v:.{digits}f}"


def table(rows):
    head = ["sequence", "tracker", "centre_in_box", "mask_iou", "lost", "median_us", "p99_us"]
    body = []
    for r in rows:
        if r["status"] != "ok":
            body.append([r["sequence"], r["label"], r["note"] or r["status"], "", "", "", ""])
        else:
            body.append([r["sequence"], r["label"], cell(r["centre_in_box"], 3), cell(r["mask_iou"], 3),
                         cell(r["lost"], 0), cell(r["median_us"], 0), cell(r["p99_us"], 0)])
    # widths from the rows that have numbers, so that a note does not stretch one column
    widths = [max([len(head[c])] + [len(b[c]) for b, r in zip(body, rows) if r["status"] == "ok" or c < 2])
              for c in range(len(head))]
    right = [False, False, True, True, True, True, True]

    def line(cells):
        out = []
        for c, v in enumerate(cells):
            out.append(v.rjust(widths[c]) if right[c] and len(v) <= widths[c] else v.ljust(widths[c]))
        return "| " + " | ".join(out) + " |"

    lines = [line(head), "| " + " | ".join(("-" * (w - 1) + ":") if right[c] else "-" * w
                                          for c, w in enumerate(widths)) + " |"]
    for b, r in zip(body, rows):
        if r["status"] != "ok":
            lines.append("| " + b[0].ljust(widths[0]) + " | " + b[1].ljust(widths[1]) + " | " + b[2] + " |")
        else:
            lines.append(line(b))
    return "\n".join(lines)


def failure_row(name, error, rows, log):
    """A folder that could not be compared: said on stderr and as a row of its own."""
    log(f"rays-compare: {name}: {error}")
    rows.append({"sequence": name, "tracker": "-", "label": "-", "status": "failed", "note": str(error)})


def compare_folder(seq, args, work, opencv_py, opencv_ok, shown, rows, log):
    """Appends one folder's rows; True when a run failed."""
    try:
        found = compare_sequence(seq, args, work, opencv_py, opencv_ok, log)
    except (OSError, ValueError, KeyError) as e:
        failure_row(os.path.basename(os.path.normpath(seq)), e, rows, log)
        return True
    rows.extend(r for r in found if r["tracker"] in shown)
    return any(r["status"] == "failed" for r in found)


def main(argv=None):
    args = parse_args(sys.argv[1:] if argv is None else argv)
    err = sys.stderr

    def log(msg):
        print(msg, file=err, flush=True)

    sequences, ignored = [], []
    for s in args.sequences:
        if not os.path.isdir(s):
            ignored.append((s, "not a folder"))
        elif not os.path.isfile(os.path.join(s, "seq.y4m")) or not os.path.isfile(os.path.join(s, "meta.json")):
            ignored.append((s, "no seq.y4m and meta.json in it"))
        else:
            sequences.append(s)
    for s, why in ignored:
        log(f"rays-compare: ignoring {s}: {why}")
    if not sequences:
        log("rays-compare: no sequence folders given (each needs seq.y4m and meta.json)")
        return 2
    wants_rays = any(TRACKERS[t][2] == "rays" for t in args.trackers)
    if wants_rays and not os.access(args.rays_replay, os.X_OK):
        log(f"rays-compare: no rays-replay at {args.rays_replay}: build it (cmake --build build/release) "
            "or pass --rays-replay PATH")
        return 2

    skipped = []
    opencv_ok, opencv_py, probe = {}, None, None
    wanted_cv = [t for t in args.trackers if TRACKERS[t][2] == "opencv"]
    if wanted_cv:
        opencv_py, probe = find_opencv(args.opencv_python)
        if opencv_py is None:
            skipped.append(NO_OPENCV)
            for t in wanted_cv:
                opencv_ok[t], opencv_ok[t + ":why"] = False, "python3-opencv is not installed"
        else:
            for t in wanted_cv:
                why = probe["trackers"].get(t)
                opencv_ok[t] = why is None
                if why:
                    opencv_ok[t + ":why"] = why
                    skipped.append(f"SKIPPED: OpenCV {TRACKERS[t][0]}: {why}")
        # the OpenCV rows that cannot run are left out of the table; the SKIPPED lines say why
    shown = [t for t in args.trackers if TRACKERS[t][2] == "rays" or opencv_ok.get(t)]

    work = args.work or tempfile.mkdtemp(prefix="rays-compare-")
    rows, failed = [], False
    try:
        for s in sequences:
            failed |= compare_folder(s, args, work, opencv_py, opencv_ok, shown, rows, log)
            for kind in args.variants:  # each written once, under the work folder
                try:
                    folder = variants.derive(s, kind, os.path.join(work, "variants"))
                except (OSError, ValueError, KeyError) as e:
                    failure_row(f"{os.path.basename(os.path.normpath(s))}-{kind}", e, rows, log)
                    failed = True
                    continue
                failed |= compare_folder(folder, args, work, opencv_py, opencv_ok, shown, rows, log)
    finally:
        if not args.work:
            shutil.rmtree(work, ignore_errors=True)

    opencv_info = None
    if wanted_cv:
        opencv_info = {"python": opencv_py, "version": probe.get("cv2"), "threads": args.opencv_threads,
                       "error": probe.get("error") if opencv_py is None else None}
    if args.json:
        for line in skipped:
            log(line)
        print(json.dumps({"rays_replay": os.path.abspath(args.rays_replay) if wants_rays else None,
                          "opencv": opencv_info, "skipped": skipped,
                          "ignored": [{"path": s, "why": w} for s, w in ignored], "results": rows}, indent=1))
    else:
        for line in skipped:
            print(line)
        if wants_rays:
            print(f"rays-replay: {os.path.abspath(args.rays_replay)}")
        if opencv_py:
            threads = "OpenCV's default threads" if args.opencv_threads < 0 else f"{args.opencv_threads} thread(s)"
            print(f"OpenCV: {probe.get('cv2')} ({opencv_py}, {threads})")
        print(table(rows))
        notes = sorted({(r["label"], r["note"]) for r in rows if r["status"] == "ok" and r["note"]})
        for label, note in notes:
            print(f"note: {label}: {note}")
        for tid in args.trackers:
            worst = [f"{r['sequence']} {r['worst_centre_in_box']:.3f}" for r in rows
                     if r["tracker"] == tid and r.get("worst_centre_in_box") is not None]
            if worst:
                print(f"note: {TRACKERS[tid][0]}: the mean of {len(NUDGES)} starts (init, and 1-3 px from it); "
                      f"the worst start's centre_in_box: {', '.join(worst)}")
    return 1 if failed else 0
