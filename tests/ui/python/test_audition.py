"""nibrig.audition on a real JACK server, heard by an independent client (jackd2's jack_rec): each
slot plays its tool at the level the offline render of the same tool and stroke has, speed and force
set while it plays change it as the render says, stop is silence, no call waits for the audio
thread, and bad input is refused."""

import time

import numpy as np
import pytest

import nibrig
from jack_server import JackServer, record

RATE = 48000
# 1 s of narrow-band noise: in trials, live and offline levels of the same tool and stroke agreed
# within 1 dB; 1.5 dB leaves room for a loaded machine. Tools 10 dB apart tell the slots apart.
TOLERANCE_DB = 1.5
LOUD, QUIET, MIDDLE = "penh_DM85", "stab", "cryon"  # -25.5, -35.8, -33.2 dB full scale at 0.1 m/s on office


@pytest.fixture(scope="module")
def server():
    s = JackServer(rate=RATE)
    yield s
    s.stop()


def level_db(samples) -> float:
    return 20 * np.log10(np.sqrt(np.mean(np.asarray(samples, dtype=np.float64) ** 2)))


def heard_db(seconds=1.0) -> float:
    """The player's last `seconds` of a recording that starts 0.2 s after a change (crossfade, ramps)."""
    time.sleep(0.2)
    return level_db(record("pyaudition:outport 0", seconds + 0.5, RATE)[-int(seconds * RATE):])


def offline_db(tool, speed, force=2.2, seconds=1.0) -> float:
    r = nibrig.render.tool(tool, "office", speed=speed, force=force, seconds=seconds + 1.0, rate_hz=RATE)
    return level_db(r.samples[-int(seconds * RATE):])


def test_the_jack_server_is_listed_with_its_rate(server):
    (jack,) = nibrig.audition.devices("jack")
    assert jack["available"]
    (system,) = [d for d in jack["devices"] if d["name"] == "system"]
    assert system["outputs"] == 2 and system["preferred_rate_hz"] == RATE


def test_slots_play_their_tools_speed_and_force_change_them_and_stop_is_silence(server):
    with nibrig.audition.Player("jack", "system", name="pyaudition") as player:
        assert player.stream["rate_hz"] == RATE  # the device's own rate when none is asked
        assert player.status == "running"
        player.play([LOUD, QUIET, MIDDLE], "office", speed=0.1)
        assert player.names == [f"{t} on office" for t in (LOUD, QUIET, MIDDLE)] and player.selected == "A"
        a = heard_db()
        assert a == pytest.approx(offline_db(LOUD, 0.1), abs=TOLERANCE_DB)
        player.select("B")
        assert player.selected == "B"
        b = heard_db()
        assert b == pytest.approx(offline_db(QUIET, 0.1), abs=TOLERANCE_DB)
        assert a - b > 7  # the 10 dB between the tools, less both tolerances: the slot really switched
        player.select(2)
        assert heard_db() == pytest.approx(offline_db(MIDDLE, 0.1), abs=TOLERANCE_DB)

        player.select("a")
        player.speed = 0.2
        assert heard_db() == pytest.approx(offline_db(LOUD, 0.2), abs=TOLERANCE_DB)
        player.force = 1.0
        assert (player.speed, player.force) == (0.2, 1.0)
        assert heard_db() == pytest.approx(offline_db(LOUD, 0.2, force=1.0), abs=TOLERANCE_DB)

        player.stop()
        time.sleep(0.2)
        heard = record("pyaudition:outport 0", 1.0, RATE)[-RATE // 2:]
        assert np.max(np.abs(heard)) == 0.0  # the engine adds nothing of its own to silence
        stats = player.stats
        assert stats["losses"] == 0 and stats["callbacks"] > 0
    assert player.status == "closed"


def test_no_call_waits_for_the_audio_thread(server):
    player = nibrig.audition.Player("jack", "system", name="pyheld")
    player.play([MIDDLE, QUIET], "office", speed=0.05)
    server.kill()
    deadline = time.monotonic() + 20
    while player.status != "lost" and time.monotonic() < deadline:
        time.sleep(0.01)
    assert player.status == "lost"
    # With no callback draining the engine's queue (256 commands), these all return and the rest is held.
    for i in range(500):
        player.select(i % 2)
    assert player.pending > 0
    server.start()
    deadline = time.monotonic() + 30
    while player.pending > 0 and time.monotonic() < deadline:
        time.sleep(0.05)
    assert player.pending == 0
    assert player.stats["reconnects"] >= 1
    player.close()


def test_bad_input_is_refused(server):
    with pytest.raises(OSError, match="nothing"):
        nibrig.audition.Player("jack", "nothing")
    with nibrig.audition.Player("jack", "system", name="pybad") as player:
        with pytest.raises(ValueError, match="one to three"):
            player.play([MIDDLE] * 4, "office")
        with pytest.raises(ValueError, match="nothing"):
            player.play(["nothing"], "office")
        player.play([MIDDLE, QUIET], "office")
        with pytest.raises(ValueError, match="slot C holds no tool"):
            player.select("C")
        with pytest.raises(ValueError, match="'D'"):
            player.select("D")
        with pytest.raises(ValueError, match="speed"):
            player.speed = -1.0
        with pytest.raises(ValueError, match="force"):
            player.force = float("nan")
        with pytest.raises(ValueError, match="speed"):
            player.play([MIDDLE], "office", speed=0.1, sweep=True)
    with pytest.raises(ValueError, match="closed"):
        player.select("A")
