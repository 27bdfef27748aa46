"""One mooring line in its vertical plane: a piecewise elastic catenary with point loads,
resting on a (sloped) seabed with Coulomb friction.

A line runs from end A (``s = 0``) to end B (``s = L``) through pieces ``k`` of unstretched
length ``l_k``, weight in water ``w_k`` per unstretched length (negative: buoyant) and axial
stiffness ``EA_k``; at the joints between pieces act vertical point loads ``P_j`` (clump
weights positive, floats negative; 0 at a plain section joint). In the plane of the line
(horizontal ``x`` from A towards B, ``z`` up) the horizontal tension ``H`` is constant off
the seabed and the vertical tension ``V(s)`` (the vertical part of ``T t``, ``t`` pointing
towards B) grows by ``w_k`` per metre and jumps by ``P_j`` at a joint. With ``V_B = V(L)``
and the end conditions written from B downwards, a suspended piece starting at ``V_0``
(its lower end) and of length ``l`` adds (the elastic catenary; Irvine 1981; Jonkman 2007,
NREL/TP-500-41958, eqs. 2-1, 2-2)::

    (1)  dx = H/w [asinh(V_1/H) - asinh(V_0/H)] + H l/EA,        V_1 = V_0 + w l
    (2)  dz = (T_1 - T_0)/w + (V_0 l + w l^2/2)/EA,               T = sqrt(H^2 + V^2)

evaluated in the cancellation-free forms of :mod:`kanat.statics.catenary` (eqs. 6-7 there).

**Seabed contact at A.** When end A rests on the seabed, whose slope along the line is
``alpha`` (rising towards B; ``tan alpha = 0`` on a flat seabed), the line leaves it
tangentially at the touchdown point ``s_TD`` where ``V(s_TD) = H tan alpha``. The grounded
part ``0 <= s <= s_TD`` lies straight along the seabed; its tension is ``T_TD = H/cos alpha``
at touchdown and falls towards A by the along-slope weight and the Coulomb friction of
MoorPy's ``CB`` convention (the friction acts towards A, the line being pulled towards B;
Jonkman 2007 eqs. 2-5 to 2-7; MoorPy ``catenary()``)::

    (3)  T(s) = max(T_TD - c sum_{s < s' < s_TD} (w ds' + P_j), 0),   c = sin alpha + mu cos alpha

so that the grounded part stretches by ``int T/EA ds`` and the line reaches
``(x, z) = cos alpha, sin alpha times (s_TD + int_0^s_TD T/EA ds)`` at touchdown. A clump
weight at the touchdown point is carried partly by the seabed (``S = H tan alpha - V(s_TD-)``)
and adds ``c S`` of friction. A buoyant stretch below the touchdown point (a lifted loop)
is not modelled: :func:`end_position` raises :class:`LiftedLoop`.

Every quantity comes with its derivatives with respect to ``(H, V_B)`` (forward-mode,
by the chain rule through the pieces), so the end conditions are solved by Newton's
method with the exact Jacobian and the line's stiffness is its inverse.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from kanat.errors import SolverError

__all__ = ["Ground", "LiftedLoop", "LineEvaluation", "Pieces", "end_position", "sample"]

SERIES_LIMIT = 1e-4       # |y| below which asinh(y)/y is evaluated by its series (error < 1e-17)


class LiftedLoop(SolverError):
    """A buoyant stretch below the touchdown point would lift off the seabed again."""


@dataclass(frozen=True, eq=False)
class Pieces:
    """A line made of uniform pieces joined at point loads, from end A to end B.

    Attributes
    ----------
    length, weight, stiffness : ndarray, shape (n,)
        Unstretched length ``l_k`` [m], weight in water ``w_k`` [N/m] (negative: buoyant)
        and axial stiffness ``EA_k`` [N] of each piece, from A.
    load : ndarray, shape (n - 1,)
        Downward point load ``P_j`` [N] at the joint between pieces ``j`` and ``j + 1``
        (negative: a float).
    """

    length: np.ndarray
    weight: np.ndarray
    stiffness: np.ndarray
    load: np.ndarray = field(default_factory=lambda: np.zeros(0))

    starts: np.ndarray = field(init=False, repr=False)
    total_weight: float = field(init=False, repr=False)
    total_length: float = field(init=False, repr=False)
    l: tuple = field(init=False, repr=False)       # the same as tuples of floats, for the scalar hot loops
    w: tuple = field(init=False, repr=False)
    ea: tuple = field(init=False, repr=False)
    p: tuple = field(init=False, repr=False)
    s0: tuple = field(init=False, repr=False)

    def __post_init__(self):
        for name in ("length", "weight", "stiffness", "load"):
            object.__setattr__(self, name, np.asarray(getattr(self, name), dtype=float))
        if len(self.load) != len(self.length) - 1:
            raise ValueError(f"{len(self.length)} pieces need {len(self.length) - 1} joint loads "
                             f"(got {len(self.load)})")
        # A-side end of each piece [m]; weight in water with the point loads [N] (negative: floats)
        object.__setattr__(self, "starts", np.concatenate([[0.0], np.cumsum(self.length)[:-1]]))
        object.__setattr__(self, "total_weight", float(np.dot(self.weight, self.length) + np.sum(self.load)))
        object.__setattr__(self, "total_length", float(np.sum(self.length)))
        for name, values in (("l", self.length), ("w", self.weight), ("ea", self.stiffness), ("p", self.load),
                             ("s0", self.starts)):
            object.__setattr__(self, name, tuple(float(v) for v in values))

    @classmethod
    def uniform(cls, length: float, weight: float, stiffness: float) -> Pieces:
        return cls(np.array([length]), np.array([weight]), np.array([stiffness]))

    def reversed(self) -> Pieces:
        """The same line seen from B (``s -> L - s``)."""
        return Pieces(self.length[::-1], self.weight[::-1], self.stiffness[::-1], self.load[::-1])

    def can_lie_slack(self) -> bool:
        """True when no piece and no point load is buoyant (the line may lie slack on a seabed)."""
        return bool(np.all(self.weight >= 0.0) and np.all(self.load >= 0.0))


@dataclass(frozen=True)
class Ground:
    """End A resting on the seabed: slope along the line and Coulomb friction.

    Attributes
    ----------
    slope : float
        ``tan alpha``, the seabed's rise per horizontal metre towards B [-].
    friction : float
        Coulomb coefficient ``mu`` along the line (MoorPy's ``CB``) [-].
    """

    slope: float = 0.0
    friction: float = 0.0
    cos: float = field(init=False, repr=False)
    sin: float = field(init=False, repr=False)
    resistance: float = field(init=False, repr=False)

    def __post_init__(self):
        cos = 1.0 / math.sqrt(1.0 + self.slope * self.slope)
        object.__setattr__(self, "cos", cos)
        object.__setattr__(self, "sin", self.slope * cos)
        # c = sin alpha + mu cos alpha: tension lost per newton of weight on the seabed, eq. (3)
        object.__setattr__(self, "resistance", self.slope * cos + self.friction * cos)


@dataclass(frozen=True)
class LineEvaluation:
    """End B's position from the end tensions, with derivatives.

    Attributes
    ----------
    x, z : float
        Position of B relative to A in the line's plane [m].
    jacobian : ndarray, shape (2, 2)
        ``d(x, z)/d(H, V_B)`` [m/N].
    anchor : ndarray, shape (2,)
        ``(H_A, V_A)``: the in-plane force of the line on end A [N] (towards B, up).
    anchor_jacobian : ndarray, shape (2, 2)
        ``d(H_A, V_A)/d(H, V_B)``.
    touchdown : float
        ``s_TD`` [m]: unstretched length on the seabed (0 when the line is suspended).
    """

    x: float
    z: float
    jacobian: np.ndarray
    anchor: np.ndarray
    anchor_jacobian: np.ndarray
    touchdown: float


# --------------------------------------------------------------------------- one suspended piece

def _asinhc(y: float) -> float:
    """``asinh(y)/y`` (1 at y = 0)."""
    return 1.0 - y * y / 6.0 if abs(y) < SERIES_LIMIT else math.asinh(y) / y


def _log1pc(r: float) -> float:
    """``log(1 + r)/r`` for ``r >= 0`` (1 at r = 0: a weightless piece, whose tension does not change
    along it; ``log1p`` is accurate down to the smallest ``r``)."""
    return math.log1p(r) / r if r > 0.0 else 1.0


def suspended_piece(H, V0, l, w, EA):
    """Eqs. (1)-(2) for one piece and their partial derivatives.

    Parameters
    ----------
    H, V0, l, w, EA : float
        Horizontal tension ``>= 0``, vertical tension at the piece's A-side end, length,
        weight per length and axial stiffness.

    Returns
    -------
    dx, dz : float
    partials : tuple of 6 floats
        ``(dx/dH, dx/dV0, dx/dl, dz/dH, dz/dV0, dz/dl)``; ``dx/dH`` is ``inf`` where the
        line hangs vertically through a zero of its tension.
    """
    V1 = V0 + w * l
    if H == 0.0:
        return _vertical_piece(V0, V1, l, w, EA)
    T0, T1 = math.hypot(H, V0), math.hypot(H, V1)
    Tsum = T0 + T1
    dz = l * (V0 + V1) / Tsum + l * (V0 + V1) / (2.0 * EA)
    cross = -l * (V0 + V1) / (Tsum * T0 * T1)                   # (1/T1 - 1/T0)/w, cancellation-free
    if (V0 >= 0.0 and V1 >= 0.0) or (V0 <= 0.0 and V1 <= 0.0):
        D = V1 * T0 + V0 * T1
        ratio = (V0 + V1) / D if D != 0.0 else 1.0 / H
        per_h = l * ratio * _asinhc(w * l * ratio)               # [asinh(V1/H) - asinh(V0/H)]/w, eq. (7)
    else:                                                        # the piece holds its lowest point
        per_h = (math.asinh(V1 / H) - math.asinh(V0 / H)) / w
    dx = H * per_h + H * l / EA
    slope_change = l / T1 + V0 * cross                           # (V1/T1 - V0/T0)/w
    return dx, dz, (per_h - slope_change + l / EA, H * cross, H / T1 + H / EA,
                    H * cross, slope_change + l / EA, V1 / T1 + V1 / EA)


def _vertical_piece(V0, V1, l, w, EA):
    """:func:`suspended_piece` at ``H = 0``: a vertical piece, straight or folded."""
    stretch = l * (V0 + V1) / (2.0 * EA)
    if (V0 >= 0.0 and V1 >= 0.0) or (V0 <= 0.0 and V1 <= 0.0):
        sign = 1.0 if V0 + V1 > 0.0 else (-1.0 if V0 + V1 < 0.0 else 0.0)
        low, high = sorted((abs(V0), abs(V1)))
        per_h = l * _log1pc((high - low) / low) / low if low > 0.0 else math.inf   # log(high/low)/|w|
        return 0.0, sign * l + stretch, (per_h + l / EA, 0.0, 0.0, 0.0, l / EA,
                                         (1.0 if V1 > 0.0 else -1.0 if V1 < 0.0 else 0.0) + V1 / EA)
    T0, T1 = abs(V0), abs(V1)
    slope_change = (V1 / T1 - V0 / T0) / w
    return 0.0, l * (V0 + V1) / (T0 + T1) + stretch, (math.inf, 0.0, 0.0, 0.0, slope_change + l / EA,
                                                       V1 / T1 + V1 / EA)


def grounded_piece(T_top, l, g, EA):
    """Stretch of a grounded piece whose tension falls by ``g`` per metre towards A, eq. (3).

    Returns
    -------
    stretch, T_bottom : float
        ``int T/EA ds`` over the piece [m] and the tension at its A-side end [N].
    partials : tuple of 4 floats
        ``(d stretch/d T_top, d stretch/d l, d T_bottom/d T_top, d T_bottom/d l)``.
    """
    if g > 0.0 and T_top < g * l:                                # slack below T = 0
        return T_top * T_top / (2.0 * g * EA), 0.0, (T_top / (g * EA), 0.0, 0.0, 0.0)
    T_bottom = T_top - g * l
    return (T_top * l - 0.5 * g * l * l) / EA, T_bottom, (l / EA, T_bottom / EA, 1.0, -g)


# --------------------------------------------------------------------------- the whole line

def _vertical_walk(VB, pieces: Pieces):
    """Vertical tension at the A-side end of every piece, walking down from B.

    Returns ``bottom`` and ``below`` (lists of n floats): ``V`` at each piece's A-side end,
    and just below the joint under it (after its point load; ``below[0] = bottom[0]``).
    """
    n = len(pieces.length)
    bottom, below = [0.0] * n, [0.0] * n
    V = VB
    for k in range(n - 1, -1, -1):
        bottom[k] = V - pieces.w[k] * pieces.l[k]
        V = bottom[k] - (pieces.p[k - 1] if k > 0 else 0.0)
        below[k] = V
    return bottom, below


def _touchdown(bottom, below, threshold, pieces: Pieces):
    """Where the line, walked down from B, first reaches ``V = threshold``.

    Returns ``(k, s_TD, at_joint)``: inside piece ``k`` (``at_joint`` False), or at the
    joint under piece ``k`` (``s_TD`` its A-side end; the seabed carries part of the joint's
    load and piece ``k`` is wholly suspended).
    """
    for k in range(len(pieces.length) - 1, -1, -1):
        top = bottom[k] + pieces.w[k] * pieces.l[k]
        if bottom[k] < threshold <= top:
            return k, pieces.s0[k] + (threshold - bottom[k]) / pieces.w[k], False
        if below[k] < threshold <= bottom[k]:
            return k, pieces.s0[k], True
    raise SolverError("no touchdown point found although end A is grounded")  # unreachable: below[0] < threshold


def _check_no_loop(bottom, k, s_td, threshold, pieces: Pieces) -> None:
    """Raise :class:`LiftedLoop` when the weight on the seabed between some point and the
    touchdown point is negative: the would-be vertical tension below touchdown rises above
    its touchdown value."""
    highest = max((max(bottom[j], bottom[j] + pieces.w[j] * pieces.l[j]) for j in range(k)),
                  default=-math.inf)
    if highest > threshold + 1e-12 * max(abs(pieces.total_weight), abs(threshold), 1.0):
        raise LiftedLoop(f"a buoyant stretch below the touchdown point (s = {s_td:.6g} m) would lift "
                         "off the seabed again (a lifted loop); the catenary statics does not model it")


def end_position(H: float, VB: float, pieces: Pieces, ground: Ground | None = None) -> LineEvaluation:
    """Position of end B relative to A, eqs. (1)-(3), with its Jacobian.

    Parameters
    ----------
    H : float
        Horizontal tension ``>= 0`` [N] of the suspended part.
    VB : float
        Vertical tension at B [N] (the line pulls B down by ``V_B``).
    pieces : Pieces
    ground : Ground or None
        End A resting on the seabed, or None (no seabed contact at A).

    Returns
    -------
    LineEvaluation
    """
    bottom, below = _vertical_walk(VB, pieces)
    threshold = H * ground.slope if ground is not None else -math.inf
    if ground is None or below[0] >= threshold:
        return _suspended(H, VB, pieces, bottom, below)
    if VB <= threshold:
        raise SolverError(f"V_B = {VB:.6g} N does not lift end B off the seabed (touchdown at B)")
    k, s_td, at_joint = _touchdown(bottom, below, threshold, pieces)
    _check_no_loop(bottom, k, s_td, threshold, pieces)
    return _grounded(H, pieces, ground, bottom, below, k, s_td, at_joint)


def _suspended(H, VB, pieces: Pieces, bottom, below) -> LineEvaluation:
    x = z = a = b = c = d = 0.0
    for k in range(len(pieces.length)):
        dx, dz, p = suspended_piece(H, bottom[k], pieces.l[k], pieces.w[k], pieces.ea[k])
        x, z = x + dx, z + dz
        a, b, c, d = a + p[0], b + p[1], c + p[3], d + p[4]     # dV0/dV_B = 1, dV0/dH = 0
    return LineEvaluation(x, z, np.array([[a, b], [c, d]]), np.array([H, below[0]]), np.eye(2), 0.0)


def _grounded(H, pieces: Pieces, ground: Ground, bottom, below, k, s_td, at_joint) -> LineEvaluation:
    tan, cos, c = ground.slope, ground.cos, ground.resistance
    n = len(pieces.length)
    x = z = j00 = j01 = j10 = j11 = 0.0
    for j in range(k + 1 if not at_joint else k, n):             # wholly suspended pieces
        dx, dz, p = suspended_piece(H, bottom[j], pieces.l[j], pieces.w[j], pieces.ea[j])
        x, z = x + dx, z + dz
        j00, j01, j10, j11 = j00 + p[0], j01 + p[1], j10 + p[3], j11 + p[4]
    T, dT_h, dT_v = H / cos, 1.0 / cos, 0.0                      # grounded tension at touchdown
    if at_joint:                                                 # joint k-1 on the seabed
        ds_h = ds_v = 0.0
        support = H * tan - below[k]                             # part of the clump the seabed carries
        if T > c * support:
            T, dT_h, dT_v = T - c * support, dT_h - c * tan, c
        else:
            T, dT_h, dT_v = 0.0, 0.0, 0.0
        first, top_length = k - 1, None
    else:                                                        # touchdown inside piece k
        w = pieces.w[k]
        ds_h, ds_v = tan / w, -1.0 / w
        dx, dz, p = suspended_piece(H, H * tan, pieces.s0[k] + pieces.l[k] - s_td, w,
                                    pieces.ea[k])
        x, z = x + dx, z + dz
        j00 += p[0] + p[1] * tan - p[2] * ds_h
        j01 -= p[2] * ds_v
        j10 += p[3] + p[4] * tan - p[5] * ds_h
        j11 -= p[5] * ds_v
        first, top_length = k, s_td - pieces.s0[k]
    stretch, dst_h, dst_v = 0.0, 0.0, 0.0
    for j in range(first, -1, -1):
        partial = j == k and top_length is not None
        l = top_length if partial else pieces.l[j]
        dl_h, dl_v = (ds_h, ds_v) if partial else (0.0, 0.0)
        I, T_next, q = grounded_piece(T, l, c * pieces.w[j], pieces.ea[j])
        stretch += I
        dst_h += q[0] * dT_h + q[1] * dl_h
        dst_v += q[0] * dT_v + q[1] * dl_v
        T, dT_h, dT_v = T_next, q[2] * dT_h + q[3] * dl_h, q[2] * dT_v + q[3] * dl_v
        if j > 0:                                                # the joint below, on the seabed
            drop = c * pieces.p[j - 1]
            T, dT_h, dT_v = (T - drop, dT_h, dT_v) if T > drop else (0.0, 0.0, 0.0)
    extent, dex_h, dex_v = s_td + stretch, ds_h + dst_h, ds_v + dst_v
    sin = ground.sin
    jacobian = np.array([[j00 + cos * dex_h, j01 + cos * dex_v], [j10 + sin * dex_h, j11 + sin * dex_v]])
    anchor_jacobian = np.array([[cos * dT_h, cos * dT_v], [sin * dT_h, sin * dT_v]])
    return LineEvaluation(x + cos * extent, z + sin * extent, jacobian, np.array([T * cos, T * sin]),
                          anchor_jacobian, s_td)


# --------------------------------------------------------------------------- the profile

def _floored_integral(T_top, g, s_top, a, b):
    """``int_a^b max(T_top - g (s_top - s), 0) ds`` for ``a <= b <= s_top``."""
    if g > 0.0:
        a = max(a, s_top - T_top / g)
        if b <= a:
            return 0.0
    F = lambda s: T_top * s - g * (s_top * s - 0.5 * s * s)      # noqa: E731
    return F(b) - F(a)


def sample(s, H, VB, pieces: Pieces, ground: Ground | None = None):
    """Shape and tension of the line at unstretched arclengths ``s`` from A.

    Parameters
    ----------
    s : array_like, shape (m,)
        Stations in ``[0, L]`` [m].
    H, VB : float
        The solved end tensions (:func:`end_position`; ``H > 0`` when A is grounded).
    pieces : Pieces
    ground : Ground or None

    Returns
    -------
    x, z, tension, vertical : ndarray, shape (m,)
        In-plane position relative to A [m], tension [N] and the vertical part of the
        tension vector [N] (on the seabed: ``T sin alpha``).
    """
    s = np.asarray(s, dtype=float)
    out = [np.zeros_like(s) for _ in range(4)]
    bottom, below = _vertical_walk(VB, pieces)
    touchdown, base = 0.0, (0.0, 0.0)
    if ground is not None and below[0] < H * ground.slope:
        k, touchdown, at_joint = _touchdown(bottom, below, H * ground.slope, pieces)
        base = _sample_ground(s, H, pieces, ground, k, touchdown, at_joint, below, out)
    starts, ends = pieces.starts, pieces.starts + pieces.length
    for k in range(len(pieces.length)):
        lo = max(starts[k], touchdown)
        if ends[k] < lo:
            continue
        V0 = bottom[k] + pieces.weight[k] * (lo - starts[k])
        w, EA = pieces.weight[k], pieces.stiffness[k]
        here = np.flatnonzero((s >= lo) & (s <= ends[k]) & ((s > touchdown) | (touchdown == 0.0)))
        if len(here):
            dx, dz, V = _offsets(s[here] - lo, H, V0, w, EA)
            out[0][here], out[1][here], out[2][here], out[3][here] = base[0] + dx, base[1] + dz, np.hypot(H, V), V
        dx, dz, _ = suspended_piece(H, V0, ends[k] - lo, w, EA)
        base = (base[0] + dx, base[1] + dz)
    return tuple(out)


def _offsets(l, H, V0, w, EA):
    """Eqs. (1)-(2) at many lengths ``l`` of one piece (vectorized :func:`suspended_piece`)."""
    V1 = V0 + w * l
    if H == 0.0:
        return (np.zeros_like(l), np.array([suspended_piece(0.0, V0, x, w, EA)[1] for x in l]), V1)
    T0, T1 = math.hypot(H, V0), np.hypot(H, V1)
    dz = l * (V0 + V1) / (T0 + T1) + l * (V0 + V1) / (2.0 * EA)
    one_sign = (V0 >= 0.0) & (V1 >= 0.0) | (V0 <= 0.0) & (V1 <= 0.0)
    D = V1 * T0 + V0 * T1
    safe = one_sign & (D != 0.0)
    ratio = np.where(safe, (V0 + V1) / np.where(safe, D, 1.0), 1.0 / H)
    y = w * l * ratio
    small = np.abs(y) < SERIES_LIMIT
    asinhc = np.where(small, 1.0 - y * y / 6.0, np.arcsinh(y) / np.where(small, 1.0, y))
    folded = (np.arcsinh(V1 / H) - math.asinh(V0 / H)) / (w if w != 0.0 else 1.0)
    per_h = np.where(one_sign, l * ratio * asinhc, folded)
    return H * per_h + H * l / EA, dz, V1


def _sample_ground(s, H, pieces, ground, k, touchdown, at_joint, below, out):
    """Fill the grounded stations, eq. (3); return the touchdown point's position."""
    c, starts = ground.resistance, pieces.starts
    T = H / ground.cos
    if at_joint:
        T = max(T - c * (H * ground.slope - below[k]), 0.0)
        k -= 1
    stretches, top = [], touchdown                            # (s_lo, s_hi, T(s_hi), g, EA), from A
    for j in range(k, -1, -1):
        g = c * pieces.weight[j]
        stretches.append((starts[j], top, T, g, pieces.stiffness[j]))
        T = max(T - g * (top - starts[j]), 0.0)
        if j > 0:
            T = max(T - c * pieces.load[j - 1], 0.0)
        top = starts[j]
    stretched = 0.0                                           # [m], of the stretches below
    for lo, hi, T_hi, g, EA in reversed(stretches):
        for i in np.flatnonzero((s >= lo) & (s <= hi)):
            extent = s[i] + stretched + _floored_integral(T_hi, g, hi, lo, s[i]) / EA
            tension = max(T_hi - g * (hi - s[i]), 0.0)
            out[0][i], out[1][i] = ground.cos * extent, ground.sin * extent
            out[2][i], out[3][i] = tension, tension * ground.sin
        stretched += _floored_integral(T_hi, g, hi, lo, hi) / EA
    return ground.cos * (touchdown + stretched), ground.sin * (touchdown + stretched)
