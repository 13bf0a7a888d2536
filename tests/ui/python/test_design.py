"""nibrig.design on a coarse stylus (32 modes, 4 mm elements, as the CLI's design tests): a
prediction is what `nibrig predict` writes, it is placed in the demo's space, and a search toward
a tool of that space keeps to its constraints, its optimum no farther than the line's ends."""

import json
import multiprocessing
import pickle
import re
import shutil
import subprocess
from concurrent.futures import ProcessPoolExecutor

import numpy as np
import pytest

import nibrig
from command_line import nibrig_command
from conftest import REPOSITORY

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
    command = nibrig_command()
    subprocess.run([command, "predict", "--design", p.design, "--surface", "glass", "--modes", "32", "--mesh-size",
                    "0.004", "-o", str(tmp_path / "p.json")], check=True, capture_output=True)
    written = json.loads((tmp_path / "p.json").read_text())
    assert written["mu"] == p.mu
    np.testing.assert_array_equal(np.array(written["amplitude_m_s2"]), p.amplitude)


def test_a_designer_and_its_predictions_go_to_another_process_and_back(designer):
    point = "DM85:0.5,vero:0.5,tip=2mm"
    here = designer.predict(point, "glass")
    # A prediction pickles as its numbers: each comes back bit for bit, its descriptors' error too
    # (the placement uses it).
    copy = pickle.loads(pickle.dumps(here))
    assert (copy.design, copy.surface, copy.mu, copy.first_mode_hz, copy.weighted_mean) == (
        here.design, here.surface, here.mu, here.first_mode_hz, here.weighted_mean)
    assert copy.mode_frequencies_hz == here.mode_frequencies_hz
    np.testing.assert_array_equal(copy.amplitude, here.amplitude)
    space = nibrig.space.default(bootstrap=20)
    np.testing.assert_array_equal(copy.place(space).covariance, here.place(space).covariance)
    # A fresh interpreter unpickles the designer (its forcing model travels as the file's text, its
    # diameters and speeds through mm) and predicts what this one does, to rounding.
    with ProcessPoolExecutor(1, mp_context=multiprocessing.get_context("spawn")) as pool:
        there = pool.submit(designer.predict, point, "glass").result()
    assert there.mu == pytest.approx(here.mu, rel=1e-12)
    np.testing.assert_allclose(there.amplitude, here.amplitude, rtol=1e-12)


def test_a_designer_whose_file_changed_since_it_was_pickled_is_refused(tmp_path):
    materials = tmp_path / "materials.json"
    shutil.copyfile(REPOSITORY / "assets" / "materials.json", materials)
    state = pickle.dumps(nibrig.design.designer(materials=materials, **COARSE))  # same bytes: the cached model
    pickle.loads(state)
    materials.write_text(materials.read_text() + "\n")
    with pytest.raises(ValueError, match=re.escape(str(materials)) + " changed since this Designer was pickled"):
        pickle.loads(state)


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

    # The search pickles as its candidates, bit for bit: the same path, optimum and runners-up.
    again = pickle.loads(pickle.dumps(found))
    assert (again.path, again.optimum, again.runners_up(3)) == (path, best, found.runners_up(3))
    with pytest.raises(ValueError, match="not a pickled Search"):
        state = found.__getstate__()
        nibrig.design.Search.__new__(nibrig.design.Search).__setstate__((state[0], [99], [target], [], None))
    assert found.fem_solved == [] and found.grid_error is None

    # Through the design grid: the FEM only where the grid's measured error could change the answer,
    # an optimum the FEM solved, within that error of the full search's, for fewer solves.
    guided = designer.search(space, target, "protector", between=("vero:1,tip=1mm", "DM85:1,tip=4mm"),
                             max_tip_mm=3.0, grid=True)
    assert guided.grid_error > 0
    assert abs(guided.optimum["distance"] - best["distance"]) <= guided.grid_error
    solved = guided.fem_solved
    assert len(solved) == len(guided.path) and 0 < sum(solved) < len(path)
    assert solved[[c["design"] for c in guided.path].index(guided.optimum["design"])]
    again = pickle.loads(pickle.dumps(guided))
    assert (again.fem_solved, again.grid_error, again.path) == (solved, guided.grid_error, guided.path)


