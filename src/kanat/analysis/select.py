"""Choosing nodes and time windows of a result dataset.

Nodes are given by global index (``0`` .. ``n_node - 1``, negative from the end) or as
``CABLE@S``: the node of cable ``CABLE`` nearest to the unstretched arclength ``S`` [m]
(``S`` may be ``end``), e.g. ``tow@0`` for the tow point, ``tow@end`` for the body end.
"""
from __future__ import annotations

import numpy as np
import xarray as xr

from kanat.errors import KanatError


def cable_names(ds: xr.Dataset) -> list[str]:
    """Cable names in the order of their nodes."""
    return [str(c) for c in dict.fromkeys(ds["cable"].values.tolist())]


def _selector(ds: xr.Dataset, text: str) -> int:
    cable, _, where = text.partition("@")
    names = cable_names(ds)
    if cable not in names:
        raise KanatError(f"node '{text}': no cable '{cable}'; cables: {', '.join(names)}")
    index = np.flatnonzero(ds["cable"].values == cable)
    s = ds["s"].values[index]
    if where in ("", "end"):
        return int(index[0] if where == "" else index[-1])
    try:
        target = float(where)
    except ValueError:
        raise KanatError(f"node '{text}': write CABLE@S with S in metres or 'end'") from None
    return int(index[np.argmin(np.abs(s - target))])


def select_nodes(ds: xr.Dataset, nodes=None) -> np.ndarray:
    """Global node indices of a selection.

    Parameters
    ----------
    ds : xarray.Dataset
    nodes : sequence of int or str, or None
        Indices, ``CABLE@S`` selectors, or None for every node.

    Returns
    -------
    ndarray of int
    """
    n = ds.sizes.get("node", 0)
    if nodes is None:
        return np.arange(n)
    if isinstance(nodes, (int, np.integer, str)):
        nodes = [nodes]
    chosen = []
    for item in nodes:
        if isinstance(item, str) and not item.lstrip("-").isdigit():
            chosen.append(_selector(ds, item))
            continue
        i = int(item)
        if not -n <= i < n:
            raise KanatError(f"node {i} does not exist; this result has nodes 0 to {n - 1}")
        chosen.append(i % n)
    return np.array(chosen, dtype=int)


def first_nodes(ds: xr.Dataset) -> np.ndarray:
    """The first node (``s = 0``) of every cable: the tow point of a towed cable."""
    cables = ds["cable"].values
    return np.array([int(np.argmax(cables == name)) for name in cable_names(ds)], dtype=int)


def time_window(ds: xr.Dataset, window=None) -> xr.Dataset:
    """The part of a dynamic result with ``start <= time <= end``.

    Parameters
    ----------
    window : (float or None, float or None) or None
        Start and end [s]; None for either end means the end of the run.

    Raises
    ------
    KanatError
        When the window holds no output sample.
    """
    if window is None:
        return ds
    start, end = window
    time = ds["time"].values
    lo = time[0] if start is None else float(start)
    hi = time[-1] if end is None else float(end)
    keep = (time >= lo - 1e-9) & (time <= hi + 1e-9)
    if not keep.any():
        raise KanatError(f"the window {lo:g} to {hi:g} s holds no output; the run covers "
                         f"{time[0]:g} to {time[-1]:g} s")
    return ds.isel(time=np.flatnonzero(keep))
