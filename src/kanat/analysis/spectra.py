"""Spectra of tension (Welch's method, :func:`scipy.signal.welch`).

One-sided power spectral density of the tension at chosen nodes, after removing the mean,
with Hann windows of ``segment_s`` seconds overlapping by half. The output times must be
evenly spaced (they are for every kanat run). The PSD integrates to the variance:
``sum(psd) * df == std**2`` up to the window's leakage.
"""
from __future__ import annotations

import numpy as np
import xarray as xr
from scipy.signal import welch

from kanat.analysis.select import first_nodes, select_nodes, time_window
from kanat.errors import KanatError

EVEN_RTOL = 1e-6
"""Relative spread of the output interval accepted as evenly sampled."""


def sample_interval(time: np.ndarray) -> float:
    """The output interval [s]; raises if the samples are not evenly spaced."""
    if time.size < 2:
        raise KanatError("a spectrum needs at least two output samples")
    steps = np.diff(time)
    dt = float(np.median(steps))
    if np.max(np.abs(steps - dt)) > EVEN_RTOL * max(dt, 1e-300):
        raise KanatError(f"the output times are not evenly spaced (intervals {steps.min():g} to "
                         f"{steps.max():g} s); a spectrum needs a constant output_dt")
    return dt


def tension_spectrum(ds: xr.Dataset, nodes=None, window=None, segment_s: float | None = None,
                     variable: str = "tension") -> xr.Dataset:
    """Power spectral density of the tension at chosen nodes.

    Parameters
    ----------
    ds : xarray.Dataset
        A dynamic result.
    nodes : sequence of int or str, optional
        Node indices or ``CABLE@S`` selectors; default the first node of each cable.
    window : (float or None, float or None), optional
        Time window [s].
    segment_s : float, optional
        Length of Welch's segments [s]; default a quarter of the window (at least 8
        samples), which trades resolution ``1/segment_s`` for a steadier estimate.
    variable : str
        A ``(time, node)`` variable.

    Returns
    -------
    xarray.Dataset
        ``psd(frequency, node)`` [N^2/Hz] with coordinates ``frequency`` [Hz], ``s`` and
        ``cable``; attributes ``segment_s`` and ``sample_interval_s``.
    """
    if "time" not in ds.dims:
        raise KanatError("a tension spectrum needs a dynamic result (a 'time' dimension)")
    part = time_window(ds, window)
    dt = sample_interval(part["time"].values)
    index = first_nodes(ds) if nodes is None else select_nodes(ds, nodes)
    values = part[variable].values[:, index]
    n = values.shape[0]
    per = n // 4 if segment_s is None else int(round(segment_s / dt))
    per = min(max(per, 8), n)
    frequency, psd = welch(values, fs=1.0 / dt, window="hann", nperseg=per, noverlap=per // 2,
                           detrend="constant", scaling="density", axis=0)
    units = ds[variable].attrs.get("units", "N")
    return xr.Dataset({"psd": (("frequency", "node"), psd, {"units": f"{units}^2/Hz",
                                                             "long_name": f"power spectral density of {variable}"})},
                      coords={"frequency": ("frequency", frequency, {"units": "Hz"}), "node": index,
                              "s": ("node", ds["s"].values[index]), "cable": ("node", ds["cable"].values[index])},
                      attrs={"segment_s": per * dt, "sample_interval_s": dt})


def spectral_peak(spectrum: xr.Dataset) -> xr.DataArray:
    """Frequency of the largest PSD value at each node [Hz] (the zero frequency excluded)."""
    psd = spectrum["psd"].isel(frequency=slice(1, None))
    return psd["frequency"][psd.argmax("frequency")].drop_vars("frequency", errors="ignore")