def test_bad_designs_and_searches_are_value_errors(designer):
    with pytest.raises(ValueError, match="wood"):
        designer.predict("wood,tip=2mm", "glass")
    space = nibrig.space.default(bootstrap=20)
    with pytest.raises(ValueError, match="at most 0.5 mm"):
        designer.search(space, space.stimuli[0], "protector", between=("vero:1,tip=1mm", "DM85:1,tip=4mm"),
                        max_tip_mm=0.5)
    with pytest.raises(ValueError, match="max_cost"):
        designer.search(space, space.stimuli[0], "protector", max_cost=2.0)


def test_a_smallest_tip_above_the_largest_is_refused_naming_it(designer):
    # The command line's --min-tip-mm above --max-tip-mm, refused by the same library request,
    # before any prediction.
    space = nibrig.space.default(bootstrap=20)
    with pytest.raises(ValueError, match=r"^min_tip_mm: 3 mm is above max_tip_mm, 2 mm"):
        designer.search(space, space.stimuli[0], "protector", min_tip_mm=3.0, max_tip_mm=2.0)


def test_a_designs_modes_give_its_response_in_closed_form(designer):
    modes = designer.modes("DM85:0.5,vero:0.5,tip=2mm")
    f = np.array(modes.frequencies_hz)
    assert len(f) == 32 and np.all(np.diff(f) > 0)
    # The same solve as a prediction's.
    assert modes.frequencies_hz == designer.predict("DM85:0.5,vero:0.5,tip=2mm", "glass").mode_frequencies_hz
    # |H| from the modal parameters, written out here: sum of c_i b_i (-W^2) / (w_i^2 - W^2 + 2j z_i w_i W).
    w = 2 * np.pi * f
    big_w = 2 * np.pi * np.asarray(modes.response_frequencies_hz)[:, None]
    h = (modes.sensor * modes.tip * -big_w**2 / (w**2 - big_w**2 + 2j * modes.damping_ratios * w * big_w)).sum(axis=1)
    # The same sum in another order: round-off, relative 1e-9 with margin.
    np.testing.assert_allclose(modes.response, np.abs(h), rtol=1e-9)
    assert not modes.response.flags.writeable
    again = pickle.loads(pickle.dumps(modes))  # as its numbers, bit for bit
    assert (again.design, again.frequencies_hz) == (modes.design, modes.frequencies_hz)
    for name in ("damping_ratios", "tip", "sensor", "response", "response_frequencies_hz"):
        np.testing.assert_array_equal(getattr(again, name), getattr(modes, name))


def test_the_forcing_model_predicts_what_a_prediction_predicts(designer):
    forcing = designer.forcing
    assert forcing.reference == (2.0, "vero")
    assert "glass" in forcing.surfaces and 2.0 in forcing.tips_mm and "DM85" in forcing.materials
    # The reference's gains are 1 by definition (Sec. 5.2): 0 dB at every frequency.
    assert np.max(np.abs(forcing.tip_gain_db(2.0))) == 0 and np.max(np.abs(forcing.material_gain_db("vero"))) == 0
    surface = forcing.surface_forcing("glass")
    assert surface.shape == (len(forcing.speeds_m_s), len(forcing.frequencies_hz)) and np.all(surface >= 0)
    # A single-material design: the model's spectrum from the design's response is the prediction's.
    modes = designer.modes("DM85:1,tip=2mm")
    predicted = designer.predict("DM85:1,tip=2mm", "glass")
    np.testing.assert_allclose(forcing.predict(modes.response, "glass", 2.0, "DM85"), predicted.amplitude, rtol=1e-12)
    # Eq. 10 by hand at the reference tool: |H| times F_S.
    np.testing.assert_allclose(forcing.predict(modes.response, "glass", 2.0, "vero"), surface * modes.response, rtol=1e-12)
    assert forcing.residual_rms_db > 0 and len(forcing.exemplar_fits) > 0
    with pytest.raises(ValueError, match="moon"):
        forcing.surface_forcing("moon")
    # Pickled as the forcing file's text: the same model, its tips and speeds through mm to an ulp.
    again = pickle.loads(pickle.dumps(forcing))
    assert (again.surfaces, again.materials, again.notes) == (forcing.surfaces, forcing.materials, forcing.notes)
    np.testing.assert_allclose(again.tips_mm, forcing.tips_mm, rtol=1e-15)
    np.testing.assert_allclose(again.predict(modes.response, "glass", 2.0, "DM85"), predicted.amplitude, rtol=1e-12)


