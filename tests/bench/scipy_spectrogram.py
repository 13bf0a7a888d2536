#!/usr/bin/python3
"""Times scipy.signal.spectrogram on the input of bench_spectrogram.cpp (same formula, same LCG).

Run with Debian's interpreter, which has numpy and scipy:  /usr/bin/python3 tests/bench/scipy_spectrogram.py
Prints milliseconds per call (median of repeats) and the checksum that the C++ benchmark prints as its
`checksum` counter, so that the two are known to compute the same spectrogram.
"""
import time

import numpy as np
from scipy import signal

RATE = 48000.0
SAMPLES = 60 * 48000
MASK = (1 << 64) - 1


def make_input():
    s = 1
    raw = np.empty(SAMPLES, dtype=np.uint64)
    for n in range(SAMPLES):  # sequential LCG: a plain loop, a few seconds, not timed
        s = (s * 6364136223846793005 + 1442695040888963407) & MASK
        raw[n] = s >> 11
    noise = raw.astype(np.float64) * 2.0 ** -53 - 0.5
    t = np.arange(SAMPLES, dtype=np.float64) / RATE
    return 0.5 * np.sin(2 * np.pi * 440.0 * t) + 0.25 * np.sin(2 * np.pi * 1234.5 * t) + noise


def main():
    x = make_input()
    for length in (1024, 4096):
        kwargs = dict(fs=RATE, window="hann", nperseg=length, noverlap=3 * length // 4,
                      detrend="constant", scaling="spectrum", mode="magnitude")
        signal.spectrogram(x, **kwargs)  # warm-up
        times = []
        for _ in range(7):
            start = time.perf_counter()
            f, t, sxx = signal.spectrogram(x, **kwargs)
            times.append(time.perf_counter() - start)
        # scipy's magnitude is |X|/sum(w) on every bin; nibrig's peak amplitude doubles the interior bins.
        checksum = 2.0 * sxx[1:-1, :].sum() + sxx[0, :].sum() + sxx[-1, :].sum()
        print(f"scipy.signal.spectrogram segment={length}: {1e3 * np.median(times):.1f} ms per call "
              f"({len(t)} segments x {len(f)} bins), checksum={checksum:.12g}")


if __name__ == "__main__":
    main()
