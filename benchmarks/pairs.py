"""Ratios of two configurations' times taken repeat by repeat (the benchmarks interleave their runs, so
each pair was timed at one machine speed): steadier than the ratio of medians on a machine whose
speed drifts."""
from __future__ import annotations

import numpy as np


def paired(peer, ours) -> str:
    """``peer[i] / ours[i]`` over the repeats as ``median (min-max)``, e.g. ``1.35x (1.04-1.49)``."""
    ratios = np.asarray(peer, float) / np.asarray(ours, float)
    return f"{np.median(ratios):.2f}x ({ratios.min():.2f}-{ratios.max():.2f})"
