"""nibrig.design on a coarse stylus (32 modes, 4 mm elements, as the CLI's design tests): a
prediction is what `nibrig predict` writes, it is placed in the demo's space, and a search toward
a tool of that space keeps to its constraints, its optimum no farther than the line's ends."""

import json
import os
import subprocess

import numpy as np
import pytest

import nibrig

COARSE = dict(modes=32, mesh_size=0.004)


@pytest.fixture(scope="module")
def designer():
    return nibrig.design.designer(**COARSE)


def test_a_prediction_is_what_the_command_line_predicts(designer, tmp_path):
    p = designer.predict("DM85:0.5,vero:0.5,tip=2mm", "glass")
    assert p.design == "DM85:0.5,vero:0.5,tip=2mm"
    assert 0 < p.mu < 1
    assert p.amplitude.shape == (len(p.speeds_m_s), len(p.frequencies_hz))
    assert p.mode_frequencies_hz == sorted(p.mode_frequencies_hz)
    command = os.environ.get("NIBRIG_COMMAND")
    if not command:
        pytest.skip("NIBRIG_COMMAND (the nibrig executable) not given")
    subprocess.run([command, "predict", "--design", p.design, "--surface", "glass", "--modes", "32", "--mesh-size",
                    "0.004", "-o", str(tmp_path / "p.json")], check=True, capture_output=True)
    written = json.loads((tmp_path / "p.json").read_text())
    assert written["mu"] == p.mu
    np.testing.assert_array_equal(np.array(written["amplitude_m_s2"]), p.amplitude)


def test_a_search_keeps_to_its_constraints_and_beats_the_ends(designer):
    space = nibrig.space.default(bootstrap=20)
    assert space.has_descriptor_map
    target = space.stimuli[0]
    seen = []
    found = designer.search(space, target, "protector", between=("vero:1,tip=1mm", "DM85:1,tip=4mm"),
                            max_tip_mm=3.0, progress=lambda step, done, total: seen.append(done))
    path = found.path
    assert seen and seen[-1] == len(path)
    for c in path:
        tip = float(c["design"].split("tip=")[1].rstrip("m"))
        assert tip <= 3.0 + 1e-9
    best = found.optimum
    assert best["distance"] <= min(path[0]["distance"], path[8]["distance"])
    assert best["to_targets"][target][0] == best["distance"]
    # Its place is the one the prediction of that design gives (the search's own evaluation). The
    # design's text keeps 6 significant digits of its fraction and tip: a few 1e-7 of a unit here.
    placed = designer.predict(best["design"], "protector").place(space)
    np.testing.assert_allclose(placed.mean, best["coordinates"], rtol=0, atol=1e-5)


def test_bad_designs_and_searches_are_value_errors(designer):
    with pytest.raises(ValueError, match="wood"):
        designer.predict("wood,tip=2mm", "glass")
    space = nibrig.space.default(bootstrap=20)
    with pytest.raises(ValueError, match="at most 0.5 mm"):
        designer.search(space, space.stimuli[0], "protector", between=("vero:1,tip=1mm", "DM85:1,tip=4mm"),
                        max_tip_mm=0.5)
    with pytest.raises(ValueError, match="max_cost"):
        designer.search(space, space.stimuli[0], "protector", max_cost=2.0)
