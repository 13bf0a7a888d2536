"""Every `nibrig` example command on the documentation site names a command that exists and only
options that command's --help lists; the blocks marked `runs-here` run and exit 0."""

from __future__ import annotations

import os
import shlex
import subprocess
import sys
import time
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).resolve().parent))
sys.path.insert(0, str(Path(__file__).resolve().parents[3] / "ui/docs/_ext"))

import cli_help  # noqa: E402
import site_examples  # noqa: E402


@pytest.fixture(scope="module")
def helps() -> dict[tuple[str, ...], cli_help.Help]:
    return {tuple(h.words): h for h in cli_help.every_command()}


@pytest.fixture(scope="module")
def panel() -> cli_help.Help:
    return cli_help.read([], cli_help.panel_path())


def problems(command: str, helps, panel: cli_help.Help | None = None) -> list[str]:
    """What is wrong with one example command: a command that does not exist, an option its help
    does not list."""
    words = shlex.split(command)[1:]
    if Path(shlex.split(command)[0]).name == "nibrig-panel":
        helps = {(): panel}
    path: tuple[str, ...] = ()
    rest = list(words)
    found = []
    # The longest run of words that names a command ("design loop"), past the global options
    # given before it ("nibrig -j 2 design").
    while rest:
        if path + (rest[0],) in helps:
            path += (rest.pop(0),)
            continue
        leading = {n: e for e in helps[path].global_options for n in e.names}
        entry = leading.get(rest[0].split("=", 1)[0])
        if entry is None or not helps[path].subcommands:
            break
        takes_value = entry.argument and not entry.argument.startswith("Excludes")
        del rest[:2 if takes_value and "=" not in rest[0] else 1]
    help = helps[path]
    if help.subcommands and not help.positionals and rest and not rest[0].startswith("-"):
        found.append(f"`nibrig {' '.join(path + (rest[0],))}`: no such command")
    if help.subcommands and path == () and not rest:
        found.append("`nibrig` alone: no command")
    options = help.option_names()
    for word in rest:
        if word.startswith("-") and len(word) > 1 and not word[1].isdigit():
            name = word.split("=", 1)[0]
            if name not in options:
                found.append(f"`{help.name}` has no option {name} (its --help lists "
                             f"{', '.join(sorted(options))})")
    return found


def test_the_site_has_examples_and_some_run_here():
    examples = site_examples.examples()
    assert len(examples) > 50, [e.line for e in examples]
    assert sum(e.runs_here for e in examples) >= 8


def test_every_example_names_a_command_and_options_its_help_lists(helps, panel):
    wrong = [f"{e.where}: {e.line}\n    {p}" for e in site_examples.examples()
             for p in problems(e.line, helps, panel)]
    assert not wrong, "\n".join(wrong)


def test_a_wrong_option_or_command_is_found(helps, panel):
    # The check itself: each of these must be caught, or the test above proves nothing.
    assert problems("nibrig design --target cryon/office --no-such-option 3", helps)
    assert problems("nibrig design lop --resume", helps)
    assert problems("nibrig rig capture --simulated --sweep", helps)  # --sweep is render's
    assert not problems("nibrig -v design loop --resume -o loop/", helps)
    assert not problems("nibrig rig capture --simulated --tool vero2 -o x", helps)
    assert problems("nibrig-panel --view space --no-such-option", helps, panel)
    assert not problems("nibrig-panel --view space --screenshot s.png", helps, panel)


def _runnable_blocks() -> dict[int, list[site_examples.Example]]:
    blocks: dict[int, list[site_examples.Example]] = {}
    for e in site_examples.examples():
        if e.runs_here:
            blocks.setdefault(e.block, []).append(e)
    return blocks


@pytest.mark.parametrize("block", sorted(_runnable_blocks()))
def test_a_block_marked_runs_here_runs(block, tmp_path):
    # Each block in a folder of its own, its commands in order (a capture, then its measurement),
    # with the built command in the place of `nibrig` and a user cache of its own.
    env = dict(os.environ)
    env.setdefault("NIBRIG_CACHE", str(tmp_path / "user_cache"))
    env.setdefault("LSAN_OPTIONS", f"suppressions={site_examples.REPOSITORY}/tests/lsan.supp:"
                   "print_suppressions=0")
    for e in _runnable_blocks()[block]:
        words = shlex.split(e.line)
        start = time.monotonic()
        run = subprocess.run([str(cli_help.command_path()), *words[1:]], cwd=tmp_path, env=env,
                             capture_output=True, text=True, timeout=300)
        seconds = time.monotonic() - start
        assert run.returncode == 0, f"{e.where}: {e.line}\n{run.stdout[-2000:]}{run.stderr[-2000:]}"
        print(f"{seconds:5.1f} s  {e.line}")
