"""nibrig.rig on the simulated rig, computed as fast as it goes: a capture holds what `nibrig rig
capture` writes for the same request, a replay of it gives the same streams, a comparison is what
`nibrig rig compare` reports, and refusals, progress and Ctrl-C behave as for every long call (the
rig itself is checked in the C++ suites, the USB controller there on simavr)."""

import json
import os
import pickle
import signal
import subprocess
import threading
import time

import numpy as np
import pytest

import nibrig
from command_line import nibrig_command

STREAMS = ("acceleration", "speed_m_s", "normal_force_N", "tangential_force_N")


@pytest.fixture(scope="module")
def captured(tmp_path_factory):
    """Two seconds of the study's sweep with vero2 on office, and the progress it reported."""
    folder = tmp_path_factory.mktemp("rig") / "vero2_office"
    seen = []
    session = nibrig.rig.capture(nibrig.rig.simulated("vero2", "office"), folder, profile="sweep", seconds=2.0,
                                 notes="from python", progress=lambda step, done, total: seen.append((step, done, total)))
    return folder, session, seen


def test_a_simulated_capture_is_what_the_command_line_writes(captured, tmp_path):
    folder, s, _ = captured
    assert s.complete and s.folder == folder
    assert (s.tool, s.surface, s.notes) == ("vero2", "office", "from python")
    assert s.capture["ended_because"] == "profile finished" and s.capture["dropped_frames"] == 0
    # Whole seconds of 1 kHz frames and 48 kHz acceleration: the counts are exact.
    assert len(s.speed_m_s) == 2000 and len(s.normal_force_N) == 2000 and len(s.acceleration) == 96000
    assert s.frame_times_s[-1] == pytest.approx(1999 / s.speed_rate_hz, rel=1e-15)
    assert s.acceleration.dtype == np.float32
    assert not s.acceleration.flags.writeable and not s.acceleration.flags.owndata  # lent, read-only
    np.testing.assert_array_equal(s.acceleration_m_s2, s.acceleration.astype(np.float64) * s.accelerometer_m_s2_per_unit)
    # The arm presses with 2.2 N; the simulated sensor's noise is 5 mN rms, so over 2000 frames its
    # mean is within a few tenths of a mN of the load (0.01 N leaves room for the motor's start).
    assert float(np.mean(s.normal_force_N)) == pytest.approx(2.2, abs=0.01)
    # The sweep rises to 250 mm/s; the speed loop follows within its 50 ms time constant.
    assert float(np.max(s.speed_m_s)) == pytest.approx(0.25, abs=0.01)
    again = nibrig.rig.session(folder)  # the library's reader, from the folder
    for name in STREAMS:
        np.testing.assert_array_equal(getattr(again, name), getattr(s, name))
    subprocess.run([nibrig_command(), "rig", "capture", "--simulated", "--tool", "vero2", "--surface", "office", "--profile",
                    "sweep", "--seconds", "2", "--speedup", "0", "-o", str(tmp_path / "cli")], check=True,
                   capture_output=True)
    cli = nibrig.rig.session(tmp_path / "cli")
    # The same request with the same seed computes the same float32 samples, to the bit.
    for name in STREAMS:
        np.testing.assert_array_equal(getattr(cli, name), getattr(s, name))
    np.testing.assert_array_equal(cli.profile_speed_m_s, s.profile_speed_m_s)


def test_a_session_pickles_with_its_streams_and_record_bit_for_bit(captured):
    folder, s, _ = captured
    again = pickle.loads(pickle.dumps(s))
    for name in STREAMS + ("profile_speed_m_s", "frame_times_s", "acceleration_m_s2"):
        np.testing.assert_array_equal(getattr(again, name), getattr(s, name))
    assert (again.folder, again.complete, again.warnings, again.tool, again.surface, again.notes, again.capture,
            again.accelerometer_m_s2_per_unit) == (s.folder, s.complete, s.warnings, s.tool, s.surface, s.notes,
                                                   s.capture, s.accelerometer_m_s2_per_unit)


