"""Design checks of a mooring (case section ``design``): sea states, conditions, standard.

The sea states are a CSV table next to the case file (``sea_states``), read when the case is
loaded (:mod:`kanat.io.sea_states`) into ``sea_state_rows``, so that the model holds numbers
and no check opens a file. What the checks compute is in :mod:`kanat.design_checks`.
"""
from __future__ import annotations

from typing import Any, Literal

from pydantic import Field, field_validator, model_validator

from ._base import KanatModel, fmt, quantity

SEA_STATE_COLUMNS = ("name", "hs", "tp", "gamma", "heading_deg", "probability", "duration")
"""Columns of a sea-state table: name, Hs [m], Tp [s], JONSWAP gamma [-], heading [deg],
probability of occurrence [-] and the simulated duration [s] of each run."""

STANDARDS = ("api-rp-2sk", "dnv-os-e301")
CONSEQUENCE_CLASSES = (1, 2)
CONDITION_KINDS = ("intact", "damaged")
ANALYSES = ("dynamic", "quasi-static", "frequency")
EXTREMES = ("rayleigh", "weibull", "gumbel")


class SeaState(KanatModel):
    """One row of the sea-state table.

    Attributes
    ----------
    name : str
    hs, tp, gamma, heading_deg : float
        The JONSWAP sea [m, s, -, deg] (``environment.waves`` of each run).
    probability : float
        Fraction of the year the sea state lasts [-] (fatigue weighting).
    duration : float
        Simulated duration of each of its runs [s].
    """

    name: str = Field(min_length=1, description="the sea state's name in the tables")
    hs: float = quantity(unit="m", gt=0, description="significant wave height of the JONSWAP sea")
    tp: float = quantity(unit="s", gt=0, description="peak period")
    gamma: float = quantity(3.3, unit="-", ge=1, description="peak enhancement factor")
    heading_deg: float = quantity(0.0, unit="deg", description="direction the waves travel to, as environment.waves")
    probability: float = quantity(unit="-", ge=0, le=1, description="fraction of the year the sea state lasts (fatigue)")
    duration: float = quantity(unit="s", gt=0, description="simulated duration of each of its runs")


class Fatigue(KanatModel):
    """Fatigue check: a T-N curve and the design life."""

    curve: str = Field("api-chain-studless",
                       description="a T-N curve of kanat.analysis.fatigue (api-chain-studless, "
                                   "api-chain-studlink, api-wire-six-strand, api-wire-spiral)")
    design_life: float = quantity(25.0, unit="years", gt=0,
                                  description="the life a line must reach (a line passes when its "
                                              "fatigue life is at least this)")


class Design(KanatModel):
    """The design checks of a mooring (``kanat design``; docs/design.md).

    Attributes
    ----------
    standard : {"api-rp-2sk", "dnv-os-e301"}
    consequence_class : {1, 2} or None
        DNV-OS-E301's consequence class.
    analysis : {"dynamic", "quasi-static", "frequency"}
    mean_offset : float, dict or None
        Quasi-static analysis: the vessel's mean offset along the waves' heading [m], for every
        condition or per condition kind (``intact``, ``damaged``).
    sea_states : str or None
        CSV file of the sea states (:data:`SEA_STATE_COLUMNS`), relative to the case file.
    sea_state_rows : tuple of SeaState or None
        The sea states, read from ``sea_states`` when the case is loaded.
    storm_duration : float
        Exposure the most probable maximum is for [s].
    seeds : int
        Random seeds (runs) per sea state and condition.
    conditions : tuple of str
        ``intact``, ``damaged`` (each cable removed in turn) and/or cable names (those removed).
    extremes : {"rayleigh", "weibull", "gumbel"}
    fatigue : Fatigue or None
    """

    standard: Literal[STANDARDS] = Field(  # type: ignore[valid-type]
        "api-rp-2sk", description="api-rp-2sk: safety factors on the most probable maximum tension; "
                                  "dnv-os-e301: partial factors on the mean and dynamic tension against "
                                  "0.95 MBL (needs consequence_class; dynamic analysis only)")
    consequence_class: Literal[CONSEQUENCE_CLASSES] | None = Field(  # type: ignore[valid-type]
        None, description="DNV-OS-E301 consequence class: 1 (a line failure is unlikely to lead to "
                          "unacceptable consequences) or 2 (it may); required by dnv-os-e301")
    analysis: Literal[ANALYSES] = Field(  # type: ignore[valid-type]
        "dynamic", description="dynamic: lumped-model runs in each sea state; quasi-static: the statics "
                               "at the vessel's mean offset plus its most probable maximum wave-frequency "
                               "motion from the RAOs (vessel.motion.rao); frequency: the lumped model linearised about its "
                               "equilibrium, tension spectra per sea state (simulation.method: frequency)")
    mean_offset: float | dict[str, float] | None = quantity(
        None, unit="m", description="quasi-static analysis: the vessel's mean offset along each sea state's "
                                    "heading (from the mean wind, current and wave-drift loads), to which the "
                                    "most probable maximum wave-frequency motion is added: one value for every "
                                    "condition, or {intact: S, damaged: S} (a broken line moves the vessel further)")
    sea_states: str | None = Field(
        None, description="CSV file with columns name, hs [m], tp [s], gamma, heading_deg, "
                          "probability, duration [s], relative to the case file; read when the "
                          "case is loaded")
    sea_state_rows: tuple[SeaState, ...] | None = Field(
        None, description="the sea states (read from 'sea_states', or written inline)")
    storm_duration: float = quantity(10800.0, unit="s", gt=0,
                                     description="exposure of the most probable maximum tension")
    seeds: int = Field(1, ge=1, description="runs (random wave phases) per sea state and condition")
    conditions: tuple[str, ...] = Field(
        ("intact", "damaged"), min_length=1,
        description="intact; damaged (each cable removed in turn); or names of the cables removed")
    extremes: Literal[EXTREMES] = Field(  # type: ignore[valid-type]
        "rayleigh", description="estimator of the most probable maximum (kanat.analysis.extremes.mpm)")
    fatigue: Fatigue | None = Field(
        None, description="{curve, design_life}: fatigue life of every line from the intact runs")

    @field_validator("mean_offset")
    @classmethod
    def _kinds(cls, value: Any) -> Any:
        if isinstance(value, dict):
            unknown = [k for k in value if k not in CONDITION_KINDS]
            if unknown:
                raise ValueError(f"'{unknown[0]}' is not a kind of condition; the keys are "
                                 f"{', '.join(CONDITION_KINDS)}")
        return value

    @field_validator("sea_state_rows")
    @classmethod
    def _distinct(cls, rows: tuple[SeaState, ...] | None) -> Any:
        if rows is None:
            return None
        if not rows:
            raise ValueError("the sea-state table has no rows")
        names = [r.name for r in rows]
        repeated = sorted({n for n in names if names.count(n) > 1})
        if repeated:
            raise ValueError(f"sea state '{repeated[0]}' appears twice; names must be unique")
        total = sum(r.probability for r in rows)
        if total > 1.0 + 1e-9:
            raise ValueError(f"the sea states' probabilities add up to {fmt(total)}, more than 1")
        return rows

    @model_validator(mode="after")
    def _read(self) -> Design:
        if self.sea_state_rows is None:
            if self.sea_states is None:
                raise ValueError("a design block needs 'sea_states': a CSV file with columns "
                                 + ", ".join(SEA_STATE_COLUMNS))
            raise ValueError(f"the sea-state table '{self.sea_states}' was not read; load the case "
                             "with kanat.io.load_case, which reads it next to the case file")
        return self
