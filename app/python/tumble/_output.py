"""What render(output=...) wrote, shown inline in Jupyter: a video plays, a GIF or a still shows,
PNG frames show their first and last frame."""
from __future__ import annotations

import base64
import glob
import html
import os
import re
from typing import List

# Larger files are linked, not embedded: a notebook carries its outputs in its own file.
EMBED_LIMIT = 64 << 20

_TYPES = {".mp4": ("video", "video/mp4"), ".webm": ("video", "video/webm"),
          ".gif": ("image", "image/gif"), ".png": ("image", "image/png")}


class Output(os.PathLike):
    """A file (or PNG frames) that tumble.render wrote.

    path: the output as the command line names it ("flip.mp4", "frames/%06d.png", or "null");
    frames: how many frames it holds; notes: what the command line prints as "tumble: note:";
    diverged: for compare=, each integrator that diverged, with its message. os.fspath(output)
    is the path; in Jupyter it displays itself (a video plays, an image shows).
    """

    def __init__(self, path: str, frames: int, notes: List[str], diverged: List[str]) -> None:
        self.path = path
        self.frames = frames
        self.notes = list(notes)
        self.diverged = list(diverged)

    def __fspath__(self) -> str:
        return self.path

    def __repr__(self) -> str:
        return "<tumble.Output %s: %d frame%s>" % (self.path, self.frames,
                                                    "" if self.frames == 1 else "s")

    def files(self) -> List[str]:
        """The files written: one, or a PNG sequence's frames in order (none for null)."""
        if "%" in self.path:
            pattern = re.sub(r"%0?\d*d", "*", self.path)
            return sorted(glob.glob(pattern))
        return [self.path] if os.path.isfile(self.path) else []

    def _embedded(self, path: str) -> str:
        kind, mime = _TYPES.get(os.path.splitext(path)[1].lower(), (None, None))
        if kind is None:
            return ""
        if os.path.getsize(path) > EMBED_LIMIT:
            return '<a href="%s">%s</a>' % (html.escape(path), html.escape(path))
        data = base64.b64encode(open(path, "rb").read()).decode("ascii")
        if kind == "video":
            return ('<video controls autoplay loop muted playsinline style="max-width:100%%">'
                    '<source src="data:%s;base64,%s" type="%s"></video>' % (mime, data, mime))
        return '<img style="max-width:100%%" src="data:%s;base64,%s"/>' % (mime, data)

    def _repr_html_(self) -> str:
        files = self.files()
        caption = "<div><code>%s</code>: %d frame%s</div>" % (
            html.escape(self.path), self.frames, "" if self.frames == 1 else "s")
        if len(files) > 1:  # a PNG sequence: its first and last frame
            return caption + self._embedded(files[0]) + self._embedded(files[-1])
        return caption + "".join(self._embedded(f) for f in files)
