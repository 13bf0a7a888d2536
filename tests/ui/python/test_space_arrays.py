"""nibrig.space for a scientist who works with arrays: judgments made from arrays fit and score as the
same judgments read from a file do, nothing read or written; spaces and judgments pickle; the
estimator runs under scikit-learn's cross-validation; the log goes to Python's logging; the models
are listed; errors name the Python argument."""

import copy
import logging
import os
import pickle
import subprocess

import numpy as np
import pytest

import nibrig
from command_line import nibrig_command
from conftest import shared_data


def arrays_of(judgments):
    """The judgments' arrays, copied out as a script would hold them."""
    return np.array(judgments.triplets), list(judgments.stimuli), np.array(judgments.counts)


def simulated_answers(count, stimuli=10, seed=3):
    """Triplets of a 2-D observer (logistic, scale 3) with one answer each: X, y and the truth."""
    rng = np.random.default_rng(seed)
    truth = rng.normal(size=(stimuli, 2))
    X = np.array([rng.choice(stimuli, 3, replace=False) for _ in range(count)])
    d = lambda i, j: np.linalg.norm(truth[i] - truth[j], axis=-1)  # noqa: E731
    p_first = 1 / (1 + np.exp(-3 * (d(X[:, 0], X[:, 2]) - d(X[:, 0], X[:, 1]))))
    return X, (rng.random(count) < p_first).astype(np.int64), truth


def test_judgments_from_arrays_fit_and_score_as_the_file_does(salmon, tmp_path, monkeypatch):
    triplets, stimuli, counts = arrays_of(nibrig.space.read_judgments(salmon))
    assert triplets.shape == (15054, 3) and counts.shape == (15054, 2) and len(stimuli) == 300
    assert counts.sum() == 15054  # one answer per row of Salmon's
    monkeypatch.chdir(tmp_path)  # the arrays' fit and score touch no file: this folder stays empty
    from_arrays = nibrig.space.Judgments(triplets, stimuli, counts=counts)
    assert from_arrays.file is None and len(from_arrays) == 15054
    space = nibrig.space.fit(from_arrays, dims=2, starts=2)
    scores = space.evaluate(from_arrays)
    assert os.listdir(tmp_path) == []
    assert space.judgments == "judgments given as arrays"
    # The same triplets, counts and seed: the same doubles as the fit of the file.
    from_file = nibrig.space.fit(salmon, dims=2, starts=2)
    np.testing.assert_array_equal(space.coordinates, from_file.coordinates)
    assert scores.log_loss == from_file.evaluate(salmon).log_loss


def test_answers_counts_and_ordered_rows_are_three_ways_to_the_same_judgments():
    X, y, _ = simulated_answers(200)
    by_answers = nibrig.space.Judgments(X, answers=y)
    # The rows put in (reference, the closer, the farther) order, and as counts.
    ordered = np.where(y[:, None] == 1, X, X[:, [0, 2, 1]])
    by_order = nibrig.space.Judgments(ordered)
    by_counts = nibrig.space.Judgments(X, counts=np.column_stack([y, 1 - y]))
    np.testing.assert_array_equal(by_answers.counts, by_counts.counts)
    assert by_answers.stimuli == [str(k) for k in range(10)]
    a = nibrig.space.fit(by_answers, dims=2, starts=2)
    b = nibrig.space.fit(by_order, dims=2, starts=2)
    # A triplet and its mirror with the counts swapped are the same evidence: the same likelihood.
    assert a.negative_log_likelihood == pytest.approx(b.negative_log_likelihood, rel=1e-9)


