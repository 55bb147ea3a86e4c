"""The ``Metaballs`` widget: one trait per setting of the figure's parameter table, synced both ways with a
``<metaballs-view>`` in the notebook's output, and the figure's statistics read back."""

from __future__ import annotations

import asyncio
import itertools

import anywidget
import traitlets

from ._parameters import PLANE_TABLE, STATIC, TABLE, Refused, check, older_names, shown

_ROWS = {row["python"]: row for row in TABLE}
_PLANE_ROWS = {row["python"]: row for row in PLANE_TABLE}
_OLDER = older_names()
_PLANE_OLDER = older_names(PLANE_TABLE)
_WASM = {
    "webgpu": "pkg/metaballs_bg.wasm",
    "webgl2": "pkg-webgl/metaballs_bg.wasm",
    "levels": "pkg-levels/metaballs_levels_bg.wasm",
}
MESH_FORMATS = ("stl", "obj", "ply")
CLIP_RATES = (24, 30, 60)


def _settings(rows: dict) -> dict:
    """One synced trait per parameter, its default and help from the table."""
    return {name: traitlets.Any(row["value"], help=row["description"]).tag(sync=True) for name, row in rows.items()}


def _checked(rows: dict):
    """The validator of the traits of `rows`: a value as the figure holds it, or the figure's refusal."""

    @traitlets.validate(*rows)
    def _check(self, proposal):
        row = rows[proposal["trait"].name]
        try:
            return check(row, proposal["value"])
        except Refused:
            raise _refusal(self, row, proposal) from None

    return _check


def _refusal(widget, row: dict, proposal) -> traitlets.TraitError:
    """A value the figure would refuse, said as the figure says it: name="text": why; keeping the value."""
    text = proposal["value"]
    text = ("true" if text else "false") if isinstance(text, bool) else text
    try:
        check(row, proposal["value"])
    except Refused as refused:
        return traitlets.TraitError(
            f'{row["name"]}="{text}": {refused}; keeping {shown(getattr(widget, proposal["trait"].name))}'
        )
    raise AssertionError("only a refused value has a refusal")


def _resolve(future, result) -> None:
    """Gives a waiting call its answer, unless it stopped waiting (it timed out)."""
    if not future.done():
        future.set_result(result)


class _Asking(anywidget.AnyWidget):
    """A widget whose figure answers what Python asks (``await w.save_scene()``), by message."""

    lang = traitlets.Unicode(
        "",
        help="The language the figure speaks, a tag such as 'de', 'ja' or 'pt-BR' (empty: the notebook "
        "page's). Its words only: settings, scene files and exports read the same in every language.",
    ).tag(sync=True)

    def __init__(self, **kwargs):
        super().__init__(**kwargs)
        self._calls = itertools.count(1)
        self._waiting: dict = {}
        self.on_msg(self._answer)

    async def _ask(self, method: str, *args, timeout: float = 60.0):
        """Asks the figure and waits for its answer: a value, bytes, or why it refused."""
        call = next(self._calls)
        answer = asyncio.get_running_loop().create_future()
        self._waiting[call] = answer
        try:
            self.send({"type": "call", "id": call, "method": method, "args": list(args)})
            content, buffers = await asyncio.wait_for(answer, timeout)
        except asyncio.TimeoutError:
            raise TimeoutError(
                f"the figure did not answer {method} in {timeout:g} s. It answers while a notebook shows it, "
                "and the kernel (ipykernel 7 or later) takes the answer in while this cell awaits it, unless "
                "cells queued after this one (Run All) are ahead of it: run this cell on its own, or ask in "
                "the notebook's last cell"
            ) from None
        finally:
            self._waiting.pop(call, None)
        if "error" in content:
            raise ValueError(content["error"])
        return bytes(buffers[0]) if content.get("bytes") else content.get("value")

    def _answer(self, _widget, content, buffers):
        """The figure answers what Python asked."""
        if isinstance(content, dict) and content.get("type") == "answer":
            answer = self._waiting.get(content.get("id"))
            if answer is not None:
                # The kernel may take the message in on another thread than the one whose loop awaits
                # the answer: it is resolved through that loop, which is woken for it.
                answer.get_loop().call_soon_threadsafe(_resolve, answer, (content, list(buffers or [])))


