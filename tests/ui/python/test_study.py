"""nibrig.study on a study two simulated participants ran through `nibrig experiment run` (six
catalog pairings on the actuator, answering from the demo's space): the answers are the lines of
their responses.csv, and the report's numbers are those `nibrig experiment report` gives for the same
settings (the statistics themselves are checked in the C++ suites)."""

import csv
import json
import pickle
import subprocess

import numpy as np
import pytest

import nibrig
from command_line import nibrig_command

PARTICIPANTS = ("P1", "P2")
REPORT = dict(bootstrap=10, starts=4, seed=3)



@pytest.fixture(scope="module")
def study(tmp_path_factory):
    """The study folder, and the CLI's report of it in <study>/report."""
    command = nibrig_command()
    root = tmp_path_factory.mktemp("study")
    truth = nibrig.space.default(bootstrap=20)
    truth.save(root / "truth.json")
    catalog = nibrig.measure.load_catalog(nibrig.measure.bundled_catalog())
    playable = [f"{p['tool']}/{p['surface']}" for p in catalog.pairings
                if p["mu"] is not None and p["weighted_mean"] is not None]
    (root / "stimuli.txt").write_text("\n".join(playable[:6]) + "\n")
    folder = root / "study"
    for participant in PARTICIPANTS:
        subprocess.run([command, "experiment", "run", "--stimuli", str(root / "stimuli.txt"), "--mode", "actuator",
                        "--participant", participant, "--simulate", str(root / "truth.json"), "-o", str(folder)],
                       check=True, capture_output=True)
    subprocess.run([command, "experiment", "report", str(folder), "--bootstrap", str(REPORT["bootstrap"]),
                    "--starts", str(REPORT["starts"]), "--seed", str(REPORT["seed"])], check=True, capture_output=True)
    return folder


def test_the_answers_are_the_participants_logged_lines(study):
    a = nibrig.study.answers(study)
    assert a.mode == "actuator" and a.plan == "two-stage" and len(a.stimuli) == 6
    assert [p["id"] for p in a.participants] == list(PARTICIPANTS)
    lines = []
    for participant in PARTICIPANTS:
        with open(study / "participants" / participant / "responses.csv", newline="") as f:
            lines += [(participant, row) for row in csv.DictReader(f)]
    assert len(a) == len(lines) == len(a.records) == len(a.trial)
    for k, (participant, row) in enumerate(lines):
        r = a.records[k]
        assert r["participant"] == a.participant[k] == participant
        assert r["trial"] == a.trial[k] == int(row["trial"])
        assert (r["reference"], r["left"], r["right"]) == (row["reference"], row["left"], row["right"])
        assert a.stimuli[a.reference[k]] == row["reference"] and a.stimuli[a.left[k]] == row["left"]
        assert r["chosen"] == row["chosen"] and a.chose_left[k] == (row["chosen"] == "left")
        assert r["practice"] == a.practice[k] == (row["practice"] == "1")
        # The log's text read as a double by both: the same double.
        assert a.response_s[k] == float(row["response_s"])
    assert a.practice.sum() == 3 * len(PARTICIPANTS)  # the default practice, per participant

    # The answers pickle as their values, bit for bit: a worker holds the study read here.
    again = pickle.loads(pickle.dumps(a))
    assert (again.folder, again.stimuli, again.mode, again.plan, again.dims, again.warnings, again.participants,
            again.records, again.participant) == (a.folder, a.stimuli, a.mode, a.plan, a.dims, a.warnings,
                                                  a.participants, a.records, a.participant)
    for name in ("trial", "practice", "stage", "reference", "left", "right", "chose_left", "response_s"):
        np.testing.assert_array_equal(getattr(again, name), getattr(a, name), err_msg=name)
    state = a.__getstate__()
    broken = (state[0], state[1], [state[2][0][:4] + ([state[2][0][4][0][:2] + (99,) + state[2][0][4][0][3:]],)],
              state[3])
    with pytest.raises(ValueError, match="not a pickled Answers"):  # an answer naming a 100th stimulus of 6
        nibrig.study.Answers.__new__(nibrig.study.Answers).__setstate__(broken)


def test_the_report_is_what_the_command_line_reports(study, tmp_path):
    seen = []
    r = nibrig.study.report(study, output=tmp_path / "report", progress=lambda *report: seen.append(report), **REPORT)
    assert r.folder == tmp_path / "report"
    cli = json.loads((study / "report" / "report.json").read_text())
    assert (r.selection, r.triplets, r.responses) == ("paper", cli["triplets"], cli["responses"])
    # The same judgments written by the same writer.
    assert (tmp_path / "report" / "judgments.csv").read_text() == (study / "report" / "judgments.csv").read_text()
    assert r.with_descriptors and cli["space"]["with_descriptors"]
    space = r.space
    assert isinstance(space, nibrig.space.Space) and space.has_descriptor_map
    # The same fit (seed, starts and data): the CLI's space.json keeps 17 significant digits.
    np.testing.assert_allclose(space.coordinates, nibrig.space.load(study / "report" / "space.json").coordinates,
                               rtol=0, atol=1e-12)
    assert r.mean_region_sd == pytest.approx(cli["space"]["mean_region_sd"], rel=1e-12)
    assert [p["id"] for p in r.participants] == [p["id"] for p in cli["participants"]] == list(PARTICIPANTS)
    for mine, theirs in zip(r.participants, cli["participants"]):
        assert (mine["answers"], mine["practice"]) == (theirs["answers"], theirs["practice"])
        assert mine["median_response_s"] == pytest.approx(theirs["median_response_s"], rel=1e-12)
        for which in ("agreement_with_space", "agreement_with_others"):
            for key in ("agreements", "trials", "fraction", "z", "p_value"):
                # Sums of halves and wholes, then the normal tail: equal to rounding in the JSON.
                assert mine[which][key] == pytest.approx(theirs[which][key], rel=1e-12, abs=1e-300)
    # The latest report reaches the callable (a quicker one may be overtaken); the last is the
    # bootstrap's end.
    assert seen[-1] == ("bootstrap refits", REPORT["bootstrap"], REPORT["bootstrap"])
    assert all(0 <= done <= total for _, done, total in seen)

    # The report pickles as what it shows; its space as the Space pickles, predicting the same.
    again = pickle.loads(pickle.dumps(r))
    for name in ("folder", "mode", "plan", "stimuli", "selection", "triplets", "responses", "judgments_file",
                 "with_descriptors", "mean_region_sd", "participants", "validation", "warnings"):
        assert getattr(again, name) == getattr(r, name), name
    np.testing.assert_array_equal(again.space.coordinates, space.coordinates)
    # What it shows are copies: changing one leaves the report as it was.
    r.participants[0]["id"] = "changed"
    assert r.participants[0]["id"] == PARTICIPANTS[0]