def test_a_material_calibrated_in_python_is_what_the_command_line_calibrates(tmp_path, monkeypatch):
    # A lab's model without DM95 (the command line's check writes one with DM95 calibrated; its curve
    # is taken out here), then DM95 calibrated against it from its 1 and 4 mm prints, in both faces.
    monkeypatch.setenv("NIBRIG_FORCING_MODELS", str(tmp_path / "store"))
    command = nibrig_command()
    coarse = ["--modes", "32", "--mesh-size", "0.004"]
    subprocess.run([command, "forcing", "calibrate-material", "--material", "DM95", "-o", str(tmp_path / "dm95.json")]
                   + coarse, check=True, capture_output=True)
    model = json.loads((tmp_path / "dm95.json").read_text())
    model["material_curves"] = [c for c in model["material_curves"] if c["material"] != "DM95"]
    (tmp_path / "without.json").write_text(json.dumps(model))
    subprocess.run([command, "forcing", "calibrate-material", "--material", "DM95", "--tips", "1,4", "--forcing",
                    str(tmp_path / "without.json"), "-o", str(tmp_path / "cli.json")] + coarse,
                   check=True, capture_output=True)
    cli = next(c for c in json.loads((tmp_path / "cli.json").read_text())["material_curves"] if c["material"] == "DM95")

    c = nibrig.design.calibrate_material("DM95", forcing=tmp_path / "without.json", tips_mm=[1, 4], **COARSE)
    assert c.name == "DM95" and c.prints == 2
    db = 20 / np.log(10)
    # The same fit of the same prints: equal to the file's 17 digits.
    np.testing.assert_allclose(c.gain_db, db * np.array(cli["log_gain"]), rtol=0, atol=1e-9)
    np.testing.assert_allclose(c.gain_se_db, db * np.array(cli["log_gain_se"]), rtol=0, atol=1e-9)
    assert all(se > 0 for se in c.gain_se_db)
    # The 2 mm prints, not calibrated on, are predicted; every print calibrated on is fitted.
    assert {p["tool"] for p in c.predicted} == {"DM952"}
    assert {p["tool"] for p in c.fits} == {"DM951", "DM954"}
    again = pickle.loads(pickle.dumps(c))
    assert (again.name, again.gain_db, again.gain_se_db, again.prints, again.exemplars, again.fits, again.predicted) == (
        c.name, c.gain_db, c.gain_se_db, c.prints, c.exemplars, c.fits, c.predicted)

    kept = c.keep("lab-DM95")
    assert kept == tmp_path / "store" / "lab-DM95.json"
    with pytest.raises(ValueError, match="stored already"):
        c.keep("lab-DM95")
    # Kept by name, it is the model a designer predicts with.
    assert "DM95" in nibrig.design.designer(forcing="lab-DM95", **COARSE).forcing.materials
    # A material the model has already is refused (a calibration adds one, under a new name).
    with pytest.raises(ValueError, match="DM85"):
        nibrig.design.calibrate_material("DM85", forcing=tmp_path / "without.json", **COARSE)
