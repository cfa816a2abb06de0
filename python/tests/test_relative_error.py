"""Relative errors and their statistics come from the C++ (corlab.relative_error_stats,
fit/relative_error.hpp): the same doubles as numpy's formulas that the dataset's scores were
computed with, what is left out, and bad input."""
# SPDX-License-Identifier: BSD-3-Clause
import math

import numpy as np
import pytest

import corlab


def numpy_stats(model, reference):
    """The formulas the Python used before (dataset.error_stats)."""
    r = (model - reference) / reference
    r = r[np.isfinite(r)]
    return {"n": int(r.size), "rms": float(np.sqrt(np.mean(r * r))),
            "worst": float(r[np.argmax(np.abs(r))]), "bias": float(np.mean(r))}


@pytest.mark.parametrize("n", [3, 8, 11, 127, 129, 2048, 20000])
def test_stats_are_numpys_to_the_last_bit(n):
    rng = np.random.default_rng(n)
    reference = rng.uniform(0.05, 1.0, n)
    model = reference * (1 + rng.normal(0.0, 0.05, n))
    model[::7] = math.nan  # models that cannot evaluate a case
    assert corlab.relative_error_stats(model, reference) == numpy_stats(model, reference)
    with np.errstate(invalid="ignore"):
        assert np.array_equal(corlab.relative_errors(model, reference),
                              (model - reference) / reference, equal_nan=True)


def test_left_out_and_empty():
    s = corlab.relative_error_stats([1.0, 2.0, math.nan, 0.9], [1.0, 0.0, 1.0, 1.0])
    assert s["n"] == 2 and s["worst"] == pytest.approx(-0.1) and s["rms"] == pytest.approx(
        math.sqrt(0.01 / 2))
    empty = corlab.relative_error_stats([], [])
    assert empty["n"] == 0 and all(math.isnan(empty[k]) for k in ("rms", "worst", "bias"))


def test_sizes_must_agree():
    with pytest.raises(ValueError) as err:
        corlab.relative_error_stats([1.0, 2.0], [1.0])
    assert err.value.field == "model values"
    with pytest.raises(ValueError):
        corlab.relative_errors([[1.0]], [[1.0]])
