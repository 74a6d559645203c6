# SPDX-License-Identifier: Apache-2.0
"""YUV4MPEG2 reading and writing in pure Python (no numpy), for rays-compare's scorer and overlay.

A frame is a tuple of planes (Y, or Y, Cb, Cr), each a bytes object of row-major samples.
"""

_CHROMA = {  # colour-space tag -> (planes, chroma subsampling x, y)
    "mono": (1, 1, 1),
    "420": (3, 2, 2), "420jpeg": (3, 2, 2), "420mpeg2": (3, 2, 2), "420paldv": (3, 2, 2),
    "422": (3, 2, 1),
    "444": (3, 1, 1),
}


class Y4M:
    """A whole YUV4MPEG2 file in memory: width, height, colour tag, frames."""

    def __init__(self, width, height, colour, frames, fps=(30, 1)):
        self.width, self.height, self.colour, self.frames, self.fps = width, height, colour, frames, fps

    @property
    def chroma_size(self):
        _, sx, sy = _CHROMA[self.colour]
        return (self.width + sx - 1) // sx, (self.height + sy - 1) // sy


def read(path):
    with open(path, "rb") as f:
        data = f.read()
    head, sep, rest = data.partition(b"\n")
    if not sep or not head.startswith(b"YUV4MPEG2"):
        raise ValueError(f"{path}: not a YUV4MPEG2 file")
    tok = {t[:1].decode(): t[1:].decode() for t in head.split()[1:]}
    width, height = int(tok["W"]), int(tok["H"])
    colour = tok.get("C", "420jpeg")  # the format's default is 4:2:0 (JPEG siting)
    if colour not in _CHROMA:
        raise ValueError(f"{path}: colour space C{colour} is not supported (8-bit mono, 4:2:0, 4:2:2, 4:4:4 are)")
    fps = (30, 1)
    if "F" in tok and ":" in tok["F"]:
        num, den = tok["F"].split(":")
        fps = (int(num), int(den))
    planes, sx, sy = _CHROMA[colour]
    cw, ch = (width + sx - 1) // sx, (height + sy - 1) // sy
    sizes = [width * height] + [cw * ch] * (planes - 1)
    frames, pos = [], 0
    while pos < len(rest):
        nl = rest.index(b"\n", pos)
        if not rest.startswith(b"FRAME", pos):
            raise ValueError(f"{path}: frame {len(frames)} has no FRAME marker")
        pos = nl + 1
        frame = []
        for size in sizes:
            if pos + size > len(rest):
                raise ValueError(f"{path}: frame {len(frames)} is cut short")
            frame.append(rest[pos:pos + size])
            pos += size
        frames.append(tuple(frame))
    return Y4M(width, height, colour, frames, fps)


def write(path, width, height, frames, colour="420jpeg", fps=(30, 1)):
    """frames: iterable of plane tuples matching `colour`."""
    with open(path, "wb") as f:
        f.write(f"YUV4MPEG2 W{width} H{height} F{fps[0]}:{fps[1]} Ip A1:1 C{colour}\n".encode())
        for frame in frames:
            f.write(b"FRAME\n")
            for plane in frame:
                f.write(plane)
