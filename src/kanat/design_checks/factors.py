"""Required safety factors on line tension, by standard, analysis and condition.

API RP 2SK (3rd ed., 2005), its table of line tension limits and factors of safety: the
MBL over the most probable maximum tension must be at least

============  ============  =======
condition     quasi-static  dynamic
============  ============  =======
intact        2.00          1.67
damaged       1.43          1.25
============  ============  =======

(tension limits of 50 %, 60 %, 70 % and 80 % of the MBL). "Damaged" is the one-line-broken
condition after the system has settled (the transient condition, 1.05, is not checked).

DNV-OS-E301 does not check a safety factor on the MPM: it checks a design tension built from
partial factors on the mean and the dynamic tension against 0.95 MBL; kanat refuses it until
that check is built (:data:`REFUSED_STANDARDS`).
"""
from __future__ import annotations

from kanat.errors import KanatError

API_RP_2SK = {
    ("intact", "quasi-static"): 2.00,
    ("intact", "dynamic"): 1.67,
    ("damaged", "quasi-static"): 1.43,
    ("damaged", "dynamic"): 1.25,
}
"""API RP 2SK 3rd ed. (tension limits 50, 60, 70, 80 % of MBL): required MBL / T_max by (condition, analysis)."""

REFUSED_STANDARDS = {
    "dnv-os-e301": "DNV-OS-E301 checks a design tension gamma_mean T_mean + gamma_dyn T_dyn "
                   "against 0.95 MBL (partial factors per consequence class), not a safety "
                   "factor on the MPM; that check is not built yet: use standard: api-rp-2sk",
}
"""Standards a case may name whose check kanat does not carry out, with the reason."""


def required_safety_factor(standard: str, analysis: str, condition: str) -> float:
    """The safety factor a line must reach.

    Parameters
    ----------
    standard : {"api-rp-2sk"}
    analysis : {"quasi-static", "dynamic"}
    condition : {"intact", "damaged"}
        The kind of condition (``damaged:<cable>`` counts as ``damaged``).

    Returns
    -------
    float
        MBL / most probable maximum tension required [-].
    """
    if standard in REFUSED_STANDARDS:
        raise KanatError(f"design.standard: {standard}: {REFUSED_STANDARDS[standard]}")
    if standard != "api-rp-2sk":
        raise KanatError(f"design.standard: unknown standard '{standard}'; known: api-rp-2sk")
    kind = condition.split(":", 1)[0]
    key = (kind, analysis)
    if key not in API_RP_2SK:
        raise KanatError(f"no API RP 2SK safety factor for the {kind} condition in a {analysis} "
                         "analysis (conditions: intact, damaged; analyses: quasi-static, dynamic)")
    return API_RP_2SK[key]
