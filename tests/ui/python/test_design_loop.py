"""The design loop in Python: a new loop proposes its first print and waits for its measurement, as
`nibrig design loop` does without a rig; resumed with the simulated rig it measures the print, and
every number it returns is the one the loop's folder keeps."""

import json
import locale
import pickle

import numpy as np
import pytest

import nibrig
from conftest import shared_data


def test_a_loop_waits_for_its_print_then_resumed_on_the_simulated_rig_measures_it(tmp_path):
    space_file = tmp_path / "space.json"
    nibrig.space.default(bootstrap=20).save(space_file)
    folder = tmp_path / "loop"
    encoding = locale.getpreferredencoding(False)
    started = nibrig.design.loop(folder, target="wnylon/glass", surface="glass", space=space_file, rounds=2)
    # Exporting the print left the process's locale as it was (lib3mf sets "C"): files still UTF-8.
    assert locale.getpreferredencoding(False) == encoding
    assert started.awaiting == 1 and started.stopped is None
    assert len(started.rounds) == 1 and started.rounds[0]["measured_distance"] is None
    assert (folder / "round-1" / "print" / "stylus.3mf").exists()
    # The paper's probit at s = 2/3: Φ(s·d) = 0.75 at d = Φ⁻¹(0.75) / s; the solver's 1e-12.
    assert started.threshold == pytest.approx(0.6744897501960817 * 1.5, rel=1e-9)

    resumed = nibrig.design.loop(folder, resume=True, simulated=True, seconds=14)
    assert resumed.awaiting is None
    assert resumed.stopped in ("within the threshold", "no design predicted closer", "round limit")
    measured = [r for r in resumed.rounds if r["measured_distance"] is not None]
    assert len(measured) >= 1 and len(measured) <= 2
    np.testing.assert_array_equal(resumed.measured_distances, [r["measured_distance"] for r in measured])
    # What the folder keeps, to the digit JSON writes.
    for r in resumed.rounds:
        kept = json.loads((folder / f"round-{r['round']}" / "round.json").read_text())
        assert kept["design"] == r["design"]
        assert kept["predicted"]["distance"] == pytest.approx(r["predicted_distance"], rel=1e-15)
        assert kept["measured"]["distance"] == pytest.approx(r["measured_distance"], rel=1e-15)
        np.testing.assert_allclose(kept["measured"]["position"], r["measured_position"], rtol=1e-15)
    # Pickled as its rounds' numbers, bit for bit, the waiting and the finished loop alike.
    for loop in (started, resumed):
        again = pickle.loads(pickle.dumps(loop))
        assert (again.folder, again.threshold, again.stopped, again.awaiting) == (
            loop.folder, loop.threshold, loop.stopped, loop.awaiting)
        for a, b in zip(again.rounds, loop.rounds, strict=True):
            assert a.keys() == b.keys()
            for key in a:
                if isinstance(a[key], np.ndarray):
                    np.testing.assert_array_equal(a[key], b[key])
                else:
                    assert a[key] == b[key]


def test_a_resumed_loop_takes_no_new_target_and_a_new_one_needs_its_space(tmp_path):
    with pytest.raises(ValueError, match="resume"):
        nibrig.design.loop(tmp_path / "loop", resume=True, target="cryon/office")
    with pytest.raises(ValueError, match="space"):
        nibrig.design.loop(tmp_path / "loop", target="cryon/office", surface="glass")
    with pytest.raises(ValueError, match="holds no design loop"):
        nibrig.design.loop(tmp_path / "nothing", resume=True)


def test_the_papers_recorded_prints_stand_in_for_printing(tmp_path):
    space_file = tmp_path / "space.json"
    nibrig.space.default(bootstrap=20).save(space_file)
    data = shared_data() / "piovarci2018"
    with pytest.raises(ValueError, match="one way"):
        nibrig.design.loop(tmp_path / "both", target="wnylon/glass", surface="glass", space=space_file,
                           simulated=True, replay_prints=data)
    folder = tmp_path / "loop"
    done = nibrig.design.loop(folder, target="wnylon/glass", surface="glass", space=space_file, rounds=2,
                              replay_prints=data)
    recorded = {f"{m}:1,tip={t}mm" for m in ("vero", "DM85") for t in (1, 2, 4)}
    assert set(json.loads((folder / "loop.json").read_text())["candidates"]) == recorded
    assert done.awaiting is None and done.stopped is not None
    designs = [r["design"] for r in done.rounds]
    assert 1 <= len(designs) <= 2 and len(set(designs)) == len(designs) and set(designs) <= recorded
    for r in done.rounds:
        # Each print's μ is its paper friction run's (nibrig.measure on the file), to a fifth of the
        # run's 95 % half-width: the replay holds the force samples on the accelerometer's clock.
        kept = json.loads((folder / f"round-{r['round']}" / "measurement.json").read_text())
        mu = kept["pairings"][0]["friction"]["mu"]
        material, tip = r["design"].split(":1,tip=")
        (run_file,) = (data / "friction" / "printed").glob(f"{material}{tip[:-2]}_glass_*.csv.gz")
        run = nibrig.measure.recording(run_file)
        low, high = run.mu_interval
        assert mu == pytest.approx(run.mu, abs=(high - low) / 10)
        assert r["measured_distance"] is not None
