"""Natural modes of the lumped system about its equilibrium (docs/frequency.md).

Undamped free motions ``u = phi cos(omega t)`` of the linearised system
(:mod:`kanat.frequency.linearize` eq. 1) solve the generalized eigenproblem::

    (1)  K phi = omega^2 M phi

with ``M`` symmetric positive definite. For a symmetric ``K`` (conservative loads) the lowest
modes come from :func:`scipy.linalg.eigh` (up to :data:`DENSE_LIMIT` degrees of freedom) or
from :func:`scipy.sparse.linalg.eigsh` in shift-invert mode about ``sigma = 0`` (ARPACK; Ericsson
& Ruhe 1980); a ``K`` whose asymmetry exceeds :data:`SYMMETRY_TOLERANCE` (drag in a current,
a towed line) is solved as the non-symmetric problem by :func:`scipy.linalg.eig`, the complex
eigenvalues' real parts kept. Mode shapes are scaled so that their largest displacement
component is +1.
"""
from __future__ import annotations

import warnings

import numpy as np
import scipy.linalg as la
import scipy.sparse.linalg as spla
import xarray as xr

from kanat.errors import CaseWarning
from kanat.frequency.linearize import Linearization, linearize

DENSE_LIMIT = 1500           # degrees of freedom solved densely (eigh of 1500 x 1500: ~1 s)
SYMMETRY_TOLERANCE = 1e-6    # ||K - K^T|| / ||K|| above which K is treated as non-symmetric
DIRECTIONS = ("x", "y", "z", "roll", "pitch", "yaw")    # a 6-DOF body's Euler angles last


def eigenmodes(lin: Linearization, n: int = 10) -> tuple[np.ndarray, np.ndarray]:
    """The ``n`` lowest modes of eq. (1): eigenvalues ``omega^2`` (n,) ascending [rad^2/s^2] and
    mode shapes (n_dof, n), each scaled to a largest component of +1."""
    K, M = lin.stiffness, lin.mass
    size = K.shape[0]
    n = min(int(n), size)
    if n < 1:
        raise ValueError(f"the number of modes must be at least 1 (got {n})")
    symmetric = lin.asymmetry <= SYMMETRY_TOLERANCE
    if symmetric:
        K = 0.5 * (K + K.T)
    if not symmetric:
        values, vectors = la.eig(K.toarray(), M.toarray())
        _warn_complex(values)
        values, vectors = values.real, vectors.real
    elif size <= DENSE_LIMIT or n >= size - 1:
        values, vectors = la.eigh(K.toarray(), M.toarray(), subset_by_index=[0, n - 1])
    else:
        values, vectors = spla.eigsh(K.tocsc(), k=n, M=M.tocsc(), sigma=0.0, which="LM")
    order = np.argsort(values)[:n]
    values, vectors = values[order], vectors[:, order]
    biggest = vectors[np.argmax(np.abs(vectors), axis=0), np.arange(n)]
    return values, vectors / biggest


def _warn_complex(values: np.ndarray) -> None:
    """Warn when a non-symmetric ``K`` gives eigenvalues with imaginary parts beyond round-off."""
    finite = values[np.isfinite(values)]
    worst = np.max(np.abs(finite.imag) / np.maximum(np.abs(finite), 1e-300), initial=0.0)
    if worst > SYMMETRY_TOLERANCE:
        warnings.warn("the stiffness is not symmetric (drag in a flow, a 6-DOF body's loads turning with it) "
                      f"and some eigenvalues are complex (imaginary part up to {worst:.2g} of the modulus): "
                      "their real parts are reported; the undamped modes are an approximation there",
                      CaseWarning, stacklevel=3)


