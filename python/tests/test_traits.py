"""The widget's traits against the figure's parameter table: one trait per parameter with the table's
default, good values taken as the figure takes them, and bad ones refused with the figure's own words
(compared with the native command line, which reads parameters with the same Rust parser)."""

import asyncio
import json
import os
import pathlib
import subprocess

import pytest
import traitlets

from metaballs_widget import Metaballs, Metaballs2d
from metaballs_widget._parameters import PLANE_TABLE, STATIC, TABLE, Refused, attribute_text, check, read, trait_name

ROOT = pathlib.Path(__file__).resolve().parents[2]
CLI = os.environ.get("METABALLS_CLI", str(ROOT / "target" / "debug" / "metaballs"))

# Bad values of every kind Python checks itself.
BAD = [
    ("spheres", 0), ("spheres", 65), ("spheres", 2.5), ("spheres", -3), ("spheres", "many"), ("resolution", 4),
    ("iso", 30), ("iso", 0.01), ("iso", "high"), ("iso", float("nan")), ("speed", 1e39), ("yaw", 400),
    ("paused", "maybe"), ("color", "red"), ("color", "#12345"), ("display", "sketch"), ("theme", "sepia"),
    ("controls", "iso,volume"), ("hud", 3), ("max-pixel-ratio", 9), ("spot-angle", 0),
]


def cli_message(name, value):
    """What the Rust parser says about `name=value` (the command line prints it as `error: …`)."""
    result = subprocess.run(
        [CLI, "render", "--view", f"{name}={attribute_text(value)}", "--out", os.devnull],
        capture_output=True, text=True, timeout=60, env={**os.environ, "XDG_RUNTIME_DIR": "/tmp"},
    )
    assert result.returncode != 0, f"{name}={value!r} was accepted by the figure's parser"
    return result.stderr.strip().splitlines()[-1].removeprefix("error: ")


def test_the_table_is_the_one_the_build_wrote():
    written = json.loads((ROOT / "www" / "parameters.json").read_text(encoding="utf-8"))
    assert [row["name"] for row in TABLE] == [row["name"] for row in written]
    assert (STATIC / "widget.js").stat().st_size > 10_000, "the widget's module was not bundled"


def test_the_rust_parsers_vectors_read_the_same_in_python():
    """Every text the Rust parser answered (www/parameter-vectors.json, written by `metaballs manifest`)
    reads the same here: the same value, or the same message."""
    vectors = json.loads((ROOT / "www" / "parameter-vectors.json").read_text(encoding="utf-8"))
    assert len(vectors) > 2000
    wrong = []
    for v in vectors:
        row = next(r for r in (PLANE_TABLE if v["table"] == "plane" else TABLE) if r["name"] == v["name"])
        try:
            got = {"value": read(row, v["text"], v.get("given"))}
        except Refused as refused:
            got = {"message": str(refused)}
        if "value" in v:
            value = got.get("value")
            # A flag is a bool; a number is an int or a float of the same value (never a bool).
            same = "value" in got and value == v["value"] and isinstance(value, bool) == isinstance(v["value"], bool)
        else:
            same = got.get("message") == v["message"]
        if not same:
            wrong.append(f"{v['table']} {v.get('given', v['name'])}={v['text']!r}: {got}, Rust: {v}")
    assert wrong == [], "\n".join(wrong[:20])


def test_every_parameter_is_a_synced_trait_with_the_tables_default():
    widget = Metaballs()
    for row in TABLE:
        name = trait_name(row["name"])
        trait = widget.traits()[name]
        assert trait.metadata.get("sync"), f"{name} is not synced"
        assert getattr(widget, name) == row["value"], f"{name}: {getattr(widget, name)!r} is not the table's default"
        assert trait.help == row["description"]
    widget.close()


def test_both_widgets_take_the_language_they_speak_which_is_no_setting():
    for Widget in (Metaballs, Metaballs2d):
        widget = Widget(lang="ja")
        trait = widget.traits()["lang"]
        assert trait.metadata.get("sync") and widget.lang == "ja"
        assert Widget().lang == "", "without it the figure follows the notebook's page"
        assert "lang" not in {row["name"] for row in TABLE + PLANE_TABLE}
        widget.close()


def test_good_values_are_taken_as_the_figure_takes_them():
    widget = Metaballs(spheres=2, iso=0.7, display="WireFrame", color="#FFAA00", controls="iso, spheres")
    assert (widget.spheres, widget.iso, widget.display, widget.color) == (2, 0.7, "wireframe", "#ffaa00")
    assert widget.controls == "iso,spheres"
    widget.paused = "on"
    assert widget.paused is True
    widget.max_pixel_ratio = 1
    assert widget.max_pixel_ratio == 1
    widget.close()


@pytest.mark.parametrize("name,value", BAD)
def test_a_bad_value_is_refused_with_the_figures_message_and_the_old_value_kept(name, value):
    row = next(row for row in TABLE if row["name"] == name)
    with pytest.raises(Refused) as refused:
        check(row, value)
    assert str(refused.value) == cli_message(name, value)

    widget = Metaballs()
    before = getattr(widget, trait_name(name))
    with pytest.raises(traitlets.TraitError) as error:
        setattr(widget, trait_name(name), value)
    assert str(error.value).startswith(f'{name}="')
    assert str(refused.value) in str(error.value)
    assert getattr(widget, trait_name(name)) == before, "the bad value was kept"
    widget.close()


