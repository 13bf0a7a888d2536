"""Shared by the Python module's tests: the recorded data beside the repository, a scratch folder."""

import os
import pathlib

import pytest

REPOSITORY = pathlib.Path(__file__).resolve().parents[3]


def shared_data() -> pathlib.Path:
    """../shared/data beside the repository, or $NIBRIG_SHARED_DATA (as the C++ suites find it)."""
    folder = pathlib.Path(os.environ.get("NIBRIG_SHARED_DATA", REPOSITORY.parent / "shared" / "data"))
    if not folder.is_dir():
        raise RuntimeError(f"no recorded data at {folder} (set NIBRIG_SHARED_DATA)")
    return folder


@pytest.fixture
def salmon() -> pathlib.Path:
    """Salmon's alien-eggs triplets (PROVENANCE.md there): 15,054 answers about 300 stimuli."""
    return shared_data() / "salmon_alien_eggs" / "responses_train.csv"