class _Figure(_Asking):
    _esm = STATIC / "widget.js"

    # What the figure reports (set by the figure; setting them from Python changes nothing).
    triangles = traitlets.Int(0, help="Triangles in the newest frame (``await w.stats()`` draws one).").tag(
        sync=True
    )
    fps = traitlets.Float(0.0, help="Frames drawn per second.").tag(sync=True)
    adapter = traitlets.Unicode("", help="What the figure draws with (WebGPU's adapter, or WebGL2).").tag(sync=True)

    def __init__(self, **kwargs):
        # Older spellings (``balls=``, ``mesher=``) are the settings' current names.
        kwargs = {_OLDER.get(name, name): value for name, value in kwargs.items()}
        super().__init__(**kwargs)

    # What the figure in the notebook's output is asked: awaited (``await w.save_scene()``), so that the
    # kernel takes in the figure's answer while the cell waits for it.

    async def stats(self) -> dict:
        """The statistics of a frame drawn for the call (with the settings set before it): ``triangles``,
        ``fps``, ``frame_time`` (ms), ``adapter``, ``mesher`` and ``overflowed``. The figure draws that frame
        even while it is scrolled out of view or paused, so a notebook run from the top reads real counts."""
        reported = await self._ask("nextFrame")
        names = {"frameTime": "frame_time"}
        stats = {names.get(key, key): value for key, value in reported.items()}
        self.triangles, self.adapter = int(stats.get("triangles", 0)), str(stats.get("adapter", ""))
        return stats

    async def save_scene(self) -> str:
        """The scene (spheres and every setting of the picture) as the figure's JSON document."""
        return await self._ask("saveScene")

    async def load_scene(self, text: str) -> None:
        """Loads a scene document; raises ``ValueError`` with what is wrong, keeping the scene."""
        await self._ask("loadScene", str(text))

    async def export_mesh(self, format: str = "stl") -> bytes:
        """The current frame's mesh as the bytes of a ``stl``, ``obj`` or ``ply`` file."""
        if format not in MESH_FORMATS:
            raise ValueError(f"format must be one of {', '.join(MESH_FORMATS)}, got {format!r}")
        return await self._ask("exportMesh", format)

    async def critical_points(self) -> dict:
        """The field's critical points for the spheres now (found with proof): ``points`` (``position``,
        ``value`` = the iso level at which the surface passes through it, ``index``, ``role``: join, loop,
        hole, cavity, fill or birth), the merge ``tree``, the ``bands`` between critical levels with their
        ``blobs``, ``cavities`` and ``genus``, and ``counts`` at the figure's iso level."""
        return await self._ask("criticalPoints")

    async def picture(self, scale: float = 1.0) -> bytes:
        """A PNG of the view at the figure's size times ``scale`` (show it with ``IPython.display.Image``)."""
        return await self._ask("picture", float(scale))

    async def record(
        self,
        seconds: float = 4.0,
        fps: int = 30,
        width: int | None = None,
        height: int | None = None,
        format: str | None = None,
    ) -> bytes:
        """A clip of the figure's animation, made in the browser frame by frame (each 1/``fps`` of
        animation after the last, however long it takes to draw), as file bytes: ``format`` ``"webm-vp9"``,
        ``"webm-vp8"``, ``"mp4-h264"`` (where the browser encodes them) or ``"gif"``; by default the first
        the browser writes. ``width`` and ``height`` default to the figure's size. The figure's spheres
        are back where they were afterwards. (``metaballs record`` makes GIF and APNG clips without a
        browser.)"""
        if fps not in CLIP_RATES:
            raise ValueError(f"fps must be one of {', '.join(map(str, CLIP_RATES))}, got {fps!r}")
        if not 0.1 <= float(seconds) <= 60:
            raise ValueError(f"seconds must be a number from 0.1 to 60, got {seconds!r}")
        options = {"seconds": float(seconds), "fps": int(fps)}
        for name, value in (("width", width), ("height", height), ("format", format)):
            if value is not None:
                options[name] = value
        # Drawing and encoding take about a second of the browser's time per second of clip, or more.
        return await self._ask("record", options, timeout=120.0 + 30.0 * float(seconds))

    _check = _checked(_ROWS)

    def _answer(self, _widget, content, buffers):
        """The figure asks for a build's WebAssembly (once per page: it is sent as a binary buffer), or
        answers what Python asked."""
        if isinstance(content, dict) and content.get("type") == "wasm" and content.get("build") in _WASM:
            data = (STATIC / _WASM[content["build"]]).read_bytes()
            self.send({"type": "wasm", "build": content["build"]}, [data])
        else:
            super()._answer(_widget, content, buffers)


def _older(new: str) -> property:
    """An older spelling of a setting, read and set as the setting itself."""
    return property(lambda self: getattr(self, new), lambda self, value: setattr(self, new, value))


Metaballs = type(
    "Metaballs",
    (_Figure,),
    {
        **_settings(_ROWS),
        **{old: _older(new) for old, new in _OLDER.items()},
        "__doc__": "Merging spheres drawn with marching cubes, as a widget: "
        "``Metaballs(spheres=2, iso=1)``. Every setting of the figure is a trait, synced both ways.",
        "__module__": __name__,
    },
)


class _Plane(_Asking):
    _esm = STATIC / "widget-2d.js"

    def __init__(self, **kwargs):
        # Older spellings (``levels=``) are the settings' current names.
        kwargs = {_PLANE_OLDER.get(name, name): value for name, value in kwargs.items()}
        super().__init__(**kwargs)

    async def contours(self) -> dict:
        """The contour at the iso level as data: ``iso``, ``cells``, ``rings`` (closed lists of points in
        the box [-1, 1]², the inside on their left), ``saddles``, ``crossings`` and each square's case."""
        return await self._ask("contours")

    async def svg(self, size: int = 640) -> str:
        """The picture as an SVG document: vector, for notes and print."""
        return await self._ask("toSVG", int(size))


    _check = _checked(_PLANE_ROWS)


Metaballs2d = type(
    "Metaballs2d",
    (_Plane,),
    {
        **_settings(_PLANE_ROWS),
        **{old: _older(new) for old, new in _PLANE_OLDER.items()},
        "__doc__": "Marching squares over circles, as a widget: ``Metaballs2d(circles='0.3,0.1,0.35;-0.35,-0.2,0.3', "
        "saddle='decider')``. Every setting of the 2D figure is a trait, synced both ways.",
        "__module__": __name__,
    },
)
