"""nibrig.render: the samples are those `nibrig render` writes for the same tool, stroke and seed
(the engine itself is checked in the C++ suites), a seed fixes them, and bad input is refused."""

import pickle
import struct
import subprocess

import numpy as np
import pytest

import nibrig
from command_line import nibrig_command


def float_wav(path):
    """The samples of a mono float WAV, read here from its chunks."""
    data = path.read_bytes()
    assert data[:4] == b"RIFF" and data[8:12] == b"WAVE"
    at = 12
    while at < len(data):
        name, size = data[at:at + 4], struct.unpack("<I", data[at + 4:at + 8])[0]
        if name == b"data":
            return np.frombuffer(data[at + 8:at + 8 + size], dtype="<f4")
        at += 8 + size + (size & 1)
    raise AssertionError("no data chunk")


def test_a_rendering_is_what_the_command_line_renders(tmp_path):
    r = nibrig.render.tool("cryon", "office", speed=0.1, force=1.5, seconds=0.5, seed=7)
    assert len(r) == 24000 and r.rate_hz == 48000
    assert r.samples.dtype == np.float32
    assert not r.samples.flags.writeable and not r.samples.flags.owndata  # lent, read-only
    rms = float(np.sqrt(np.mean(r.samples.astype(np.float64) ** 2)))
    assert rms > 1e-4  # a crayon on paper at 100 mm/s is well above silence
    command = nibrig_command()
    subprocess.run([command, "render", "--tool", "cryon", "--surface", "office", "--speed", "100", "--force", "1.5",
                    "--seconds", "0.5", "--seed", "7", "-o", str(tmp_path / "r.wav")], check=True, capture_output=True)
    np.testing.assert_array_equal(float_wav(tmp_path / "r.wav"), r.samples)


def test_a_seed_fixes_the_samples_and_another_changes_them():
    a = nibrig.render.tool("stab", "note", speed=0.05, seconds=0.2, seed=3).samples
    b = nibrig.render.tool("stab", "note", speed=0.05, seconds=0.2, seed=3).samples
    c = nibrig.render.tool("stab", "note", speed=0.05, seconds=0.2, seed=4).samples
    np.testing.assert_array_equal(a, b)
    assert not np.array_equal(a, c)


def test_a_rendering_pickles_with_its_samples_bit_for_bit():
    r = nibrig.render.tool("stab", "note", speed=0.05, seconds=0.2, seed=3)
    again = pickle.loads(pickle.dumps(r))
    np.testing.assert_array_equal(again.samples, r.samples)
    assert (len(again), again.rate_hz, again.tool, again.stroke) == (len(r), r.rate_hz, r.tool, r.stroke)


def test_bad_input_is_refused():
    with pytest.raises(ValueError, match="nothing"):
        nibrig.render.tool("nothing", "office", speed=0.1, seconds=0.1)
    with pytest.raises(ValueError, match="rate"):
        nibrig.render.tool("cryon", "office", speed=0.1, seconds=0.1, rate_hz=100)
    with pytest.raises(ValueError):
        nibrig.render.tool("cryon", "office", speed=-1.0, seconds=0.1)