def test_the_wasm_is_sent_when_the_figure_asks():
    widget = Metaballs()
    sent = []
    widget.send = lambda content, buffers=None: sent.append((content, buffers))
    widget._answer(widget, {"type": "wasm", "build": "webgpu"}, [])
    widget._answer(widget, {"type": "wasm", "build": "elsewhere"}, [])
    widget._answer(widget, {"type": "wasm", "build": "levels"}, [])
    assert [c for c, _ in sent] == [{"type": "wasm", "build": "webgpu"}, {"type": "wasm", "build": "levels"}]
    assert all(bytes(b[0][:4]) == b"\0asm" for _, b in sent)
    widget.close()


def test_what_is_asked_of_the_figure_comes_back_as_it_answers():
    async def scenario():
        widget = Metaballs()
        asked = []
        widget.send = lambda content, buffers=None: asked.append(content)
        with pytest.raises(ValueError, match="format must be one of stl, obj, ply"):
            await widget.export_mesh("gltf")
        # The figure answers with bytes, a value and a refusal, as the front end sends them.
        mesh = asyncio.ensure_future(widget.export_mesh("stl"))
        scene = asyncio.ensure_future(widget.save_scene())
        refused = asyncio.ensure_future(widget.load_scene("{"))
        await asyncio.sleep(0)
        assert [(c["method"], c["args"]) for c in asked] == [("exportMesh", ["stl"]), ("saveScene", []), ("loadScene", ["{"])]
        ids = [c["id"] for c in asked]
        widget._answer(widget, {"type": "answer", "id": ids[1], "value": '{"format": "metaballs-scene"}'}, [])
        widget._answer(widget, {"type": "answer", "id": ids[0], "bytes": True}, [memoryview(b"solid")])
        widget._answer(widget, {"type": "answer", "id": ids[2], "error": "not a scene document"}, [])
        assert await mesh == b"solid"
        assert await scene == '{"format": "metaballs-scene"}'
        with pytest.raises(ValueError, match="not a scene document"):
            await refused
        # Nobody to answer: it says so instead of waiting for ever.
        with pytest.raises(TimeoutError, match="It answers while a notebook shows it.+Run All"):
            await widget._ask("saveScene", timeout=0.05)
        assert widget._waiting == {}

        # The statistics of a frame drawn for the call, with Python's names; the traits follow them.
        stats = asyncio.ensure_future(widget.stats())
        await asyncio.sleep(0)
        assert asked[-1]["method"] == "nextFrame"
        figures = {"triangles": 5900, "fps": 0, "frameTime": 12.5, "adapter": "WebGL2", "mesher": "cpu", "overflowed": False}
        widget._answer(widget, {"type": "answer", "id": asked[-1]["id"], "value": figures}, [])
        assert await stats == {**{k: v for k, v in figures.items() if k != "frameTime"}, "frame_time": 12.5}
        assert (widget.triangles, widget.adapter) == (5900, "WebGL2")

        # The critical points, as the figure's criticalPoints() resolves them.
        found = asyncio.ensure_future(widget.critical_points())
        await asyncio.sleep(0)
        assert asked[-1]["method"] == "criticalPoints"
        result = {"points": [{"value": 0.78125, "role": "join"}], "counts": {"blobs": 2}}
        widget._answer(widget, {"type": "answer", "id": asked[-1]["id"], "value": result}, [])
        assert await found == result
        widget.close()

    asyncio.run(scenario())


def test_the_2d_widget_has_a_trait_per_setting_of_the_2d_figure_with_its_default():
    from metaballs_widget import Metaballs2d
    from metaballs_widget._parameters import PLANE_TABLE

    written = json.loads((ROOT / "www" / "plane-parameters.json").read_text(encoding="utf-8"))
    assert [row["name"] for row in written] == [row["name"] for row in PLANE_TABLE]
    assert (STATIC / "widget-2d.js").stat().st_size > 10_000, "the 2D widget's module was not bundled"
    w = Metaballs2d()
    for row in PLANE_TABLE:
        assert getattr(w, trait_name(row["name"])) == row["value"], row["name"]
    assert w.resolution == 16 and w.saddle == "table"
    shared = {row["name"] for row in PLANE_TABLE} & {row["name"] for row in TABLE}
    assert {"iso", "saddle", "interpolation", "theme"} <= shared


def test_the_2d_widget_takes_good_values_and_refuses_bad_ones_keeping_its_own():
    from metaballs_widget import Metaballs2d

    w = Metaballs2d(circles="0.3,0.1,0.35;-0.35,-0.2,0.3", saddle="decider", resolution=12, show="grid,contour")
    assert (w.saddle, w.resolution, w.show) == ("decider", 12, "grid,contour")
    for name, value, said in [
        ("resolution", 4, 'resolution="4": resolution (squares per axis) must be between 8 and 1024, got 4; keeping 12'),
        ("saddle", "middle", 'saddle="middle"'),
        ("show", "grid,halos", 'show="grid,halos"'),
        ("controls", "iso,volume", 'controls="iso,volume"'),
    ]:
        with pytest.raises(traitlets.TraitError) as refused:
            setattr(w, trait_name(name), value)
        assert str(refused.value).startswith(said), str(refused.value)
    assert (w.saddle, w.resolution, w.show) == ("decider", 12, "grid,contour")
    # `levels` is the older name of `iso_levels`; hexadecimal and "no" mean what they mean to the figure.
    w = Metaballs2d(levels="0.5, 1.5")
    assert w.iso_levels == "0.5,1.5" and w.levels == "0.5,1.5"
    with pytest.raises(traitlets.TraitError, match="must be a number from 0.05 to 20"):
        w.iso = "0x10"
    w.paused = "no"
    assert w.paused is False
