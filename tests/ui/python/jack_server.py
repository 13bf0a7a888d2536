"""A real JACK server (the dummy driver) for the audio tests, as the C++ suites' JackServer starts one:
a name of its own, made the default for this process's clients, real-time where the machine allows."""

import itertools
import os
import subprocess
import tempfile
import threading
import time

_count = itertools.count()


def _realtime_allowed() -> bool:
    """Whether a thread of this process may run SCHED_FIFO (root, CAP_SYS_NICE or an rtprio limit)."""
    allowed = []

    def probe():
        try:
            os.sched_setscheduler(0, os.SCHED_FIFO, os.sched_param(os.sched_get_priority_min(os.SCHED_FIFO)))
            allowed.append(True)
        except OSError:
            allowed.append(False)

    thread = threading.Thread(target=probe)
    thread.start()
    thread.join()
    return allowed[0]


class JackServer:
    def __init__(self, rate: int = 48000, period: int = 256):
        self.name = f"nibrig-pytest-{os.getpid()}-{next(_count)}"
        self.rate, self.period = rate, period
        os.environ["JACK_DEFAULT_SERVER"] = self.name
        os.environ["JACK_NO_AUDIO_RESERVATION"] = "1"
        os.environ["JACK_NO_START_SERVER"] = "1"  # a client never starts a server of its own
        self._log = tempfile.NamedTemporaryFile(prefix=self.name, suffix=".log")
        self._process = None
        # Real time keeps the dummy clock on time beside compilers and other tests (recipes.md).
        self._priority = ["--realtime", "-P", "70"] if _realtime_allowed() else ["--no-realtime"]
        self.start()

    def start(self):
        if self._process is not None:
            return
        self._process = subprocess.Popen(
            ["jackd", "-n", self.name, *self._priority, "-d", "dummy", "-r", str(self.rate), "-p", str(self.period)],
            stdout=self._log, stderr=subprocess.STDOUT)
        deadline = time.monotonic() + 10
        while subprocess.run(["jack_lsp", "-s", self.name], capture_output=True).returncode != 0:
            if self._process.poll() is not None or time.monotonic() > deadline:
                raise RuntimeError(f"jackd {self.name} did not start: {open(self._log.name).read()}")
            time.sleep(0.05)

    def kill(self):
        """As a crash would: no chance to tell its clients."""
        if self._process is not None:
            self._process.kill()
            self._process.wait()
            self._process = None

    def stop(self):
        if self._process is not None:
            self._process.terminate()
            self._process.wait(timeout=10)
            self._process = None
        self._log.close()


def record(port: str, seconds: float, rate: int):
    """`seconds` of a port as an independent client hears it (jackd2's jack_rec), full scale 1."""
    import wave

    import numpy as np

    with tempfile.TemporaryDirectory() as folder:
        path = os.path.join(folder, "heard.wav")
        subprocess.run(["jack_rec", "-f", path, "-d", str(seconds), "-b", "32", port],
                       check=True, capture_output=True, timeout=seconds + 20)
        with wave.open(path) as w:
            assert w.getframerate() == rate and w.getsampwidth() == 4
            return np.frombuffer(w.readframes(w.getnframes()), dtype="<i4") / 2.0**31