def test_a_pickled_rig_is_the_rig_asked_for_and_captures_the_same_streams(captured, tmp_path):
    folder, s, _ = captured
    asked = nibrig.rig.simulated("vero2", "office", load=1.5, seed=7)
    again = pickle.loads(pickle.dumps(asked))
    for name in ("kind", "tool", "surface", "load_N", "seed", "speedup", "path", "serial"):
        assert getattr(again, name) == getattr(asked, name), name
    # Each opens the same rig afresh: the same seed and request give the same float32 samples.
    mine = nibrig.rig.capture(asked, tmp_path / "asked", profile="sweep", seconds=0.5)
    theirs = nibrig.rig.capture(again, tmp_path / "again", profile="sweep", seconds=0.5)
    for name in STREAMS:
        np.testing.assert_array_equal(getattr(theirs, name), getattr(mine, name))
    replay = pickle.loads(pickle.dumps(nibrig.rig.replay(folder)))
    assert (replay.kind, replay.path) == ("replay", folder)
    with pytest.raises(ValueError, match="not a pickled Rig"):
        nibrig.rig.Rig.__new__(nibrig.rig.Rig).__setstate__((7,) + asked.__getstate__()[1:])


def test_a_replay_gives_the_same_streams(captured, tmp_path):
    folder, s, _ = captured
    rig = nibrig.rig.replay(folder)
    assert (rig.kind, rig.tool, rig.path) == ("replay", None, folder)
    replayed = nibrig.rig.capture(rig, tmp_path / "replayed")
    assert replayed.complete and replayed.tool == "vero2"  # the session's own
    # A replay copies what was recorded: the same float32 samples.
    for name in STREAMS:
        np.testing.assert_array_equal(getattr(replayed, name), getattr(s, name))
    np.testing.assert_array_equal(replayed.profile_time_s, s.profile_time_s)
    with pytest.raises(ValueError, match="^profile: steps: .*recorded"):
        nibrig.rig.capture(rig, tmp_path / "other", profile="steps")


def test_a_comparison_has_a_row_per_speed_and_the_command_lines_numbers(tmp_path):
    rig = nibrig.rig.simulated("vero2", "office")
    c = nibrig.rig.compare(rig, None, tmp_path / "session", seconds=3.0)
    assert (c.tool, c.surface) == ("vero2", "office")
    assert c.session.complete and len(c.session.speed_m_s) == 3000
    n = len(c.bins)
    assert n == 12  # the comparison's default: 12 geometric bins over 17-250 mm/s
    for a in (c.min_speed_m_s, c.max_speed_m_s, c.rows, c.lsd_db, c.weighted_mean_log10_difference):
        assert a.shape == (n,)
    np.testing.assert_allclose(c.max_speed_m_s[:-1], c.min_speed_m_s[1:], rtol=1e-15)  # the bins tile the range
    # Every analysed row is in a bin, outside 17-250 mm/s, or without a speed: counts, exactly.
    assert c.rows.sum() == c.rows_analysed - c.rows_outside_speed_range - c.rows_without_speed
    assert c.measured_mean.shape == (n, len(c.frequencies_hz))
    assert c.measured_db.shape == (len(c.waterfall_times_s), len(c.frequencies_hz))
    assert c.blocks_dropped == 0
    c.save(tmp_path / "python.json")
    report = tmp_path / "cli"
    run = subprocess.run([nibrig_command(), "rig", "compare", "--simulated", "--tool", "vero2", "--surface", "office",
                          "--seconds", "3", "--speedup", "0", "--report", str(report)], check=True,
                         capture_output=True, text=True)
    assert f"simulated: {c.simulated} " in run.stdout
    written = json.loads((report / "comparison.json").read_text())
    assert json.loads((tmp_path / "python.json").read_text()) == written  # save() writes the same file
    assert len(written["speed_bins"]) == n
    for k, b in enumerate(written["speed_bins"]):
        assert b["rows"] == c.rows[k]
        # comparison.json keeps doubles to 17 digits and speeds in mm/s: 1e-12 is rounding.
        assert b["min_speed_mm_s"] == pytest.approx(c.min_speed_m_s[k] * 1e3, rel=1e-12)
        for key in ("lsd_db", "measured_weighted_mean", "weighted_mean_log10_difference"):
            if b[key] is None:
                assert np.isnan(getattr(c, key)[k])
            else:
                assert b[key] == pytest.approx(getattr(c, key)[k], rel=1e-12, abs=1e-12)
    assert written["overall"]["mean_lsd_db"] == pytest.approx(c.mean_lsd_db, rel=1e-12)
    assert written["capture"]["rows_analysed"] == c.rows_analysed

    # It pickles as every number it shows, bit for bit (NaN where a bin has no rows, as here).
    again = pickle.loads(pickle.dumps(c))
    for name in ("min_speed_m_s", "max_speed_m_s", "mean_speed_m_s", "rows", "lsd_db", "measured_weighted_mean",
                 "simulated_weighted_mean", "weighted_mean_log10_difference", "frequencies_hz", "measured_mean",
                 "simulated_mean", "waterfall_times_s", "waterfall_speeds_m_s", "measured_db", "simulated_db"):
        np.testing.assert_array_equal(getattr(again, name), getattr(c, name), err_msg=name)
    for name in ("tool", "surface", "simulated", "simulated_modes", "bins_with_rows", "rows_analysed",
                 "rows_outside_speed_range", "rows_without_speed", "blocks_dropped", "band_hz", "mean_lsd_db",
                 "mean_weighted_mean_log10_difference"):
        assert getattr(again, name) == getattr(c, name), name
    np.testing.assert_array_equal(again.session.acceleration, c.session.acceleration)
    again.save(tmp_path / "again.json")
    assert json.loads((tmp_path / "again.json").read_text()) == written
    with pytest.raises(ValueError, match="not a pickled Comparison"):
        nibrig.rig.Comparison.__new__(nibrig.rig.Comparison).__setstate__(("vero2",))


