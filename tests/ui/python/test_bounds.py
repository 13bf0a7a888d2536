"""Issue 46: the ranges the command line holds its options to are the library's, so a Python call
is held to them too, and its ValueError names the argument. Each refusal comes before any work
(no meshing, no rig opened), so the whole file runs in about a second."""

import math

import pytest

import nibrig


@pytest.mark.parametrize("kwargs, name", [
    ({"speed": 1e308}, "speed"),
    ({"force": 1e308}, "force"),
    ({"period": 10**9}, "period"),
])
def test_render_is_held_to_the_command_lines_ranges(kwargs, name):
    with pytest.raises(ValueError, match=rf"^{name}: "):
        nibrig.render.tool("cryon", "office", **kwargs)


def test_a_rig_is_held_to_the_command_lines_ranges(tmp_path):
    with pytest.raises(ValueError, match=r"^load: 1e\+308 N"):
        nibrig.rig.simulated("vero2", "office", load=1e308)
    with pytest.raises(ValueError, match=r"^seconds: "):
        nibrig.rig.capture(nibrig.rig.simulated("vero2", "office"), tmp_path / "s", seconds=1e-320)


def test_a_designer_and_a_search_are_held_to_the_command_lines_ranges():
    with pytest.raises(ValueError, match=r"^mesh_size: nan"):
        nibrig.design.designer(mesh_size=math.nan)


def test_a_fit_takes_a_path_or_judgments_and_a_bounded_number_of_starts(tmp_path):
    with pytest.raises(TypeError, match=r"^judgments: expected Judgments \(from arrays or read_judgments\) or a file path, found int"):
        nibrig.space.fit(42)
    with pytest.raises(ValueError, match=r"^starts: 1000000000"):
        nibrig.space.fit(tmp_path / "none.csv", starts=10**9)


@pytest.mark.parametrize("kwargs, message", [
    ({"rate": 100}, r"^rate: 100 Hz: expected a sample rate in Hz, 8000 to 384000"),
    ({"period": 10**9}, r"^period: 1e\+09 frames: expected a block size in frames, 1 to 65536"),
])
def test_a_player_is_held_to_the_command_lines_ranges_before_a_device_opens(kwargs, message):
    # Refused before any audio API is asked for the device, which does not exist.
    with pytest.raises(ValueError, match=message):
        nibrig.audition.Player("jack", "no such device", **kwargs)