def modes(case, n: int = 10) -> xr.Dataset:
    """Natural frequencies and mode shapes of a case's lumped system about its equilibrium.

    Parameters
    ----------
    case : kanat.model.Case
    n : int
        How many modes, lowest first.

    Returns
    -------
    xarray.Dataset
        ``natural_frequency(mode)`` [rad/s], ``period(mode)`` [s], ``eigenvalue(mode)``
        (``omega^2`` [rad^2/s^2]; negative: a statically unstable direction, whose frequency is
        NaN), ``direction(mode)`` (``x``, ``y``, ``z``, or a 6-DOF body's ``roll``, ``pitch``,
        ``yaw``: the direction holding most of the mode's kinetic energy ``phi^T M phi``),
        ``mode_shape(mode, node, xyz)`` (the cable nodes of the result files, with coordinates
        ``cable`` and ``s``; zero at prescribed nodes; largest component +1),
        ``body_mode_shape(mode, body, dof)`` (each body's translations, and a 6-DOF body's Euler
        angles [rad]) and ``position(node, xyz)``, the equilibrium [m].
    """
    if case.model != "lumped":
        warnings.warn(f"the modes are the lumped model's (the system discretized as in model: lumped), not "
                      f"those of model: {case.model}", CaseWarning, stacklevel=2)
    lin = linearize(case)
    values, vectors = eigenmodes(lin, n)
    if np.any(values < 0.0):
        warnings.warn(f"{int(np.sum(values < 0.0))} mode(s) with a negative stiffness (omega^2 down to "
                      f"{values.min():.3g} rad^2/s^2): the equilibrium is unstable in those directions",
                      CaseWarning, stacklevel=2)
    return _dataset(lin, values, vectors)


def _dataset(lin: Linearization, values: np.ndarray, vectors: np.ndarray) -> xr.Dataset:
    """The result of :func:`modes` (its docstring)."""
    net, count = lin.net, len(values)
    shapes = np.zeros((count, net.n_nodes, 3))
    shapes[:, lin.node, lin.xyz] = vectors.T
    omega = np.sqrt(np.where(values >= 0.0, values, np.nan))
    kind = lin.xyz + 3 * np.isin(lin.node, net.rigid.rot_node)
    inertia = lin.mass @ vectors
    energy = np.stack([np.einsum("ik,ik->k", vectors[kind == d], inertia[kind == d]) for d in range(6)])
    body = np.zeros((count, len(net.body_names), 6))
    body[:, :, :3] = shapes[:, net.body_node]
    for b, name in enumerate(net.rigid.names):
        body[:, net.body_names.index(name), 3:] = shapes[:, net.rigid.rot_node[b]]
    idx = net.node_index
    return xr.Dataset(
        {"natural_frequency": ("mode", omega, {"units": "rad/s"}),
         "period": ("mode", 2.0 * np.pi / omega, {"units": "s"}),
         "eigenvalue": ("mode", values, {"units": "rad^2/s^2"}),
         "direction": ("mode", np.array([DIRECTIONS[d] for d in np.argmax(energy, axis=0)])),
         "mode_shape": (("mode", "node", "xyz"), shapes[:, idx], {"units": "1"}),
         "body_mode_shape": (("mode", "body", "dof"), body, {"units": "1 (angles: rad per unit)"}),
         "position": (("node", "xyz"), lin.position[idx], {"units": "m"})},
        coords={"mode": np.arange(1, count + 1), "xyz": list(DIRECTIONS[:3]), "dof": list(DIRECTIONS),
                "body": list(net.body_names), "cable": ("node", net.node_cable.astype(str)),
                "s": ("node", net.node_s, {"units": "m"})},
        attrs={"model": "modes", "discretization": "lumped", "stiffness_asymmetry": lin.asymmetry})


def modes_table(ds: xr.Dataset) -> str:
    """The modes of :func:`modes` as a text table: mode, frequency, period and dominant direction."""
    lines = [f"{'mode':>4}  {'omega [rad/s]':>13}  {'period [s]':>10}  direction"]
    for k in range(ds.sizes["mode"]):
        lines.append(f"{int(ds.mode[k]):>4}  {float(ds.natural_frequency[k]):>13.5g}  "
                     f"{float(ds.period[k]):>10.5g}  {str(ds.direction.values[k])}")
    asymmetry = float(ds.attrs.get("stiffness_asymmetry", 0.0))
    if asymmetry > SYMMETRY_TOLERANCE:
        lines.append(f"(the stiffness is not symmetric: ||K - K^T|| / ||K|| = {asymmetry:.2g}; "
                     "drag in a flow, or a 6-DOF body's loads turning with it)")
    return "\n".join(lines)
