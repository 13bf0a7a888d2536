"""nibrig.measure on the paper's recordings: the numbers are those `nibrig measure` writes (the
science itself is checked in the C++ suites against its references), their documented relations
hold, a catalog of two recordings holds each one's numbers, and errors are Python's."""

import json
import os
import pickle

import numpy as np
import pytest

import nibrig
from conftest import shared_data

FRICTION = "friction/real_tools/cryon_office_2.2N_14_1.csv.gz"
VIBRATION = "vibration/arm2/arm_cryon_office.csv.gz"


def recording(name):
    return shared_data() / "piovarci2018" / name


def test_a_friction_recording_gives_mu_within_its_interval():
    m = nibrig.measure.recording(recording(FRICTION))
    assert (m.kind, m.tool, m.surface) == ("friction", "cryon", "office")
    low, high = m.mu_interval
    assert low < m.mu < high
    assert m.normal_load_N == pytest.approx(2.2)
    assert json.loads(m.to_json())["mu"] == m.mu  # what the command line writes, to the last bit
    with pytest.raises(ValueError, match="no vibration"):
        m.weighted_mean


def test_a_vibration_recording_gives_its_spectrum_and_descriptors():
    m = nibrig.measure.recording(recording(VIBRATION))
    assert m.kind == "vibration"
    a = m.amplitude
    assert a.shape == (len(m.speeds_m_s), len(m.frequencies_hz))
    assert (a >= 0).all() and np.isfinite(a).all()
    assert np.all(np.diff(m.frequencies_hz) > 0)
    assert not m.frequencies_hz.flags.writeable and not m.frequencies_hz.flags.owndata  # lent, read-only
    written = json.loads(m.to_json())
    np.testing.assert_array_equal(np.array(written["amplitude_m_s2"]), a)
    assert written["descriptors"]["weighted_mean"] == m.weighted_mean
    # Each split of the weighted power into k bands adds up to it (descriptors.hpp), to rounding.
    for k, bands in m.band_energies.items():
        assert len(bands) == k
        assert sum(bands) == pytest.approx(m.weighted_power, rel=1e-12)
    with pytest.raises(ValueError, match="no friction"):
        m.mu


def test_a_catalog_of_two_recordings_holds_each_ones_numbers(tmp_path):
    folder = tmp_path / "recordings"
    for name in (FRICTION, VIBRATION):
        (folder / os.path.dirname(name)).mkdir(parents=True, exist_ok=True)
        os.symlink(recording(name), folder / name)
    seen = []
    built = nibrig.measure.catalog(folder, threads=1, progress=lambda step, done, total: seen.append((done, total)))
    assert seen[-1] == (2, 2)
    assert built.pairings == [{"tool": "cryon", "surface": "office",
                               "mu": nibrig.measure.recording(recording(FRICTION)).mu,
                               "weighted_mean": nibrig.measure.recording(recording(VIBRATION)).weighted_mean}]
    built.save(tmp_path / "catalog.json")
    assert nibrig.measure.load_catalog(tmp_path / "catalog.json").pairings == built.pairings
    bundled = nibrig.measure.load_catalog(nibrig.measure.bundled_catalog())
    assert "cryon" in bundled.tools and "office" in bundled.surfaces


def test_a_catalog_pickles_as_the_file_it_would_write(tmp_path):
    bundled = nibrig.measure.load_catalog(nibrig.measure.bundled_catalog())
    again = pickle.loads(pickle.dumps(bundled))
    assert (again.tools, again.surfaces, again.pairings) == (bundled.tools, bundled.surfaces, bundled.pairings)
    # Every number kept: the file holds speeds in mm/s and the catalog m/s, so a value through both
    # units may move by an ulp (2.2e-16 relative), never more.
    bundled.save(tmp_path / "original.json")
    again.save(tmp_path / "copy.json")

    def numbers(node):
        if isinstance(node, dict):
            return [x for key in sorted(node) for x in numbers(node[key])]
        if isinstance(node, list):
            return [x for item in node for x in numbers(item)]
        return [node] if isinstance(node, (int, float)) and not isinstance(node, bool) else []

    original = numbers(json.loads((tmp_path / "original.json").read_text()))
    copied = numbers(json.loads((tmp_path / "copy.json").read_text()))
    assert len(copied) == len(original) > 1000
    np.testing.assert_allclose(copied, original, rtol=4.5e-16, atol=0)


def test_bad_input_and_missing_files_are_python_errors(tmp_path):
    with pytest.raises(FileNotFoundError, match="nothing.csv"):
        nibrig.measure.recording(tmp_path / "nothing.csv")
    odd = tmp_path / "odd.csv"
    odd.write_text("a,b,c\n1,2,3\n")
    with pytest.raises(ValueError, match="odd.csv"):
        nibrig.measure.recording(odd)
    with pytest.raises(FileNotFoundError):
        nibrig.measure.load_catalog(tmp_path / "none.json")


def test_a_progress_that_raises_stops_a_catalog_with_its_exception(tmp_path):
    # The exception left a worker thread of the build and aborted Python (issue 46); now it is raised
    # here, with nothing written.
    folder = tmp_path / "recordings"
    for name in (FRICTION, VIBRATION):
        (folder / os.path.dirname(name)).mkdir(parents=True, exist_ok=True)
        os.symlink(recording(name), folder / name)
    with pytest.raises(ZeroDivisionError):
        nibrig.measure.catalog(folder, threads=2, progress=lambda *a: 1 / 0)
    with pytest.raises(TypeError):
        nibrig.measure.catalog(folder, threads=2, progress=5)
    assert nibrig.measure.catalog(folder, threads=2).pairings  # the module works on after both


def test_measurements_pickle_with_every_number_they_show():
    # Bit for bit: a measurement pickles as its numbers, so a joblib worker's results are the ones
    # measured there.
    friction, vibration = (nibrig.measure.recording(recording(n)) for n in (FRICTION, VIBRATION))
    f, v = (pickle.loads(pickle.dumps(m)) for m in (friction, vibration))
    assert (f.kind, f.tool, f.surface, f.mu, f.mu_interval, f.normal_load_N, f.warnings, f.to_json()) == (
        friction.kind, friction.tool, friction.surface, friction.mu, friction.mu_interval, friction.normal_load_N,
        friction.warnings, friction.to_json())
    for name in ("frequencies_hz", "speeds_m_s", "amplitude"):
        np.testing.assert_array_equal(getattr(v, name), getattr(vibration, name))
    assert (v.weighted_mean, v.weighted_power, v.band_energies, v.to_json()) == (
        vibration.weighted_mean, vibration.weighted_power, vibration.band_energies, vibration.to_json())
    with pytest.raises(ValueError, match="no friction"):
        v.mu
    with pytest.raises(ValueError, match="not a pickled Measurement"):
        nibrig.measure.Measurement.__new__(nibrig.measure.Measurement).__setstate__(("friction",))
