"""The example notebook (ui/python/examples/science_path.ipynb) runs top to bottom with nbclient on
Debian's ipykernel, draws its six figures, offers the rendering as audio, and finds numbers that
hold: the measured tools where the bundled catalog put them, a search optimum no farther than the
line's ends, a rendering of the length asked."""

import base64
import json
import os
import pathlib

import nbclient
import nbformat
import pytest

NOTEBOOK = pathlib.Path(__file__).resolve().parents[3] / "ui" / "python" / "examples" / "science_path.ipynb"


@pytest.fixture(scope="module")
def executed(tmp_path_factory):
    os.environ["PYDEVD_DISABLE_FILE_VALIDATION"] = "1"  # ipykernel's debugger warns of frozen modules otherwise
    nb = nbformat.read(NOTEBOOK, as_version=4)
    # The kernel inherits this environment (PYTHONPATH: the tree's module); it runs in a scratch folder.
    nbclient.NotebookClient(nb, timeout=600, kernel_name="python3",
                            resources={"metadata": {"path": str(tmp_path_factory.mktemp("notebook"))}}).execute()
    return nb


def outputs(nb, kind):
    return [o for cell in nb.cells if cell.cell_type == "code" for o in cell.outputs if kind in o.get("data", {})]


def test_it_draws_six_figures_and_offers_the_sound(executed):
    figures = outputs(executed, "image/png")
    assert len(figures) == 6
    for f in figures:
        assert base64.b64decode(f["data"]["image/png"])[:8] == b"\x89PNG\r\n\x1a\n"
    (audio,) = outputs(executed, "text/html")
    assert "<audio" in audio["data"]["text/html"]
    folder = os.environ.get("NIBRIG_NOTEBOOK_FIGURES")  # the README's pictures are written so
    if folder:
        for k, f in enumerate(figures, start=1):
            (pathlib.Path(folder) / f"python_{k}.png").write_bytes(base64.b64decode(f["data"]["image/png"]))


def test_its_numbers_hold(executed):
    summary = json.loads("".join(executed.cells[-1].outputs[0]["text"]))
    import nibrig

    bundled = {(p["tool"], p["surface"]): p for p in nibrig.measure.load_catalog(nibrig.measure.bundled_catalog()).pairings}
    assert sorted(p["tool"] for p in summary["catalog"]) == ["cryon", "stab", "teflon2", "vero2"]
    for p in summary["catalog"]:
        b = bundled[(p["tool"], p["surface"])]
        # The simulated rig plays the catalog's tool with the sensors' noise: μ within 0.01, as the rig's
        # own test (SimulatedRig) holds it; the weighted mean averages hundreds of bins over six speeds,
        # so noise that leaves single bins within 2.3 dB moves it by under 1 % (0.6 % seen): 5 %.
        assert p["mu"] == pytest.approx(b["mu"], abs=0.01), p["tool"]
        assert p["weighted_mean"] == pytest.approx(b["weighted_mean"], rel=0.05), p["tool"]
    assert summary["measured"]["mu"] == next(p["mu"] for p in summary["catalog"] if p["tool"] == "cryon")
    search = summary["search"]
    assert search["distance"] <= min(search["ends"])
    render = summary["render"]
    assert render["samples"] == 3 * render["rate_hz"] and render["rms"] > 1e-4
