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

DNV-OS-E301 (*Position mooring*, Ch.2 Sec.2, the ULS for the intact system and the ALS for one
line failed) checks a design tension built from partial factors on the characteristic mean
and dynamic tensions against the characteristic capacity of the line's main body::

    T_d = gamma_mean T_C,mean + gamma_dyn T_C,dyn  <=  S_C = 0.95 S_mbs

with ``T_C,mean`` the mean tension, ``T_C,dyn = T_MPM - T_C,mean`` and ``S_mbs`` the minimum
breaking strength (the MBL). The factors, by consequence class (1: a failure is unlikely to
lead to unacceptable consequences; 2: it may), for a dynamic analysis:

=====  =====================  =====================
limit  class 1 (mean, dyn)    class 2 (mean, dyn)
=====  =====================  =====================
ULS    1.10, 1.50             1.40, 2.10
ALS    1.00, 1.10             1.00, 1.25
=====  =====================  =====================

The utilisation table keeps one format for both standards: ``safety_factor = MBL / T_MPM``
against a required factor; under DNV-OS-E301 that is ``T_d / (0.95 T_MPM)``, so that
``safety_factor >= required`` is exactly ``T_d <= 0.95 MBL``. DNV-OS-E301's factors for a
quasi-static analysis are not carried (kanat could not verify their published values):
``dnv-os-e301`` with ``analysis: quasi-static`` is refused.
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

DNV_OS_E301 = {
    ("intact", 1): (1.10, 1.50),
    ("intact", 2): (1.40, 2.10),
    ("damaged", 1): (1.00, 1.10),
    ("damaged", 2): (1.00, 1.25),
}
"""DNV-OS-E301 Ch.2 Sec.2, dynamic analysis: ``(gamma_mean, gamma_dyn)`` by (condition, consequence
class); intact is the ULS, damaged (one line failed) the ALS."""

DNV_CAPACITY_FACTOR = 0.95
"""DNV-OS-E301: the characteristic capacity of a line's main body, ``S_C = 0.95 S_mbs``."""

STANDARDS = ("api-rp-2sk", "dnv-os-e301")
"""The standards whose check kanat carries out."""

DNV_ANALYSES = ("dynamic", "frequency")
"""Analyses for which kanat carries DNV-OS-E301's partial factors (those of a dynamic analysis)."""


def _kind(condition: str) -> str:
    return condition.split(":", 1)[0]


def required_safety_factor(standard: str, analysis: str, condition: str, mean_tension: float | None = None,
                           mpm_tension: float | None = None, consequence_class: int | None = None) -> float:
    """The safety factor ``MBL / T_MPM`` a line must reach (module docstring).

    Parameters
    ----------
    standard : {"api-rp-2sk", "dnv-os-e301"}
    analysis : {"quasi-static", "dynamic", "frequency"}
        A frequency-domain analysis takes the factors of a dynamic one.
    condition : {"intact", "damaged"}
        The kind of condition (``damaged:<cable>`` counts as ``damaged``).
    mean_tension, mpm_tension : float, optional
        ``T_C,mean`` and ``T_MPM`` [N]; DNV-OS-E301 only.
    consequence_class : {1, 2}, optional
        DNV-OS-E301 only.

    Returns
    -------
    float
        MBL / most probable maximum tension required [-].
    """
    kind = _kind(condition)
    if standard == "api-rp-2sk":
        key = (kind, "dynamic" if analysis == "frequency" else analysis)
        if key not in API_RP_2SK:
            raise KanatError(f"no API RP 2SK safety factor for the {kind} condition in a {analysis} "
                             "analysis (conditions: intact, damaged; analyses: quasi-static, dynamic)")
        return API_RP_2SK[key]
    if standard == "dnv-os-e301":
        gamma_mean, gamma_dyn = dnv_partial_factors(analysis, kind, consequence_class)
        if mean_tension is None or mpm_tension is None:
            raise KanatError("DNV-OS-E301's required factor needs the line's mean and most probable "
                             "maximum tension")
        design_tension = gamma_mean * mean_tension + gamma_dyn * (mpm_tension - mean_tension)
        return design_tension / (DNV_CAPACITY_FACTOR * mpm_tension)
    raise KanatError(f"design.standard: unknown standard '{standard}'; known: {', '.join(STANDARDS)}")


def dnv_partial_factors(analysis: str, condition: str, consequence_class: int | None) -> tuple[float, float]:
    """``(gamma_mean, gamma_dyn)`` of DNV-OS-E301 for a condition kind and consequence class."""
    if analysis not in DNV_ANALYSES:
        raise KanatError(f"design.standard: dnv-os-e301 with analysis: {analysis}: kanat carries "
                         "DNV-OS-E301's partial factors of a dynamic analysis only (its quasi-static "
                         "factors are not verified here); use analysis: dynamic, or standard: api-rp-2sk")
    if consequence_class is None:
        raise KanatError("design.consequence_class: missing; DNV-OS-E301's partial factors depend on "
                         "it (1: a line failure is unlikely to lead to unacceptable consequences, 2: it may)")
    key = (_kind(condition), consequence_class)
    if key not in DNV_OS_E301:
        raise KanatError(f"no DNV-OS-E301 partial factors for the {key[0]} condition and consequence "
                         f"class {consequence_class} (conditions: intact, damaged; classes: 1, 2)")
    return DNV_OS_E301[key]


def check_standard(standard: str, analysis: str, consequence_class: int | None) -> None:
    """Refuse, before any run, a standard and analysis whose factors kanat does not carry."""
    if standard == "dnv-os-e301":
        dnv_partial_factors(analysis, "intact", consequence_class)
    else:
        required_safety_factor(standard, analysis, "intact")
