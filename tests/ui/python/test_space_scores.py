"""nibrig.space's scores: Space.evaluate against the same scores computed here from the space's own
predictions and Salmon's answers, and validate against what `nibrig space validate` writes."""

import json
import math
import subprocess

import numpy as np
import pytest

import nibrig
from command_line import nibrig_command


def salmon_triplets(path):
    """(reference, first, second) per answer, the answer first: Salmon's rows put it in 'Answer'."""
    out = []
    with open(path) as rows:
        next(rows)
        for row in rows:
            _, _, center, left, right, answer = row.split(",")[:6]
            out.append((center, answer, right if answer == left else left))
    return out


def test_evaluate_scores_the_predictions_of_the_answers(salmon):
    space = nibrig.space.fit(salmon, dims=1, starts=4)
    e = space.evaluate(salmon)
    triplets = salmon_triplets(salmon)
    # Each triplet of Salmon's was answered once, so the observed probability of the answer is 1.
    p = space.predict(triplets)
    assert e.triplets == e.responses == len(triplets) == e.majority_trials
    agreement = np.mean(p > 0.5) + 0.5 * np.mean(p == 0.5)
    # Sums of 15,054 terms in another order: round-off of ~1e-12 relative.
    assert e.majority_agreement == pytest.approx(agreement, rel=1e-9)
    assert e.individual_agreement == pytest.approx(agreement, rel=1e-9)
    assert e.mean_absolute_error == pytest.approx(np.mean(1 - p), rel=1e-9)
    assert e.log_loss == pytest.approx(np.mean(-np.log(np.maximum(p, 1e-12))), rel=1e-9)
    n = len(triplets)
    assert e.majority_z == pytest.approx((agreement * n - n / 2) / math.sqrt(n / 4), rel=1e-9)
    assert e.pearson is None and "every observed probability is 1" in e.no_correlation_because
    assert e.placed_from_descriptors == 0
    judgments = nibrig.space.read_judgments(salmon)
    assert space.evaluate(judgments).majority_agreement == e.majority_agreement


def test_validate_gives_what_the_command_line_writes(salmon, tmp_path):
    v = nibrig.space.validate(salmon, dims=[1, 2], folds=3, starts=2, seed=4)
    assert (v.triplets, v.responses) == (15054, 15054)
    assert [(q["dims"], q["lambda"], q["model"]) for q in v.points] == [(1, 0.0, "probit"), (2, 0.0, "probit")]
    for q in v.points:
        # Held-out error of a crowd that agrees ~85 % with a 1-D space: the paper's kind of number.
        assert 0.1 < q["mean_error"] < 0.3 and 0.5 < q["majority_agreement"] < 1
    # Salmon's items are positions on a line: a 1-D fit orders them (the sign is arbitrary).
    assert abs(v.rank_correlation_with_names["r"]) > 0.95 and v.rank_correlation_with_names["n"] == 300
    command = nibrig_command()
    subprocess.run([command, "space", "validate", str(salmon), "--dims", "1,2", "--folds", "3", "--starts", "2",
                    "--seed", "4", "-o", str(tmp_path / "v.json")], check=True, capture_output=True)
    written = json.loads((tmp_path / "v.json").read_text())
    for ours, theirs in zip(v.points, written["points"], strict=True):
        for key in ("mean_error", "sd_error", "majority_agreement", "individual_agreement", "log_loss"):
            # The same seeded folds and starts: the same doubles, through JSON's 17 digits.
            assert ours[key] == pytest.approx(theirs[key], abs=1e-12), key
    assert v.rank_correlation_with_names["r"] == pytest.approx(written["rank_correlation_with_names"]["rho"], abs=1e-12)


def test_validate_refuses_what_it_cannot_do(salmon):
    with pytest.raises(ValueError, match="folds"):
        nibrig.space.validate(salmon, folds=1)
    with pytest.raises(ValueError, match="catalog"):
        nibrig.space.validate(salmon, dims=[1], lambdas=[0.5])
    with pytest.raises(ValueError, match="nothing"):
        nibrig.space.validate(salmon, dims=[1], models=["nothing"])


def test_progress_counts_fold_fits(salmon):
    seen = []
    nibrig.space.validate(salmon, dims=[1], folds=2, starts=1, progress=lambda step, done, total: seen.append((done, total)))
    assert seen and seen[-1] == (2, 2)