def test_the_reports_counts_follow_from_the_answers(study, tmp_path):
    a = nibrig.study.answers(study)
    r = nibrig.study.report(study, output=tmp_path / "report", all_judgments=True, bootstrap=0, starts=2)
    assert r.selection == "every answer"
    assert r.responses == int((~a.practice).sum())  # every main answer once
    participant = np.array(a.participant)
    for p in r.participants:
        main = (participant == p["id"]) & ~a.practice
        assert p["answers"] == int(main.sum())
        # The library's median is the upper one (the higher middle of an even count): picked, not
        # computed, so it is one of the same doubles exactly.
        times = np.sort(a.response_s[main])
        assert p["median_response_s"] == times[len(times) // 2]
        agreement = p["agreement_with_space"]
        assert agreement["fraction"] == pytest.approx(agreement["agreements"] / agreement["trials"], rel=1e-15)
        # Simulated from a space with a lapse-free model: far better than chance.
        assert agreement["fraction"] > 0.6


def test_bad_folders_and_settings_are_python_errors(study, tmp_path):
    with pytest.raises(FileNotFoundError, match="nothing"):
        nibrig.study.answers(tmp_path / "nothing")
    with pytest.raises(ValueError, match="bootstrap"):
        nibrig.study.report(study, output=tmp_path / "r", bootstrap=-1)
    with pytest.raises(ValueError, match="starts"):
        nibrig.study.report(study, output=tmp_path / "r", starts=0)


def test_a_space_given_to_a_study_that_does_not_validate_is_refused_and_kept(study, tmp_path):
    # The trial's `report(study, output=out, space=out/"space.json")` fitted a space over the one given.
    out = tmp_path / "out"
    out.mkdir()
    kept = (study.parent / "truth.json").read_bytes()
    (out / "space.json").write_bytes(kept)
    with pytest.raises(ValueError, match="validation study only"):
        nibrig.study.report(study, output=out, space=out / "space.json", bootstrap=0, starts=2)
    assert (out / "space.json").read_bytes() == kept
    assert not (out / "judgments.csv").exists()


def test_a_validation_study_is_scored_against_its_space_as_the_command_line_scores_it(study, tmp_path):
    # Sec. 6.1: candidates judged against the first stimulus, here by three simulated participants
    # answering from the space the study is then scored against.
    command = nibrig_command()
    root = study.parent
    folder = tmp_path / "validation"
    for participant in ("V1", "V2", "V3"):
        subprocess.run([command, "experiment", "run", "--stimuli", str(root / "stimuli.txt"), "--mode",
                        "validation", "--practice", "0", "--participant", participant, "--simulate",
                        str(root / "truth.json"), "-o", str(folder)], check=True, capture_output=True)
    subprocess.run([command, "experiment", "report", str(folder), "--space", str(root / "truth.json")],
                   check=True, capture_output=True)
    cli = json.loads((folder / "report" / "report.json").read_text())["validation"]
    r = nibrig.study.report(folder, output=tmp_path / "report", space=root / "truth.json")
    assert r.mode == "validation" and r.space is None
    v = r.validation
    assert len(v["triplets"]) == len(cli["triplets"]) == 10  # the pairs of five candidates
    for mine, theirs in zip(v["triplets"], cli["triplets"]):
        assert (mine["reference"], mine["a"], mine["b"]) == (theirs["reference"], theirs["a"], theirs["b"])
        assert (mine["count_a"], mine["count_b"]) == (theirs["count_a"], theirs["count_b"])
        # The space's Φ of the same distances, kept to 17 digits in the JSON.
        assert mine["predicted_p_a"] == pytest.approx(theirs["predicted_p_a"], rel=1e-12)
    for which in ("majority_agreement", "individual_agreement"):
        for key in ("agreements", "trials", "fraction", "z"):
            assert v[which][key] == pytest.approx(cli[which][key], rel=1e-12)
    assert v["mean_absolute_error"] == pytest.approx(cli["mean_absolute_error"], rel=1e-12)
    again = pickle.loads(pickle.dumps(r))
    assert again.validation == v and again.space is None
    with pytest.raises(ValueError, match="space"):
        nibrig.study.report(folder, output=tmp_path / "unscored")  # a validation study needs its space
    # The space named as one of the report's own files: the call is one job, and its input is kept.
    for name in ("judgments.csv", "report.json"):
        out = tmp_path / ("onto_" + name)
        out.mkdir()
        (out / name).write_bytes((root / "truth.json").read_bytes())
        with pytest.raises(OSError, match="would replace .*" + name.replace(".", r"\.")):
            nibrig.study.report(folder, output=out, space=out / name)
        assert (out / name).read_bytes() == (root / "truth.json").read_bytes()
