"""A lab's material from its printed bar in Python: the bar written for a printer, its ring-down
fitted and saved among the lab's materials, as the command line does it."""

import json
import math
import pickle
import subprocess

import numpy as np
import pytest

import nibrig
from command_line import nibrig_command


def ring_down_csv(path, frequency_hz, damping_ratio, seed):
    """A released cantilever's first mode, in closed form: a decaying cosine from 0.2 s, 2 % noise."""
    fs = 2000.0
    t = np.arange(6000) / fs
    w = 2 * math.pi * frequency_hz
    wd = w * math.sqrt(1 - damping_ratio**2)
    after = t - 0.2
    a = np.where(after >= 0, -30 * np.exp(-damping_ratio * w * after) * np.cos(wd * after), 0.0)
    a += 0.6 * np.random.default_rng(seed).standard_normal(t.size)
    np.savetxt(path, np.c_[t, a], delimiter=",", header="time_s,acceleration_m_s2", comments="")
    return path


def test_a_bar_and_its_ring_down_make_a_lab_material_as_the_command_line_does(tmp_path, monkeypatch):
    monkeypatch.setenv("NIBRIG_MATERIALS", str(tmp_path / "lab"))
    bar = nibrig.design.calibration_bar("PLA", printer="prusa-mk3s", folder=tmp_path / "bar")
    assert bar.material == "PLA" and bar.printer == "prusa-mk3s" and bar.length_mm == 210
    for f in (bar.three_mf, bar.stl, bar.ini, bar.drawing, bar.instructions, bar.record):
        assert f.exists(), f
    assert json.loads(bar.record.read_text())["material"] == "PLA"
    # The paper's bar in closed form: 210 x 20 x 2 mm less its rounded end (a 20 x 10 mm corner pair
    # minus a half disc of R10) and its R5 hole. 0.5 %: the mesh's facets on the two arcs.
    solid = (210 * 20 - (20 * 10 - math.pi * 10**2 / 2) - math.pi * 5**2) * 2
    assert bar.volume_mm3 == pytest.approx(solid, rel=5e-3)

    trace = ring_down_csv(tmp_path / "ring.csv", 25.0, 0.02, 3)
    fit = nibrig.design.calibrate_ring_down(trace, bar=tmp_path / "bar", name="py-pla")
    # The fitted bar rings as the trace does: its frequency to 0.3 % (the trace holds 170 periods;
    # its one mode stands for the bar's several) and its damping ratio to 5 % (2 % noise on a decay
    # over some 20 time constants).
    assert fit.first_mode_hz == pytest.approx(25.0, rel=3e-3)
    assert fit.first_mode_damping_ratio == pytest.approx(0.02, rel=0.05)
    assert fit.youngs_modulus_sd_Pa > 0 and fit.rayleigh_stiffness_sd_s > 0
    assert fit.fitted.shape == (6000,)
    assert fit.saved == tmp_path / "lab" / "py-pla.json"
    saved = json.loads(fit.saved.read_text())
    assert saved["materials"][0]["youngs_modulus"] == fit.youngs_modulus_Pa
    assert saved["calibration"]["printed_as"] == "PLA"

    # Both pickle as what they show, bit for bit: a worker's bar and fit are the ones made here.
    bar_again, fit_again = pickle.loads(pickle.dumps(bar)), pickle.loads(pickle.dumps(fit))
    for name in ("material", "printer", "length_mm", "volume_mm3", "three_mf", "stl", "ini",
                 "drawing", "instructions", "record"):
        assert getattr(bar_again, name) == getattr(bar, name), name
    for name in ("name", "youngs_modulus_Pa", "youngs_modulus_sd_Pa", "rayleigh_stiffness_s",
                 "rayleigh_stiffness_sd_s", "first_mode_hz", "first_mode_damping_ratio",
                 "relative_residual", "saved"):
        assert getattr(fit_again, name) == getattr(fit, name), name
    assert np.array_equal(fit_again.fitted, fit.fitted)
    # A printer PrusaSlicer does not slice has no .ini: None before and after the pickle, never ".".
    material, printer, length, volume, files = bar.__getstate__()
    unsliced = nibrig.design.CalibrationBar.__new__(nibrig.design.CalibrationBar)
    unsliced.__setstate__((material, printer, length, volume, files[:2] + ("",) + files[3:]))
    assert unsliced.ini is None and pickle.loads(pickle.dumps(unsliced)).ini is None
    with pytest.raises(ValueError, match="not a pickled RingDownCalibration"):
        nibrig.design.RingDownCalibration.__new__(nibrig.design.RingDownCalibration).__setstate__(("py-pla",))

    # The command line fits the same trace on the same bar to the same numbers.
    subprocess.run([nibrig_command(), "-q", "material", "calibrate", "ringdown", str(trace), "--bar",
                    str(tmp_path / "bar"), "--name", "cli-pla", "--no-plots"], check=True)
    cli = json.loads((tmp_path / "lab" / "cli-pla.json").read_text())["materials"][0]
    assert cli["youngs_modulus"] == pytest.approx(fit.youngs_modulus_Pa, rel=1e-12)
    assert cli["rayleigh_stiffness"] == pytest.approx(fit.rayleigh_stiffness_s, rel=1e-12)

    # Refused before the fit: a bundled name, and the lab's own without replace.
    with pytest.raises(ValueError, match="'PETG' is a bundled material's"):
        nibrig.design.calibrate_ring_down(trace, bar=tmp_path / "bar", name="PETG")
    with pytest.raises(ValueError, match="already has a material 'py-pla'"):
        nibrig.design.calibrate_ring_down(trace, bar=tmp_path / "bar", name="py-pla")
    refit = nibrig.design.calibrate_ring_down(trace, bar=tmp_path / "bar", name="py-pla", replace=True)
    assert refit.youngs_modulus_Pa == fit.youngs_modulus_Pa


def test_a_bar_a_printer_cannot_make_is_refused_naming_why(tmp_path):
    with pytest.raises(ValueError, match="prusa-sl1s"):
        nibrig.design.calibration_bar("PLA", printer="prusa-sl1s", folder=tmp_path / "bar")
    assert not (tmp_path / "bar").exists()
    with pytest.raises(ValueError, match="unknown material 'unobtainium'"):
        nibrig.design.calibration_bar("unobtainium", printer="prusa-mk3s", folder=tmp_path / "bar")
