"""Ensemble statistics shared by the collect modules of the examples.

  mean_sd   mean, standard deviation and count of the finite values
"""
import numpy as np


def mean_sd(values):
    """(mean, sample standard deviation, count) of the finite values: nan
    for the standard deviation of a single value, (nan, nan, 0) without
    any."""
    v = np.array([x for x in values if np.isfinite(x)])
    if len(v) == 0:
        return np.nan, np.nan, 0
    return float(v.mean()), float(v.std(ddof=1)) if len(v) > 1 else np.nan, len(v)
