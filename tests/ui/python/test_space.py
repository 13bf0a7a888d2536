"""nibrig.space: a fit from Python is the library's fit, its predictions follow the judgment model
from the coordinates (computed here independently, with math.erf), its arrays are views, and bad
input, progress, the GIL and Ctrl-C behave as the issue asks."""

import math
import os
import signal
import subprocess
import threading
import time

import numpy as np
import pytest

import nibrig
from command_line import nibrig_command


def test_a_fit_predicts_the_judgments_with_the_paper_model(salmon):
    space = nibrig.space.fit(salmon, dims=1, starts=4)
    assert space.dims == 1
    with open(salmon) as rows:
        next(rows)
        named = {name for row in rows for name in row.split(",")[2:5]}
    assert sorted(space.stimuli) == sorted(named)
    assert space.model == "probit"
    assert space.coordinates.shape == (len(named), 1)  # a row per stimulus, as scikit-learn's samples
    triplets = [("i0464", "i0532", "i0546"), ("i0246", "i0386", "i0462"), ("i0532", "i0464", "i0546")]
    p = space.predict(triplets)
    assert p.shape == (3,)
    # The paper's model, Eq. 1: P = Φ(s·(d_b − d_a)), Φ(x) = (1 + erf(x/√2))/2, from the coordinates.
    index = {name: i for i, name in enumerate(space.stimuli)}
    q = space.coordinates
    for k, (r, a, b) in enumerate(triplets):
        d_a = np.linalg.norm(q[index[a]] - q[index[r]])
        d_b = np.linalg.norm(q[index[b]] - q[index[r]])
        expected = 0.5 * (1 + math.erf(space.scale * (d_b - d_a) / math.sqrt(2)))
        # The library's Φ is accurate to ~1e-15; erf's to ~1e-16: well inside 1e-12.
        assert p[k] == pytest.approx(expected, abs=1e-12)
    # Most of the judgments it was fitted to come out as answered: Salmon's crowd agrees ~80 %.
    assert space.negative_log_likelihood / space.responses < math.log(2)


def test_the_coordinates_are_a_read_only_view_that_outlives_nothing(salmon, tmp_path):
    space = nibrig.space.fit(salmon, dims=2, starts=2)
    q = space.coordinates
    assert not q.flags.writeable
    assert not q.flags.owndata  # lent, not copied
    with pytest.raises(ValueError):
        q[0, 0] = 1.0
    space.save(tmp_path / "space.json")
    again = nibrig.space.load(tmp_path / "space.json")
    assert again.stimuli == space.stimuli
    # The space file keeps 17 significant digits: the same doubles.
    np.testing.assert_array_equal(again.coordinates, q)
    del space
    assert np.isfinite(q).all()  # the view keeps its owner alive


def test_the_same_fit_as_the_command_line(salmon, tmp_path):
    command = nibrig_command()
    subprocess.run([command, "space", "fit", str(salmon), "--dims", "2", "--starts", "3", "--seed", "5",
                    "-o", str(tmp_path / "cli.json")], check=True, capture_output=True)
    from_cli = nibrig.space.load(tmp_path / "cli.json")
    from_python = nibrig.space.fit(salmon, dims=2, starts=3, seed=5)
    np.testing.assert_allclose(from_python.coordinates, from_cli.coordinates, rtol=0, atol=1e-12)


def test_bad_input_is_a_value_error_and_a_missing_file_an_os_error(salmon, tmp_path):
    with pytest.raises(FileNotFoundError, match="nothing.csv"):
        nibrig.space.fit(tmp_path / "nothing.csv")
    broken = tmp_path / "broken.csv"
    broken.write_text("Participant.ID,Timestamp,Center,Left,Right,Answer\n1,x,i1,i2,i3,i9\n")
    with pytest.raises(ValueError, match=r"broken\.csv.*line 2"):
        nibrig.space.fit(broken)
    with pytest.raises(ValueError, match="dims"):
        nibrig.space.fit(salmon, dims=0)
    with pytest.raises(ValueError, match="wobbly"):
        nibrig.space.fit(salmon, model="wobbly")
    space = nibrig.space.fit(salmon, dims=1, starts=1)
    with pytest.raises(ValueError, match="'nope' is not a stimulus"):
        space.predict([("nope", "i0464", "i0532")])
    with pytest.raises(ValueError, match="descriptor map"):
        space.place({"friction_mu": 0.3})
    with pytest.raises(OSError, match="folder"):
        space.save(tmp_path)


def test_progress_reaches_the_callable_step_by_step(salmon):
    seen = []
    nibrig.space.fit(salmon, dims=1, starts=6, bootstrap=8, progress=lambda step, done, total: seen.append((step, done, total)))
    steps = [s for s, _, _ in seen]
    assert "fitting starts" in steps and "bootstrap refits" in steps
    assert steps.index("fitting starts") < steps.index("bootstrap refits")
    for step in ("fitting starts", "bootstrap refits"):
        counts = [(d, t) for s, d, t in seen if s == step]
        assert all(0 < d <= t for d, t in counts)
        assert [d for d, _ in counts] == sorted(d for d, _ in counts)  # never backwards


def test_a_fit_lets_other_python_threads_run(salmon):
    ticks = 0
    done = threading.Event()

    def fit():
        nibrig.space.fit(salmon, dims=2, starts=8, threads=1)
        done.set()

    worker = threading.Thread(target=fit)
    worker.start()
    while not done.is_set():
        ticks += 1
        time.sleep(0.001)
    worker.join()
    # With the GIL held for the fit (a second or more) this thread could not have run at all.
    assert ticks > 20


def test_ctrl_c_stops_a_long_fit(salmon):
    started = time.monotonic()
    timer = threading.Timer(0.5, lambda: os.kill(os.getpid(), signal.SIGINT))
    timer.start()
    with pytest.raises(KeyboardInterrupt):
        nibrig.space.fit(salmon, dims=3, starts=4, bootstrap=2000, threads=1)
    stopped_after = time.monotonic() - started
    timer.join()
    # 2000 bootstrap refits take minutes; stopped, it returns within a refit or two of the signal.
    assert stopped_after < 10.0
    # The module works on afterwards.
    assert nibrig.space.fit(salmon, dims=1, starts=1).dims == 1


def test_judgments_read_once_fit_as_the_file_does(salmon):
    judgments = nibrig.space.read_judgments(salmon)
    assert judgments.responses == 15054
    from_file = nibrig.space.fit(salmon, dims=2, starts=2)
    from_read = nibrig.space.fit(judgments, dims=2, starts=2)
    assert from_read.stimuli == from_file.stimuli
    np.testing.assert_array_equal(from_read.coordinates, from_file.coordinates)