def test_bad_arrays_are_refused_naming_the_argument():
    X, y, _ = simulated_answers(20)
    with pytest.raises(TypeError, match="triplets: expected integers"):
        nibrig.space.Judgments(X.astype(float))
    with pytest.raises(ValueError, match=r"triplets: expected shape \(n, 3\)"):
        nibrig.space.Judgments(X[:, :2])
    with pytest.raises(ValueError, match=r"answers\[3\]: 2"):
        bad = y.copy()
        bad[3] = 2
        nibrig.space.Judgments(X, answers=bad)
    with pytest.raises(ValueError, match="answers and counts"):
        nibrig.space.Judgments(X, answers=y, counts=np.ones((20, 2), dtype=int))
    with pytest.raises(ValueError, match=r"triplets\[0, 1\]: 12 is not a stimulus index"):
        nibrig.space.Judgments(np.array([[0, 12, 1]]), ["a", "b", "c"])
    with pytest.raises(ValueError, match=r"triplets\[0\]: expected three different stimuli"):
        nibrig.space.Judgments(np.array([[1, 1, 2]]))
    with pytest.raises(ValueError, match=r"counts\[0, 1\]: -1"):
        nibrig.space.Judgments(np.array([[0, 1, 2]]), counts=np.array([[1, -1]]))
    with pytest.raises(TypeError, match="judgments: expected Judgments"):
        nibrig.space.fit(X)
    judgments = nibrig.space.Judgments(X, answers=y)
    # The library's bounds, in the arguments' names.
    with pytest.raises(ValueError, match="^descriptors: none, with lam above 0: it ties the axes to the descriptors"):
        nibrig.space.fit(judgments, lam=0.5)
    with pytest.raises(ValueError, match="^lam: -1: expected a weight from 0 to 10000"):
        nibrig.space.fit(judgments, lam=-1.0)
    with pytest.raises(ValueError, match="^bootstrap: 1: expected a number of resamples"):
        nibrig.space.fit(judgments, bootstrap=1)
    with pytest.raises(ValueError, match="^lambdas: 10000.5: expected a weight from 0 to 10000"):
        nibrig.space.validate(judgments, lambdas=[0.0, 0.5 + 1e4])
    with pytest.raises(ValueError, match="^folds: 1: expected a number of folds, 2 to 100"):
        nibrig.space.validate(judgments, folds=1)


def test_predict_takes_indices_as_names_and_refuses_a_reference_among_the_candidates():
    X, y, _ = simulated_answers(300)
    space = nibrig.space.fit(nibrig.space.Judgments(X, answers=y), dims=2, starts=2)
    by_index = space.predict(X[:40])
    by_name = space.predict([tuple(space.stimuli[i] for i in row) for row in X[:40]])
    np.testing.assert_array_equal(by_index, by_name)
    with pytest.raises(ValueError, match=r"triplets\[0\]: expected three different stimuli"):
        space.predict([(0, 0, 1)])
    with pytest.raises(ValueError, match=r"triplets\[0\]: 10 is not a stimulus index"):
        space.predict(np.array([[0, 1, 10]]))


def test_a_pickled_space_judgments_and_scores_are_the_originals():
    X, y, _ = simulated_answers(300)
    judgments = nibrig.space.Judgments(X, answers=y)
    space = nibrig.space.fit(judgments, dims=2, starts=2, bootstrap=4)
    for copied in (pickle.loads(pickle.dumps(space)), copy.deepcopy(space), copy.copy(space)):
        # The space's text keeps every double: the same predictions, bit for bit.
        np.testing.assert_array_equal(copied.predict(X), space.predict(X))
        assert copied.stimuli == space.stimuli and copied.warnings == space.warnings
    scores = space.evaluate(judgments)
    scores_again = pickle.loads(pickle.dumps(scores))
    for name in ("triplets", "responses", "majority_agreement", "majority_z", "majority_p_value",
                 "individual_agreement", "mean_absolute_error", "log_loss", "pearson", "no_correlation_because"):
        assert getattr(scores_again, name) == getattr(scores, name), name
    validation = nibrig.space.validate(judgments, dims=[1, 2], folds=3, starts=1)
    validation_again = pickle.loads(pickle.dumps(validation))
    assert validation_again.points == validation.points
    assert (validation_again.triplets, validation_again.responses) == (validation.triplets, validation.responses)
    assert validation_again.rank_correlation_with_names == validation.rank_correlation_with_names
    again = pickle.loads(pickle.dumps(judgments))
    np.testing.assert_array_equal(again.triplets, judgments.triplets)
    np.testing.assert_array_equal(again.counts, judgments.counts)
    np.testing.assert_array_equal(nibrig.space.fit(again, dims=2, starts=2).coordinates, space.coordinates)


def test_the_estimator_runs_under_scikit_learns_cross_validation_and_grid_search():
    from sklearn.base import clone  # Debian's python3-sklearn, which setup.sh test installs
    from sklearn.model_selection import GridSearchCV, cross_val_score

    X, y, truth = simulated_answers(1200, stimuli=12)
    estimator = nibrig.space.SpaceEstimator(dims=2, starts=2, n_stimuli=12)
    scores = cross_val_score(estimator, X, y, cv=4)
    assert scores.shape == (4,)
    # The observer's answers follow its own logistic model with scale 3: a 2-D fit predicts held-out
    # answers near that model's own rate (~0.8 here) and far from chance; 0.7 leaves room for four
    # fits on 900 answers each.
    assert np.all(scores > 0.7), scores
    search = GridSearchCV(estimator, {"dims": [1, 2]}, cv=3).fit(X, y)
    assert search.best_params_ == {"dims": 2}  # the truth is 2-D
    fitted = clone(estimator).fit(X, y)
    assert fitted.embedding_.shape == (12, 2)
    proba = fitted.predict_proba(X)
    np.testing.assert_allclose(proba.sum(axis=1), 1.0, rtol=0, atol=1e-15)
    np.testing.assert_array_equal(proba[:, 1], fitted.space_.predict(X))
    assert fitted.score(X, y) == np.mean((proba[:, 1] >= 0.5) == y)
    assert pickle.loads(pickle.dumps(fitted)).score(X, y) == fitted.score(X, y)
    with pytest.raises(ValueError, match="wobble: not a parameter"):
        estimator.set_params(wobble=1)