def test_refusals_name_what_was_asked(captured, tmp_path):
    folder, _, _ = captured
    rig = nibrig.rig.simulated("vero2", "office")
    with pytest.raises(OSError, match=str(folder)):
        nibrig.rig.capture(rig, folder, profile="sweep", seconds=0.5)
    # Each refusal begins with the argument at fault (the library's field, rig/rig_request.hpp).
    with pytest.raises(ValueError, match="^profile: zigzag"):
        nibrig.rig.capture(rig, tmp_path / "s", profile="zigzag")
    with pytest.raises(ValueError, match="^tool: .*'nope'"):
        nibrig.rig.capture(nibrig.rig.simulated("nope", "office"), tmp_path / "s", seconds=0.5)
    with pytest.raises(ValueError, match="^tool: .*'nope'"):
        nibrig.rig.compare(rig, "nope", tmp_path / "s", seconds=0.5)
    with pytest.raises(ValueError, match="^speedup: speed-up -1"):
        nibrig.rig.simulated("vero2", "office", speedup=-1)
    with pytest.raises(ValueError, match="^input_channel: 0"):
        nibrig.rig.usb(input_channel=0)
    with pytest.raises(ValueError, match="^seconds: "):
        nibrig.rig.compare(rig, "vero2", tmp_path / "s", seconds=1e-320)
    with pytest.raises(FileNotFoundError):
        nibrig.rig.session(tmp_path / "nothing")
    assert not os.path.exists(tmp_path / "s") and not os.path.exists(tmp_path / "s.partial")


def test_a_usb_rig_without_its_controller_is_an_os_error_naming_it(tmp_path):
    rig = nibrig.rig.usb(serial="NR-4242", tool="vero2", surface="office")
    with pytest.raises(OSError, match="NR-4242"):
        nibrig.rig.capture(rig, tmp_path / "usb", profile="sweep", seconds=1.0)
    assert not os.path.exists(tmp_path / "usb.partial")


def test_progress_counts_the_milliseconds_recorded(captured):
    _, _, seen = captured
    capturing = [(done, total) for step, done, total in seen if step == "capturing"]
    assert capturing and capturing[-1] == (2000, 2000)
    assert [d for d, _ in capturing] == sorted(d for d, _ in capturing)  # never backwards


def test_ctrl_c_stops_a_real_time_capture_and_finishes_its_session(tmp_path):
    folder = tmp_path / "stopped"
    interrupt = threading.Timer(0.5, lambda: os.kill(os.getpid(), signal.SIGINT))

    def progress(step, done, total):
        if step == "capturing" and done > 0 and interrupt.ident is None:
            interrupt.start()  # half a second after the turntable starts turning

    started = time.monotonic()
    with pytest.raises(KeyboardInterrupt):
        nibrig.rig.capture(nibrig.rig.simulated("vero2", "office", speedup=1), folder, profile="sweep", seconds=60,
                           progress=progress)
    stopped_after = time.monotonic() - started
    interrupt.join()
    # A minute in real time, stopped within a read (100 ms) of the signal: well under 10 s.
    assert stopped_after < 10.0
    s = nibrig.rig.session(folder)
    assert s.complete and s.capture["ended_because"] == "interrupted"
    assert 0.25 * 48000 <= len(s.acceleration) < 10 * 48000
    # Frames and acceleration stop together: within one 100 ms batch.
    assert len(s.acceleration) / 48000 == pytest.approx(len(s.speed_m_s) / 1000, abs=0.1)
