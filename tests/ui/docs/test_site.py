"""The documentation site builds with warnings as errors (a broken link, a missing picture, a
docstring that does not parse fail it), with a page per command holding every option its --help
lists, the Python reference from the module, and the pictures of the pages it includes."""

from __future__ import annotations

import html
import os
import re
import subprocess
import sys
from pathlib import Path

import pytest

REPOSITORY = Path(__file__).resolve().parents[3]
sys.path.insert(0, str(REPOSITORY / "ui/docs/_ext"))

import cli_help  # noqa: E402


@pytest.fixture(scope="module")
def site(tmp_path_factory) -> Path:
    out = Path(os.environ.get("NIBRIG_DOCS_OUTPUT") or tmp_path_factory.mktemp("html"))
    run = subprocess.run(
        ["/usr/bin/python3", "-m", "sphinx", "-W", "--keep-going", "-E", "-q", "-b", "html",
         str(REPOSITORY / "ui/docs"), str(out)],
        capture_output=True, text=True, timeout=900)
    assert run.returncode == 0, run.stdout[-4000:] + run.stderr[-8000:]
    assert run.stderr == "", run.stderr  # -q leaves only warnings, and there must be none
    return out


def test_every_command_has_a_page_with_every_option_its_help_lists(site):
    commands = cli_help.every_command()
    assert len(commands) > 40
    for help in commands:
        page = site / "commands" / (cli_help.page_name(help.words) + ".html")
        assert page.is_file(), page
        # The page's text, its literals' words split across tags joined again.
        raw = page.read_text()
        text = html.unescape(re.sub(r"<[^>]+>", "", raw))
        for entry in help.options + help.positionals:
            assert ", ".join(entry.names) in text, f"{page.name}: {entry.names}"
        for sub in help.subcommands:
            assert f'href="{cli_help.page_name([*help.words, sub.names[0]])}.html"' in raw, \
                f"{page.name}: no link to {sub.names[0]}"


def test_every_manual_page_command_has_a_site_page_with_its_options(site):
    # The manual pages come from the CLI11 tree itself (ui/cli/help_pages.cpp), not from --help's
    # text, so a command or option the site's --help reader missed is caught here.
    manuals = sorted(Path(os.environ["NIBRIG_MAN_DIR"]).glob("nibrig*.1"))
    assert len(manuals) > 40
    for manual in manuals:
        roff = manual.read_text().replace("\\-", "-")
        words = re.search(r"^\.B nibrig(.*)$", roff, re.M).group(1).split()
        names = [re.sub(r"\\fR.*", "", line[3:])
                 for before, line in zip(roff.splitlines(), roff.splitlines()[1:])
                 if before == ".TP" and line.startswith("\\fB")]
        assert names, manual.name
        page = site / "commands" / (cli_help.page_name(words) + ".html")
        assert page.is_file(), f"{manual.name}: no {page.name}"
        text = html.unescape(re.sub(r"<[^>]+>", "", page.read_text()))
        for name in names:
            assert ", ".join(name.split(",")) in text, f"{page.name}: {name} (from {manual.name})"


def test_the_python_reference_documents_each_submodule_from_its_docstrings(site):
    sys.path.insert(0, os.environ.get("NIBRIG_PYTHON", str(REPOSITORY / "build/release/python")))
    import nibrig  # the module the site was built from

    text = html.unescape((site / "python/reference.html").read_text())
    for name in ("measure", "space", "design", "render", "audition", "rig", "study"):
        module = getattr(nibrig, name)
        assert f'id="module-nibrig.{name}"' in text
        for member in (m for m in module.__all__ if callable(getattr(module, m))):
            assert f'id="nibrig.{name}.{member}"' in text, f"nibrig.{name}.{member}"
    # A docstring's text after its signature line, as help() shows it.
    summary = nibrig.space.fit.__doc__.split("\n\n", 1)[1][:30]
    assert summary in text, summary


def test_the_included_guides_bring_their_pictures(site):
    images = {p.name for p in (site / "_images").iterdir()}
    assert "wiring.svg" in images  # rig/HARDWARE.md's
    assert {f"python_{i}.png" for i in range(1, 7)} <= images
    assert {"design_path.png", "panel_space.png", "panel_design.png"} <= images