def test_the_log_goes_to_pythons_logging_and_not_to_the_terminal(capfd, caplog, tmp_path, monkeypatch):
    # A prediction without a forcing model names the default it reads, at INFO: from the C++ log.
    monkeypatch.setenv("NIBRIG_CACHE", os.environ.get("NIBRIG_CACHE", str(tmp_path)))
    with caplog.at_level(logging.INFO, logger="nibrig"):
        nibrig.design.designer().predict("vero,tip=2mm", "office")
    assert any(r.name == "nibrig" and "default" in r.getMessage() for r in caplog.records), caplog.records
    out, err = capfd.readouterr()
    assert "[info]" not in out + err and "default" not in out + err


def test_the_models_auto_candidates_and_folds_and_its_table_as_data():
    assert len(nibrig.space.MODELS) == 12 and nibrig.space.MODELS[0] == "probit"
    X, y, _ = simulated_answers(400)
    judgments = nibrig.space.Judgments(X, answers=y)
    space = nibrig.space.fit(judgments, dims=2, model="auto", models=["probit", "logistic"], folds=3, starts=2)
    assert [s["family"] for s in space.model_scores] == ["probit", "logistic"]
    chosen = min(space.model_scores, key=lambda s: s["log_loss"])["family"]
    assert space.model == chosen
    assert "3-fold" in space.model_reason
    assert nibrig.space.fit(judgments, dims=2, starts=2).model_scores == []
    with pytest.raises(ValueError, match=r"^models: the candidates of a model chosen by cross-validation \(auto\)"):
        nibrig.space.fit(judgments, models=["probit"])
    with pytest.raises(ValueError, match="^model: "):
        nibrig.space.fit(judgments, model="wobbly")


def test_the_version_is_the_command_lines():
    printed = subprocess.run([nibrig_command(), "--version"], capture_output=True, text=True, check=True).stdout
    assert printed.strip() == "nibrig " + nibrig.__version__


def test_place_takes_the_error_as_any_array():
    space = nibrig.space.default(bootstrap=2)
    n = len(space.descriptor_names)
    x = [0.3] * n
    error = np.diag(np.linspace(1e-3, 2e-3, n))
    placements = [space.place(x, error=e) for e in (error, np.asfortranarray(error), error.tolist())]
    for p in placements[1:]:
        np.testing.assert_array_equal(p.covariance, placements[0].covariance)
    # The descriptors' own error widens the region: what it adds is a covariance (symmetric, >= 0).
    added = placements[0].covariance - space.place(x).covariance
    np.testing.assert_allclose(added, added.T, rtol=0, atol=1e-15)
    assert np.all(np.linalg.eigvalsh(added) > -1e-15)
    assert np.trace(added) > 0
    with pytest.raises(ValueError, match=f"error: expected a {n} x {n} matrix"):
        space.place(x, error=np.eye(n + 1))
    again = pickle.loads(pickle.dumps(placements[0]))
    np.testing.assert_array_equal(again.mean, placements[0].mean)
    np.testing.assert_array_equal(again.covariance, placements[0].covariance)


def test_lagunas_ids_are_named_only_as_asked():
    folder = shared_data() / "lagunas2019"
    plain = nibrig.space.read_judgments(folder / "answers_processed_train.json")
    # Nothing beside the file is read: the ids stay numbers, though a names file lies there.
    assert (folder / "material_names_sorted.txt").is_file()
    assert plain.stimuli == [str(k) for k in range(100)]
    names = (folder / "material_names_sorted.txt").read_text().split()
    named = nibrig.space.read_judgments(folder / "answers_processed_train.json", names=names)
    assert named.stimuli == names
    np.testing.assert_array_equal(named.triplets, plain.triplets)
    with pytest.raises(ValueError, match="2 names given"):
        nibrig.space.read_judgments(folder / "answers_processed_train.json", names=["a", "b"])
